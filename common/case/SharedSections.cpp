// The sections every case shares: the top level (title, engines, seed) and `output`.
// (The `program` section has a file of its own: ProgramSection.cpp.)
#include "common/case/SectionReader.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>

namespace geocomp::sections {

void ReadEntries::operator()(const char *entry, std::vector<std::string> &v) const
{
  v = dealii::Utilities::split_string_list(prm.get(entry));
}

void ReadEntries::operator()(const char *entry, std::vector<double> &v) const
{
  v = dealii::Utilities::string_to_double(dealii::Utilities::split_string_list(prm.get(entry)));
}


using dealii::Patterns::Anything;
using dealii::Patterns::Bool;

std::vector<std::pair<double, double>> parse_points(const std::string &text, const std::string &parameter,
                                                    const Reader &r)
{
  std::vector<std::pair<double, double>> t;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos)
      r.fail(parameter, "expected 'kappa:value' pairs separated by commas, got '" + item + "'");
    double k = 0, v = 0;
    try {
      std::size_t u1 = 0, u2 = 0;
      const std::string ks = item.substr(0, colon), vs = item.substr(colon + 1);
      k = std::stod(ks, &u1);
      v = std::stod(vs, &u2);
      if (ks.find_first_not_of(" \t", u1) != std::string::npos || vs.find_first_not_of(" \t", u2) != std::string::npos)
        throw std::invalid_argument(item);
    } catch (const std::exception &) {
      r.fail(parameter, "expected numbers in 'kappa:value', got '" + item + "'");
    }
    if (!std::isfinite(k) || !std::isfinite(v))
      r.fail(parameter, "expected finite numbers, got '" + item + "'");
    if (!t.empty() && !(k > t.back().first))
      r.fail(parameter, "kappa must increase strictly from one point to the next");
    t.emplace_back(k, v);
  }
  if (t.empty())
    r.fail(parameter, "expected at least one 'kappa:value' point");
  if (t.front().first != 0.0)
    r.fail(parameter, "the first point must be at kappa = 0");
  return t;
}

void declare_head(dealii::ParameterHandler &prm)
{
  prm.declare_entry("title", "", Anything(), "A title for reports.");
  prm.declare_entry("engines", "dem, continuum", dealii::Patterns::MultipleSelection("dem|continuum|material-point|fem-dem|liggghts"),
                    "Engines that run the program: 'dem', 'continuum' (deal.II cube), 'material-point' "
                    "(the continuum model at one point), 'fem-dem' (the continuum section's cube with a periodic DEM "
                    "cell of the specimen's grains at every quadrature point, section 'dem rve'; docs/coupled.md), "
                    "'liggghts' (the DEM specimen in LIGGGHTS, "
                    "Debian package liggghts; docs/liggghts.md).");
  prm.declare_entry("seed", "1", dealii::Patterns::Integer(0), "Random seed: the same seed gives the same specimen and curves.");
}

void declare_output(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("output");
  prm.declare_entry("directory", "results", Anything(),
                    "Folder for results (HDF5 per engine, fields, report); relative to the working directory.");
  prm.declare_entry("report", "true", Bool(), "Write the comparison report (HTML + plots + metrics.json).");
  prm.declare_entry("fields", "true", Bool(), "Write field output (VTU for the continuum, HDF5+XDMF for DEM).");
  prm.leave_subsection();
}

OutputParameters parse_output(dealii::ParameterHandler &prm, const Reader &r)
{
  OutputParameters p;
  read_section(prm, r, "output", p);
  if (p.directory.empty())
    r.fail("output/directory", "expected a folder name");
  return p;
}

} // namespace geocomp::sections
