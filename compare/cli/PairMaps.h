#pragma once
// The maps of `pair`'s report at the named states (compare/NamedStates.h): B, the peak, D and
// the DEM onset located on the DEM's curve (the first engine's without a DEM), one panel per
// recorded section (PairSections.h: the DEM's mid-section, DemSection.h, and each FE engine's
// mid-plane, MidPlane.h) at the same strain: DEM | FE cube | FEM x DEM, those that ran.
#include "PairSections.h"

#include "compare/LocalizationOnsets.h"
#include "compare/Report.h"

#include <vector>

namespace geocomp::cli {

/// Fills in.state_maps and in.state_maps_note from `sections` (recorded_sections); `in` has its
/// responses and metrics, `onsets` the engines' onsets (the DEM's among them when it ran).
void add_state_maps(compare::ReportInput &in, const std::vector<PairSection> &sections,
                    const std::vector<compare::OnsetEstimate> &onsets);

} // namespace geocomp::cli
