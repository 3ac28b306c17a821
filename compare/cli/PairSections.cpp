#include "PairSections.h"
#include "DemSection.h"
#include "Engines.h"
#include "MidPlane.h"
#include "Pair.h"

#include "compare/SectionLocalization.h"

#include <algorithm>

namespace geocomp::cli {

namespace fs = std::filesystem;

std::vector<PairSection> recorded_sections(const CaseDescription &c, const fs::path &dir)
{
  const auto runs = [&c](const char *engine) {
    return std::find(c.engines.begin(), c.engines.end(), engine) != c.engines.end();
  };
  const bool fe = runs("continuum") || runs("fem-dem");
  std::vector<PairSection> sections;
  if (runs("dem") && (!fe || c.continuum.box_edges.empty()))
    sections.push_back({"dem", read_dem_section(dir)});
  if (!fe)
    return sections;
  const continuum::CubeParameters mesh = cube_parameters(c, dir.string());
  for (const char *engine : {"continuum", "fem-dem"})
    if (runs(engine))
      sections.push_back({engine, read_cube_section(dir, engine, engine_label(engine), mesh)});
  return sections;
}

const Response *response_of(const compare::ReportInput &in, const std::string &label)
{
  for (const auto &r : in.responses)
    if (r.label == label)
      return &r.response;
  return nullptr;
}

compare::StrainedSection strained(const PairSection &section, const compare::ReportInput &in)
{
  const std::string label = engine_label(section.engine);
  const Response *response = response_of(in, label);
  if (!section.series || !response)
    return {label, nullptr, {}, {}};
  return compare::strained_section(*section.series, *response, in.kind, in.stage, in.axial);
}

void add_strain_field_onset(const compare::ReportInput &in, const std::vector<PairSection> &sections,
                            const std::string &engine, std::vector<compare::OnsetEstimate> &onsets)
{
  const auto section = std::find_if(sections.begin(), sections.end(),
                                    [&engine](const PairSection &s) { return s.engine == engine; });
  if (section != sections.end())
    onsets.push_back(compare::strain_field_onset(strained(*section, in), engine_label(engine) + " (strain field)"));
}

} // namespace geocomp::cli
