// `geocomp crush`: S2's particle-breakage programs (single-particle crushing, uniaxial
// compression with cube, 4-ball or 18-ball fragment replacement). After a run, and alone
// with --report DIR, it rewrites <DIR>/report/ from every run in DIR (compare/CrushReport.h),
// as `geocomp shear-box` does for S4: several cases run into one folder overlay there.
#include "Commands.h"
#include "Log.h"
#include "OutputFolderLock.h"

#include "common/AtomicFile.h"
#include "compare/CrushReport.h"
#include "dem/program/CrushCase.h"

#include <filesystem>
#include <fstream>
#include <iostream>

namespace geocomp::cli {

namespace {

// <dir>/report from every run in `dir` (S2 Figs. 3 and 7, the roses); false with a message on failure.
bool refresh_crush_report(const std::string &dir)
{
  try {
    const auto runs = compare::read_crush_runs(dir);
    if (runs.empty()) {
      log::error("crush report: no <case>_summary.tsv of a crush run in " + dir);
      return false;
    }
    const compare::CrushReportOutcome o = compare::write_crush_report(runs, std::filesystem::path(dir) / "report");
    if (!o.message.empty())
      log::warning("crush report: " + o.message);
    std::cout << "wrote " << o.dir.string() << "/index.html (" << runs.size() << " runs";
    if (o.plots_made)
      for (const std::string &p : o.plots)
        std::cout << ", " << p;
    std::cout << ")\n";
    return true;
  } catch (const std::exception &e) {
    log::error(std::string("crush report: ") + e.what());
    return false;
  }
}

} // namespace

Command crush_command()
{
  Command c;
  c.name = "crush";
  c.summary = "S2 particle breakage: single-particle crushing or uniaxial compression (cube replacement)";
  c.usage = "usage: geocomp crush <case.prm> [--output DIR] [--check] [--print-parameters]\n"
            "       geocomp crush --report DIR\n\n"
            "Runs S2's single-particle crushing test (spheres crushed one by one between two platens)\n"
            "or its uniaxial compression of one-size spheres with breakage (docs/s2-breakage.md), and\n"
            "writes <DIR>/<case>_curve.tsv, _fragments.tsv, _gradation.tsv, _summary.tsv (and\n"
            "_crushing.tsv for single particles; _polar.tsv, _polar_summary.tsv and _polar_<state>.svg,\n"
            "the contact polar distributions of S2 Figs. 8-11 after seating, at the peak and at the\n"
            "end, for uniaxial runs), then rewrites <DIR>/report/ (index.html; gnuplot: stress-strain\n"
            "or force-approach, gradation as S2 Fig. 7, fragment sizes per seed as S2 Fig. 3, the roses)\n"
            "from every run in DIR; --report DIR only rewrites that report. --check only validates\n"
            "the case; --print-parameters prints every crush parameter with default and help.\n"
            "Exit 0 ok, 1 run failure, 2 bad input.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"output", "report"}, {"check", "print-parameters"});
    if (a.has("report")) {
      if (!a.positional.empty())
        throw UsageError("--report DIR takes no case file");
      const std::string dir = a.get("report");
      if (!std::filesystem::is_directory(dir)) {
        log::error("--report: '" + dir + "' is not a folder (expected the --output folder of crush runs)");
        return static_cast<int>(bad_input);
      }
      return static_cast<int>(refresh_crush_report(dir) ? ok : run_failure);
    }
    if (a.has("print-parameters")) {
      std::cout << dem::describe_crush_parameters();
      return static_cast<int>(ok);
    }
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    dem::CrushCase cc;
    try {
      cc = dem::read_crush_case(a.positional[0]);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    if (a.has("check")) {
      std::cout << cc.file << ": ok (" << cc.setup.mode << ", " << dem::to_string(cc.setup.breakage.rules.mode)
                << ")\n";
      return static_cast<int>(ok);
    }
    const std::string dir = a.get("output", cc.output_directory);
    const std::string stem = std::filesystem::path(cc.file).stem().string();
    // Locked for this run; a path that cannot be a folder is bad input (CaseError: exit 2).
    const OutputFolderLock lock(dir, cc.file, a.has("output") ? "--output" : "output/directory");
    try {
      const dem::CrushResults r =
        dem::run_crush(cc.setup, [](const std::string &line) { std::cout << line << std::endl; });
      const auto base = std::filesystem::path(dir) / stem;
      auto table = [&](const std::string &suffix, const dem::Table &t) {
        if (t.columns.empty())
          return;
        write_atomically(base.string() + suffix, [&](const std::filesystem::path &tmp) {
          dem::write_table(tmp.string(), t);
        });
      };
      table("_curve.tsv", r.curve);
      table("_crushing.tsv", r.crushing);
      table("_fragments.tsv", r.fragments);
      table("_gradation.tsv", r.gradation);
      write_atomically(base.string() + "_summary.tsv", [&](const std::filesystem::path &tmp) {
        std::ofstream out(tmp);
        out << "key\tvalue\n";
        for (const std::string &line : r.summary)
          out << line << "\n";
        if (!out)
          throw std::runtime_error("write failed: " + tmp.string());
      });
      if (!r.polar.empty()) {
        write_atomically(base.string() + "_polar.tsv",
                         [&](const std::filesystem::path &tmp) { dem::write_polar_tsv(tmp.string(), r.polar); });
        write_atomically(base.string() + "_polar_summary.tsv", [&](const std::filesystem::path &tmp) {
          dem::write_polar_summary_tsv(tmp.string(), r.polar);
        });
        for (const dem::PolarState &state : r.polar)
          write_atomically(base.string() + "_polar_" + state.first + ".svg", [&](const std::filesystem::path &tmp) {
            dem::write_polar_svg(tmp.string(), cc.setup.title + " (" + state.first + ")", state.second);
          });
      }
      for (const std::string &line : r.summary)
        std::cout << line << "\n";
      log::info("wrote " + base.string() + (r.polar.empty() ? "_*.tsv" : "_*.tsv, _polar_*.svg"));
      refresh_crush_report(dir); // a report that cannot be drawn does not fail the run (its message is logged)
    } catch (const std::exception &e) {
      log::error(std::string("crush failed: ") + e.what());
      return static_cast<int>(run_failure);
    }
    return static_cast<int>(ok);
  };
  return c;
}

} // namespace geocomp::cli
