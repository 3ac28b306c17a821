#include "PairMaps.h"
#include "Pair.h"

#include "compare/NamedStates.h"

#include <algorithm>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
const char *const maps_note =
  "The states are located on the reference curve (the DEM's): B the elastic limit, the peak the maximum of "
  "the smoothed curve, D the first sample past the peak whose stress dropped by 5 % of the peak rise (else "
  "the end of the main path), and the DEM localization onset when found. Each engine recorded its mid-section "
  "y = L0/2 at every main-path sample (DEM: particles within 2 mean radii of the plane; FE cube and FEM x DEM: "
  "points of the cells the plane cuts, y = L_y/2 of a box); each panel shows the recorded sample nearest the "
  "state's strain, its strain in the title (strains in the measure of the stress-strain plot's x axis); a box "
  "mesh has no DEM panel (the DEM's box is a cube). "
  "Displacements since the stage start, from the box centre in every engine: the displacement there of the "
  "section's least-squares affine field is subtracted. Local strain, the same measure in all: the in-plane "
  "maximum shear strain e_1 - e_3 of the best-fit deformation of each point's neighbours (DEM within 3 mean "
  "radii, FE within 1.5 point spacings). The panels of a row share one colour scale, at least 1 % of the "
  "row's scale wide, so that a homogeneous field is one colour (docs/metrics.md).";
} // namespace

void add_state_maps(compare::ReportInput &in, const std::vector<PairSection> &sections,
                    const std::vector<compare::OnsetEstimate> &onsets)
{
  if (in.responses.empty() || in.metrics.empty())
    return;
  const std::string dem_label = engine_label("dem");
  const auto reference = std::find_if(in.metrics.begin(), in.metrics.end(),
                                      [&](const compare::NamedMetrics &m) { return m.label == dem_label; });
  const compare::NamedMetrics &metrics = reference == in.metrics.end() ? in.metrics.front() : *reference;
  const Response *response = response_of(in, metrics.label);
  if (!response)
    return;
  const auto onset = std::find_if(onsets.begin(), onsets.end(),
                                  [](const compare::OnsetEstimate &o) { return o.source.rfind("DEM", 0) == 0; });
  std::vector<compare::NamedState> states;
  try {
    const compare::Curve curve = compare::extract_curve(*response, in.kind, in.stage, in.axial);
    states = compare::named_states(curve, metrics.metrics, onset == onsets.end() ? nullptr : &*onset);
  } catch (const std::exception &e) {
    in.notes.push_back("No maps at named states: " + std::string(e.what()));
    return;
  }
  const bool recorded = std::any_of(sections.begin(), sections.end(), [](const PairSection &s) { return s.series; });
  if (!recorded)
    return;
  std::vector<compare::StrainedSection> panels;
  for (const PairSection &s : sections)
    panels.push_back(strained(s, in));
  in.state_maps = compare::state_maps(states, panels);
  in.state_maps_note = std::string(maps_note) + (metrics.label == dem_label ? "" : " No DEM: the states are on the " +
                                                                                      metrics.label + " curve.");
}

} // namespace geocomp::cli
