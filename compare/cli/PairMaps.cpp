#include "PairMaps.h"
#include "DemSection.h"
#include "Engines.h"
#include "MidPlane.h"
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
  "y = L0/2 at every main-path sample (DEM: particles within 2 mean radii of the plane; FE: points of the cut "
  "cells); each panel shows the recorded sample nearest the state's strain, its strain in the title "
  "(strains in the measure of the stress-strain plot's x axis). "
  "Displacements since the stage start, from the box centre in both engines: the displacement there of the "
  "section's least-squares affine field is subtracted. Local strain, the same measure in both: the in-plane "
  "maximum shear strain e_1 - e_3 of the best-fit deformation of each point's neighbours (DEM within 3 mean "
  "radii, FE within 1.5 point spacings). The two panels of a row share one colour scale, at least 1 % of the "
  "row's scale wide, so that a homogeneous field is one colour (docs/metrics.md).";

const Response *response_of(const compare::ReportInput &in, const std::string &label)
{
  for (const auto &r : in.responses)
    if (r.label == label)
      return &r.response;
  return nullptr;
}

compare::StrainedSection strained(const std::optional<compare::SectionSeries> &s, const compare::ReportInput &in,
                                  const std::string &label)
{
  const Response *r = response_of(in, label);
  if (!s || !r)
    return {};
  return compare::strained_section(*s, *r, in.kind, in.stage, in.axial);
}
} // namespace

void add_state_maps(compare::ReportInput &in, const CaseDescription &c, const fs::path &dir,
                    const std::vector<compare::OnsetEstimate> &onsets)
{
  if (in.responses.empty() || in.metrics.empty())
    return;
  const std::string dem_label = engine_label("dem"), fe_label = engine_label("continuum");
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
  const auto runs = [&c](const char *engine) {
    return std::find(c.engines.begin(), c.engines.end(), engine) != c.engines.end();
  };
  std::optional<compare::SectionSeries> dem, fe;
  if (runs("dem"))
    dem = read_dem_section(dir);
  if (runs("continuum") && c.continuum.box_edges.empty()) { // a box is not the DEM's cube: no side-by-side maps
    const continuum::CubeParameters cube = cube_parameters(c, dir.string());
    fe = read_cube_section(dir, cube.side, cube.cells_per_side);
  }
  if (!dem && !fe)
    return;
  in.state_maps = compare::state_maps(states, strained(dem, in, dem_label), dem_label, strained(fe, in, fe_label),
                                      fe_label);
  in.state_maps_note = std::string(maps_note) + (metrics.label == dem_label ? "" : " No DEM: the states are on the " +
                                                                                      metrics.label + " curve.");
}

} // namespace geocomp::cli
