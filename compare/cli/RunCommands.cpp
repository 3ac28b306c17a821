// `geocomp material-point|continuum|dem <case>` run one engine; `geocomp pair <case>` runs
// every engine the case names (reusing up-to-date results), compares and reports;
// `geocomp compare <dir>` and `geocomp report <dir>` work on existing results.
#include "CaseValidation.h"
#include "Commands.h"
#include "Engines.h"
#include "Log.h"
#include "Mpi.h"
#include "OutputFolderLock.h"
#include "Pair.h"
#include "PairOverRanks.h"

#include "common/ResponseFile.h"
#include "compare/Metrics.h"

#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
std::string command_line;

/// `pair` on a case from the command line: its exit code (1 when an engine did not complete
/// its program; the warning was printed with the run).
int pair_exit_code(const CaseDescription &c, const fs::path &dir, bool reuse, int liggghts_ranks = 1)
{
  return pair_case(c, dir, command_run_settings(reuse, liggghts_ranks)).complete ? ok : run_failure;
}

struct RunOptions {
  CaseDescription c;
  fs::path dir;
  std::string dir_given_as; ///< "output/directory" or "--output", for messages
  bool reuse = true;
  int liggghts_ranks = 1; ///< --mpi N: LIGGGHTS under `mpirun -np N`
};

/// The value of --mpi: a whole number of ranks, 1 to 4096.
int parse_ranks(const std::string &text)
{
  std::size_t end = 0;
  int n = 0;
  try {
    n = std::stoi(text, &end);
  } catch (const std::exception &) {
    end = 0;
  }
  if (end != text.size() || n < 1 || n > 4096)
    throw UsageError("--mpi expects a number of LIGGGHTS ranks from 1 to 4096, got '" + text + "'");
  return n;
}

/// The case, validated for its engines and `engine` (the one a command runs) before
/// anything runs, and where its results go.
RunOptions parse_run(const std::vector<std::string> &args, const std::vector<std::string> &engine = {})
{
  const Arguments a = Arguments::parse(args, {"output", "mpi"}, {"force"});
  if (a.positional.size() != 1)
    throw UsageError("expected exactly one case file");
  RunOptions o;
  o.liggghts_ranks = parse_ranks(a.get("mpi", "1"));
  o.c = read_valid_case(a.positional[0], engine);
  o.dir = a.has("output") ? fs::path(a.get("output")) : fs::path(o.c.output.directory);
  o.dir_given_as = a.has("output") ? "--output" : "output/directory";
  o.reuse = !a.has("force");
  return o;
}

/// The output folder of a run, locked for as long as the result lives (OutputFolderLock).
std::unique_ptr<OutputFolderLock> lock_output(const RunOptions &o)
{
  ensure_mpi();
  return lock_for_run(o.dir, o.c.file, o.dir_given_as, MPI_COMM_WORLD);
}

Command engine_command(const std::string &engine, const std::string &summary, const std::string &details)
{
  Command c;
  c.name = engine;
  c.summary = summary;
  c.usage = "usage: geocomp " + engine + " <case> [--output DIR] [--force]" +
            (engine == "liggghts" ? " [--mpi N]" : "") + "\n\n" + details +
            "\nWrites <output directory>/" + results_file(engine) +
            " (docs/results-format.md); --output overrides the case's\n"
            "output directory; results made from the same case text by the same build are reused\n"
            "unless --force.\n";
  c.run = [engine](const std::vector<std::string> &args) {
    RunOptions o = parse_run(args, {engine});
    return guarded([&] {
      const auto lock = lock_output(o);
      const Response r = run_engine(engine, o.c, o.dir, command_run_settings(o.reuse, o.liggghts_ranks));
      return static_cast<int>(completion_status(r, o.c.program) == "complete" ? ok : run_failure);
    });
  };
  return c;
}
} // namespace

void set_command_line(const std::string &line) { command_line = line; }

RunSettings command_run_settings(bool reuse, int liggghts_ranks)
{
  RunSettings s;
  s.reuse = reuse;
  s.command_line = command_line;
  s.liggghts.ranks = liggghts_ranks;
  return s;
}

Command dem_command()
{
  return engine_command("dem", "run the DEM specimen in its wall box through the program",
                        "Prepares (or reuses, <output>/dem-specimen.bin) the case's consolidated specimen,\n"
                        "then plays the loading program with kinematic and servo walls (S0 eq. (3) as\n"
                        "wall positions), measuring wall and Love-Weber stress, coordination, fabric,\n"
                        "inertial number and unbalanced force; particle snapshots go to\n"
                        "<output>/dem-fields.h5 with an XDMF sidecar for ParaView.\n");
}

Command liggghts_command()
{
  return engine_command("liggghts", "run the case's DEM specimen in LIGGGHTS (Debian package liggghts)",
                        "Exports the case (`geocomp export liggghts`) into <output>/liggghts/ from the\n"
                        "specimen `geocomp dem` starts from, runs `liggghts -in in.geocomp` there (--mpi N:\n"
                        "under `mpirun -np N`; its screen output in liggghts.out) and reads its samples back\n"
                        "(`geocomp import liggghts`). Exit 2 when LIGGGHTS is not installed or the case has\n"
                        "an entry it cannot play, 1 when LIGGGHTS refuses the deck (its ERROR line quoted).\n"
                        "docs/liggghts.md.\n");
}

Command material_point_command()
{
  return engine_command("material-point", "run the continuum model at one material point through the program",
                        "Plays the case's loading program on one material point of the continuum model\n"
                        "(mixed control: strain on kinematic axes, stress on servo axes, S0 eq. (3)).\n");
}

