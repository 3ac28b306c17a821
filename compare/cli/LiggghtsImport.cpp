// `geocomp import liggghts DIR [--output RESULTS]` (issue 34): the samples of a deck that
// `geocomp export liggghts` wrote and LIGGGHTS ran, as the results file of an engine named
// "liggghts" (same HDF5 layout as every engine, docs/results-format.md), so that `compare`
// and the report read it beside geocomp's own engines.
#include "CaseValidation.h"
#include "Commands.h"
#include "LiggghtsExport.h"

#include "common/ResponseFile.h"
#include "common/Version.h"
#include "dem/case/SpecimenRecord.h"
#include "dem/liggghts/LiggghtsSamples.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
std::string read_text(const fs::path &file)
{
  std::ifstream in(file);
  if (!in)
    throw CaseError(file.string(), "export folder", "not found: expected a folder written by `geocomp export liggghts`");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
} // namespace

Command import_command()
{
  Command c;
  c.name = "import";
  c.summary = "read another engine's run of an exported case as a results file (LIGGGHTS)";
  c.usage = "usage: geocomp import liggghts DIR [--output RESULTS]\n\n"
            "Reads DIR/samples.txt and DIR/stages.txt, which LIGGGHTS writes when it runs the deck of\n"
            "`geocomp export liggghts <case> --output DIR` in DIR, and writes RESULTS/liggghts.h5 (RESULTS:\n"
            "the case's output directory unless given): the Response of engine \"liggghts\" with the\n"
            "case's text and parameters, strains from the box edges, the full stress tensor from the\n"
            "six walls' forces (tension positive, instantaneous), and the kinetic energies as extras.\n"
            "The case is the one DIR was exported from (DIR/geocomp-case); a case changed since the\n"
            "export is refused. docs/liggghts.md.\n\n"
            "Exit codes: 0 done, 2 bad input (no such folder or case, the case changed, samples\n"
            "missing or malformed), 1 the write failed.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"output"}, {});
    if (a.positional.size() != 2 || a.positional[0] != "liggghts")
      throw UsageError("expected `geocomp import liggghts DIR [--output RESULTS]`");
    const fs::path dir = a.positional[1];
    std::string case_file = read_text(dir / kExportCaseFile);
    while (!case_file.empty() && (case_file.back() == '\n' || case_file.back() == '\r'))
      case_file.pop_back();
    const CaseDescription cd = read_valid_case(case_file, {"dem"});
    if (read_text(dir / kExportParametersFile) != parameters_text(cd))
      throw CaseError(case_file, "case", "has changed since " + dir.string() +
                                           " was exported: export it again and run LIGGGHTS on the new deck");
    Response r;
    try {
      r = dem::read_liggghts_samples(dir, cd.program);
    } catch (const dem::LiggghtsSamplesError &e) {
      throw CaseError(dir.string(), "samples", e.what());
    }
    const fs::path out = a.has("output") ? fs::path(a.get("output")) : fs::path(cd.output.directory);
    fs::create_directories(out);
    RunMeta meta;
    meta.case_file = cd.file;
    meta.case_text = cd.text;
    meta.command = "geocomp import liggghts " + dir.string();
    meta.seed = cd.seed;
    meta.kinematics = "finite strain (LIGGGHTS particle positions; box strain from the wall positions, wall force "
                      "over current wall area)";
    meta.parameters = parameters_text(cd);
    meta.specimen_record = dem::specimen_record(cd, GEOCOMP_GIT_HASH);
    const fs::path file = out / "liggghts.h5";
    write_response(file, r, meta);
    std::cout << "import liggghts: " << r.samples.size() << " samples of " << dir.string() << " -> " << file.string()
              << "\n";
    return static_cast<int>(ok);
  };
  return c;
}

} // namespace geocomp::cli
