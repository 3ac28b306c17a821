#pragma once
// The maps of `pair`'s report at the named states (compare/NamedStates.h): B, the peak, D and
// the DEM onset located on the DEM's curve (the first engine's without a DEM), the DEM's
// mid-section (DemSection.h) beside the FE cube's mid-plane (MidPlane.h) at the same strain.
#include "compare/LocalizationOnsets.h"
#include "compare/Report.h"
#include "compare/case/CaseDescription.h"

#include <filesystem>
#include <vector>

namespace geocomp::cli {

/// Fills in.state_maps and in.state_maps_note from the sections recorded in `dir`; `in` has its
/// responses and metrics, `onsets` the engines' onsets (the DEM's among them when it ran).
void add_state_maps(compare::ReportInput &in, const CaseDescription &c, const std::filesystem::path &dir,
                    const std::vector<compare::OnsetEstimate> &onsets);

} // namespace geocomp::cli
