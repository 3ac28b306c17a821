// The sections every case shares: the top level (title, engines, seed) and `output`.
// (The `program` section has a file of its own: ProgramSection.cpp.)
#include "common/case/SectionReader.h"

namespace geocomp::sections {

using dealii::Patterns::Anything;
using dealii::Patterns::Bool;

void declare_head(dealii::ParameterHandler &prm)
{
  prm.declare_entry("title", "", Anything(), "A title for reports.");
  prm.declare_entry("engines", "dem, continuum", dealii::Patterns::MultipleSelection("dem|continuum|material-point"),
                    "Engines that run the program: 'dem', 'continuum' (deal.II cube), 'material-point' "
                    "(the continuum model at one point).");
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
  prm.enter_subsection("output");
  p.directory = prm.get("directory");
  p.report = prm.get_bool("report");
  p.fields = prm.get_bool("fields");
  prm.leave_subsection();
  if (p.directory.empty())
    r.fail("output/directory", "expected a folder name");
  return p;
}

} // namespace geocomp::sections
