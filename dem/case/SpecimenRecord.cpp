#include "dem/case/SpecimenRecord.h"

#include "common/case/CanonicalText.h"

#include <algorithm>
#include <sstream>

namespace geocomp::dem {

const std::vector<SpecimenIndependentEntry> &specimen_independent_entries()
{
  static const char *guard = "a guard only stops a run that passes it; it never changes a step, and the reused "
                             "engine takes the case's guards";
  static const std::vector<SpecimenIndependentEntry> entries = {
    {"dem/threads", "the DEM step gives the same bits for any thread count (fixed slot order, LoadScatter.h; "
                    "tested at 1-3 threads); the reused engine takes the case's thread count"},
    {"dem/guard min edge", guard},
    {"dem/guard stress ratio", guard},
    {"dem/snapshots", "particle snapshots are written during the program only, never during preparation"},
    {"dem/checkpoint interval", "program checkpoints are written during the program only"},
  };
  return entries;
}

std::string dem_parameters_text(const DemCase &c)
{
  CanonicalText t("");
  DemCase::visit_sections(c, [&t](const char *section, const auto &p) {
    t.section(section);
    std::decay_t<decltype(p)>::visit(p, t);
  });
  return t.text();
}

std::string specimen_record(const DemCase &c, const std::string &build)
{
  std::ostringstream record;
  record << "build = " << build << "\nseed = " << c.seed << "\n";
  std::istringstream lines(dem_parameters_text(c));
  const auto &independent = specimen_independent_entries();
  for (std::string line; std::getline(lines, line);) {
    const std::string entry = line.substr(0, line.find(" = "));
    const bool left_out = std::any_of(independent.begin(), independent.end(),
                                      [&entry](const SpecimenIndependentEntry &e) { return entry == e.entry; });
    if (!left_out)
      record << line << "\n";
  }
  return record.str();
}

} // namespace geocomp::dem
