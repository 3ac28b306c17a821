// `geocomp check` and `geocomp print-parameters`: the case file, without running anything.
#include "CaseValidation.h"
#include "Log.h"
#include "Commands.h"

#include "compare/case/CaseDescription.h"

#include <iostream>

namespace geocomp::cli {

Command print_parameters_command()
{
  Command c;
  c.name = "print-parameters";
  c.summary = "print every case-file parameter with default, allowed values and help";
  c.usage = "usage: geocomp print-parameters\n\n"
            "Prints every parameter of a case file (.prm syntax) with its default value, the values\n"
            "it accepts and its help text. Redirect it to a file to start a new case.\n";
  c.run = [](const std::vector<std::string> &args) {
    Arguments::parse(args, {}, {});
    if (!Arguments::parse(args, {}, {}).positional.empty())
      throw UsageError("print-parameters takes no arguments");
    std::cout << describe_parameters();
    return static_cast<int>(ok);
  };
  return c;
}

Command check_command()
{
  Command c;
  c.name = "check";
  c.summary = "validate a case file (every section, the whole loading program) without running";
  c.usage = "usage: geocomp check <case.prm|case.json>\n\n"
            "Reads and validates the case file: every section, every parameter, the whole loading\n"
            "program, and for each engine it names the checks that engine runs before it starts\n"
            "(the DEM's specimen source, text file or store; the continuum's material and mesh) -\n"
            "a case check accepts is one every engine it names accepts. Prints a summary and exits\n"
            "0, or prints one message naming the file, the parameter and what was expected, and\n"
            "exits 2. Writes nothing.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {}, {});
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    try {
      const CaseDescription d = read_valid_case(a.positional[0]);
      std::cout << d.file << ": ok\n  title: " << d.title << "\n  engines:";
      for (const auto &e : d.engines)
        std::cout << " " << e;
      std::cout << "\n  program: " << d.program.stages.size() << " stage(s), sampling every "
                << d.program.sample_interval << " s\n";
      for (std::size_t i = 0; i < d.program.stages.size(); ++i) {
        const Stage &s = d.program.stages[i];
        std::cout << "    " << i + 1 << ". " << s.name << (s.isochoric ? " (isochoric, S0 eq. 3)" : "")
                  << ", stops when";
        for (const auto &cond : s.stop_any)
          std::cout << " [" << cond.text << "]";
        if (!s.unload_at.empty())
          std::cout << ", " << s.unload_at.size() << " unloading branch(es)";
        std::cout << "\n";
      }
      std::cout << "  output: " << d.output.directory << "\n";
      return static_cast<int>(ok);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
  };
  return c;
}

const std::vector<Command> &commands()
{
  static const std::vector<Command> all = {
    pair_command(),    dem_command(),   liggghts_command(),   material_point_command(), continuum_command(), fem_dem_command(), report_command(),
    compare_command(), calibrate_command(), sweep_command(), study_command(), pack_command(), export_command(), import_command(), rate_sweep_command(), crush_command(), shear_box_command(), check_command(), print_parameters_command()};
  return all;
}

} // namespace geocomp::cli
