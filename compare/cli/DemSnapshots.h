#pragma once
// DEM particle snapshots along the main path: taken during the run (SnapshotRecorder,
// into <dir>/dem-fields.h5 with an XDMF sidecar for ParaView), read back by the report
// for the DEM's localization onset and band (S0 Fig. 3, 5).
#include "common/ProgramRunner.h"
#include "compare/LocalizationOnsets.h"
#include "compare/Metrics.h"
#include "compare/Report.h"
#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"

#include <filesystem>
#include <vector>

namespace geocomp::cli {

/// DEM particle snapshots along the main path of the last stage, for the localization
/// analysis and the mid-section maps: at its first sample and each time its progress
/// passes k/n (n = dem/snapshots), appended to <dir>/dem-fields.h5 (XDMF sidecar beside).
class SnapshotRecorder {
public:
  SnapshotRecorder(dem::DemEngine &engine, const CaseDescription &c, const std::filesystem::path &dir);
  /// A run from the start: no snapshots yet.
  void start();
  /// Going on from a program checkpoint at program time `time`, where `next` snapshots
  /// had been counted: the file keeps the snapshots taken up to then (a killed run may
  /// have written later ones).
  void resume(double time, unsigned int next);
  unsigned int next() const { return next_; }
  /// Called at every sample: a snapshot when the main path of the last stage passes k/n.
  void operator()(const RunProgress &p);

private:
  dem::DemEngine &engine_;
  std::filesystem::path file_;
  unsigned int n_, next_ = 0;
  compare::CurveKind kind_;
  compare::AxialAxis axial_;
  double sample_interval_;
};

/// The DEM side of the report from <dir>/dem-fields.h5: the localization onset and band
/// (compare::detect_localization, local-strain radius 3 mean radii, docs/metrics.md) as
/// the DEM entry of `onsets`; a note when there are no snapshots. (The DEM's maps come from
/// its mid-section at every sample, DemSection.h.)
void add_dem_fields(compare::ReportInput &in, const std::filesystem::path &dir,
                    std::vector<compare::OnsetEstimate> &onsets);

} // namespace geocomp::cli