Command continuum_command()
{
  return engine_command("continuum", "run the deal.II Mohr-Coulomb cube through the program (mpirun -np N)",
                        "Runs the case's loading program on the finite-element cube (deal.II, PETSc, MPI:\n"
                        "`mpirun -np N geocomp continuum <case>`), with VTU field output per sample.\n");
}

Command fem_dem_command()
{
  return engine_command("fem-dem", "run FEM x DEM: the continuum section's cube, a DEM cell at every point (mpirun -np N)",
                        "Runs the case's loading program on the finite-element cube of the continuum section\n"
                        "(mesh, kinematics, solver) whose every quadrature point is a periodic DEM cell of the\n"
                        "specimen's grains (section 'dem rve': prepared to the specimen's pressure and driven by\n"
                        "the point's deformation; docs/coupled.md), with VTU fields in fem-dem-fields/.\n");
}

Command pair_command()
{
  Command c;
  c.name = "pair";
  c.summary = "run every engine of a case (reusing up-to-date results), compare, write the report";
  c.usage = "usage: geocomp pair <case> [--output DIR] [--force] [--mpi N]\n\n"
            "Runs (or reuses) each engine the case names on the same loading program, computes\n"
            "the metrics of every Response (elastic limit, peak, softening, residual, dilatancy),\n"
            "and writes <output directory>/report/index.html with plots and metrics.json.\n"
            "--mpi N runs the liggghts engine under `mpirun -np N` (docs/liggghts.md).\n";
  c.run = [](const std::vector<std::string> &args) {
    RunOptions o = parse_run(args);
    return guarded([&] {
      const auto lock = lock_output(o);
      return pair_exit_code(o.c, o.dir, o.reuse, o.liggghts_ranks);
    });
  };
  return c;
}

Command sweep_command()
{
  Command c;
  c.name = "sweep";
  c.summary = "run many independent cases, spread over MPI ranks (mpirun -np N geocomp sweep ...)";
  c.usage = "usage: [mpirun -np N] geocomp sweep <case> [<case> ...] [--force]\n\n"
            "Validates every case first (any bad case: exit 2, nothing run), then runs `pair` on\n"
            "each, case k on rank k mod N (each case's engines on that one rank), and prints one\n"
            "summary line per case. Exit 1 if any case failed.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {}, {"force"});
    if (a.positional.empty())
      throw UsageError("expected at least one case file");
    std::vector<CaseDescription> cases;
    try {
      for (const auto &f : a.positional)
        cases.push_back(read_valid_case(f));
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    ensure_mpi();
    const std::vector<int> codes = pair_over_ranks(cases, command_run_settings(!a.has("force")), "sweep");
    return std::all_of(codes.begin(), codes.end(), [](int code) { return code == ok; }) ? static_cast<int>(ok)
                                                                                        : static_cast<int>(run_failure);
  };
  return c;
}

/// The results of the case's engines found in `dir` (nothing is run).
EngineRuns existing_results(const fs::path &dir)
{
  EngineRuns runs;
  for (const auto &engine : engine_names()) {
    const fs::path file = dir / results_file(engine);
    if (fs::exists(file))
      runs.emplace_back(engine, read_response(file));
  }
  if (runs.empty())
    throw std::runtime_error("no results in " + dir.string() + "; run `geocomp pair` first");
  return runs;
}

/// `report` and `compare`: existing results of a case, then `action` on the comparison;
/// a command that `writes` into the folder locks it first (OutputFolderLock).
Command existing_results_command(const std::string &name, const std::string &summary, const std::string &details,
                                 const std::function<int(const compare::ReportInput &, const fs::path &)> &action,
                                 bool writes = false)
{
  Command c;
  c.name = name;
  c.summary = summary;
  c.usage = "usage: geocomp " + name + " <case> [--output DIR]\n\n" + details;
  c.run = [action, writes](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"output"}, {});
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    return guarded([&] {
      const CaseDescription cd = read_case(a.positional[0]);
      validate_engines(cd, {}); // the same refusals as every other command, before anything is read
      const fs::path dir = a.has("output") ? fs::path(a.get("output")) : fs::path(cd.output.directory);
      std::unique_ptr<OutputFolderLock> lock;
      if (writes)
        lock = std::make_unique<OutputFolderLock>(dir, cd.file, a.has("output") ? "--output" : "output/directory");
      return action(report_input(cd, existing_results(dir), dir), dir);
    });
  };
  return c;
}

Command compare_command()
{
  return existing_results_command(
    "compare", "compare existing results of a case and print the metrics and verdict (JSON)",
    "Reads the results files of the case's engines from the output directory (nothing is\n"
    "run, nothing is written) and prints metrics.json's content: the metrics of every\n"
    "engine, their differences and the Rudnicki-Rice verdict.\n",
    [](const compare::ReportInput &in, const fs::path &) {
      std::cout << compare::metrics_json(in);
      return static_cast<int>(ok);
    });
}

Command report_command()
{
  return existing_results_command("report", "compare existing results of a case and write the report",
                                  "Reads the results files of the case's engines from the output directory (nothing is\n"
                                  "run) and writes the comparison report.\n",
                                  [](const compare::ReportInput &in, const fs::path &dir) {
                                    write_report_and_say(in, dir, MPI_COMM_WORLD);
                                    return static_cast<int>(ok);
                                  },
                                  true);
}

} // namespace geocomp::cli
