// `geocomp rate-sweep`: S1's dynamic uniaxial tests over a range of strain rates.
#include "Commands.h"
#include "Log.h"
#include "OutputFolderLock.h"

#include "continuum/dynamics/RateSweepCase.h"
#include "continuum/dynamics/RateSweepOutput.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace geocomp::cli {

Command rate_sweep_command()
{
  Command c;
  c.name = "rate-sweep";
  c.summary = "S1 dynamic uniaxial tests: strength vs strain rate against S1 eqs. (14)-(15)";
  c.usage = "usage: geocomp rate-sweep <case.prm> [--output DIR] [--check] [--print-parameters]\n\n"
            "Runs S1's plane-stress specimen (explicit deal.II dynamics, kinetic Nikolaevsky model) in\n"
            "uniaxial compression or tension at each strain rate of the case, with the kinetic\n"
            "extension on, off or both, and writes <DIR>/<case>.tsv, <case>.svg and <case>.gp\n"
            "(docs/s1-kinetic-model.md). --check only validates the case; --print-parameters prints\n"
            "every rate-sweep parameter with default and help. Exit 0 ok, 1 run failure, 2 bad input.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"output"}, {"check", "print-parameters"});
    if (a.has("print-parameters")) {
      std::cout << dynamics::describe_rate_sweep_parameters();
      return static_cast<int>(ok);
    }
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    dynamics::RateSweepCase rc;
    try {
      rc = dynamics::read_rate_sweep_case(a.positional[0]);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    if (a.has("check")) {
      std::cout << rc.file << ": ok (" << rc.setup.material.name << ", " << kinetic::to_string(rc.setup.mode) << ", "
                << rc.setup.strain_rates.size() << " rate(s))\n";
      return static_cast<int>(ok);
    }
    const std::string dir = a.get("output", rc.output_directory);
    const std::string stem = std::filesystem::path(rc.file).stem().string();
    // Locked for this run; a path that cannot be a folder is bad input (CaseError: exit 2).
    const OutputFolderLock lock(dir, rc.file, a.has("output") ? "--output" : "output/directory");
    try {
      std::printf("%-7s %10s %10s %10s %8s %10s %8s\n", "kinetic", "rate[1/s]", "strength", "S1 fit", "error",
                  "no-inertia", "steps");
      const auto rows = dynamics::run_rate_sweep(rc.setup, [](const dynamics::RateSweepRow &r) {
        std::printf("%-7s %10.0e %10.4f %10.4f %+7.1f%% %10.4f %8ld\n", r.kinetic ? "on" : "off", r.strain_rate,
                    r.normalized_strength, r.s1_fit, 100.0 * r.relative_error(), r.point_normalized_strength,
                    r.run.steps);
        std::fflush(stdout);
      });
      const std::string base = (std::filesystem::path(dir) / stem).string();
      dynamics::write_rate_sweep_tsv(base + ".tsv", rc.setup, rows);
      dynamics::write_rate_sweep_svg(base + ".svg", rc.setup, rows);
      dynamics::write_rate_sweep_gnuplot(base + ".gp", stem + ".tsv", rc.setup);
      log::info("wrote " + std::string(base) + ".tsv, .svg, .gp");
    } catch (const std::exception &e) {
      log::error(std::string("rate sweep failed: ") + e.what());
      return static_cast<int>(run_failure);
    }
    return static_cast<int>(ok);
  };
  return c;
}

} // namespace geocomp::cli
