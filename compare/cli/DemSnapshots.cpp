#include "DemSnapshots.h"

#include "dem/program/Fields.h"

#include <algorithm>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
const char *const dem_fields_file = "dem-fields.h5";

/// The strain measure onsets are reported in (compare::onset_strain): the log strain from
/// the program start, on the program's axial axis or gamma_max on isochoric programs.
double onset_label(const ResponseSample &s, compare::CurveKind kind, const compare::AxialAxis &axial)
{
  return compare::onset_strain(s.strain, Tensor3::Zero(), kind, axial);
}
} // namespace

SnapshotRecorder::SnapshotRecorder(dem::DemEngine &engine, const CaseDescription &c, const fs::path &dir)
  : engine_(engine), file_(dir / dem_fields_file), n_(std::max(1u, c.dem.snapshots)),
    kind_(compare::curve_kind_for(c.program)),
    axial_(compare::axial_axis_for(c.program).value_or(compare::AxialAxis{})),
    sample_interval_(c.program.sample_interval)
{
  fs::create_directories(dir);
}

void SnapshotRecorder::start()
{
  fs::remove(file_);
  fs::remove(dem::xdmf_path(file_));
}

void SnapshotRecorder::resume(double time, unsigned int next)
{
  next_ = next;
  if (!fs::exists(file_))
    return;
  std::vector<dem::ParticleFields> kept = dem::read_snapshots(file_);
  // Snapshots are taken at samples, a sample interval apart; the engine's clock and the
  // runner's may differ in the last bits (0.035000000000000031 against 0.035), so "later"
  // means more than half an interval later: the snapshot at the checkpoint's own sample stays.
  const double tolerance = 0.5 * sample_interval_;
  const auto later = std::find_if(kept.begin(), kept.end(),
                                  [&](const auto &f) { return f.time > time + tolerance; });
  if (later == kept.end())
    return;
  kept.erase(later, kept.end());
  fs::remove(file_);
  fs::remove(dem::xdmf_path(file_));
  for (const auto &f : kept)
    dem::append_snapshot(file_, f);
}

void SnapshotRecorder::operator()(const RunProgress &p)
{
  if (p.branch != 0 || p.stage != p.stage_count - 1 || next_ > n_)
    return;
  if (next_ > 0 && p.stage_fraction < double(next_) / double(n_) - 1e-12)
    return;
  dem::append_snapshot(file_, engine_.snapshot(onset_label(*p.sample, kind_, axial_)));
  while (next_ <= n_ && p.stage_fraction >= double(next_) / double(n_) - 1e-12)
    ++next_;
}

void add_dem_fields(compare::ReportInput &in, const fs::path &dir, std::vector<compare::OnsetEstimate> &onsets)
{
  const fs::path file = dir / dem_fields_file;
  if (!fs::exists(file)) {
    in.notes.push_back("DEM: no particle snapshots in " + file.string() + "; no DEM onset or maps.");
    return;
  }
  const std::vector<dem::ParticleFields> fields = dem::read_snapshots(file);
  if (fields.size() < 2) {
    in.notes.push_back("DEM: fewer than two particle snapshots; no DEM onset or maps.");
    return;
  }
  std::vector<compare::ParticleSnapshot> snapshots;
  for (const auto &f : fields)
    snapshots.push_back({f.ids, f.positions, f.label});
  double mean_radius = 0.0;
  for (double r : fields.front().radii)
    mean_radius += r / double(fields.front().radii.size());
  compare::LocalizationOptions options;
  options.strain.radius = 3.0 * mean_radius;
  const compare::LocalizationResult loc = compare::detect_localization(snapshots, options);
  compare::OnsetEstimate dem_onset;
  dem_onset.source = "DEM (particle local strain)";
  dem_onset.found = loc.onset_found;
  dem_onset.strain = loc.onset_label;
  dem_onset.has_angle = loc.band.found;
  dem_onset.angle_deg = loc.band.angle_to_compressive_deg;
  std::ostringstream note;
  note << fields.size() << " snapshots; heterogeneity index (CV of the incremental local shear strain) up to "
       << (loc.index.empty() ? 0.0 : *std::max_element(loc.index.begin(), loc.index.end())) << ", threshold "
       << options.threshold;
  if (loc.band.found)
    note << "; band of " << loc.band.band_particles << " particles, planarity " << loc.band.planarity;
  dem_onset.note = note.str();
  onsets.push_back(dem_onset);
}

} // namespace geocomp::cli
