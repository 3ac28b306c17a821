// `geocomp study <study.prm>`: the cases of a study file (compare/case/StudyFile.h) run as one
// job - each through `pair`, spread over the MPI ranks as `sweep` spreads them, up-to-date
// results reused - then one report overlaying their curves and plotting their summary
// against the study's entry (compare/StudyReport.h).
#include "CaseValidation.h"
#include "Commands.h"
#include "Engines.h"
#include "Log.h"
#include "Mpi.h"
#include "OutputFolderLock.h"
#include "Pair.h"
#include "PairOverRanks.h"

#include "common/AtomicFile.h"
#include "common/ProgramRunner.h"
#include "common/ResponseFile.h"
#include "compare/StudyReport.h"
#include "compare/case/StudyFile.h"

#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
/// The study with every case checked for its engines (CaseError naming the study file).
Study read_valid_study(const std::string &path)
{
  Study s = read_study(path);
  for (const StudyCase &c : s.cases) {
    try {
      validate_engines(c.description);
    } catch (const CaseError &e) {
      throw CaseError(s.file, s.parameters.cases.empty() ? "study/values" : "study/cases",
                      "case '" + c.name + "' (from " + c.source + "): " + e.what());
    }
  }
  return s;
}

/// Writes each case's file (rank 0) unless it holds that text already, so that the results
/// made from it stay up to date.
void write_case_files(const Study &s)
{
  for (const StudyCase &c : s.cases) {
    std::ifstream in(c.file, std::ios::binary);
    std::stringstream old;
    old << in.rdbuf();
    if (in && old.str() == c.description.text)
      continue;
    fs::create_directories(c.folder);
    write_atomically(c.file, [&](const fs::path &tmp) {
      std::ofstream out(tmp, std::ios::binary);
      out << c.description.text;
      if (!out)
        throw std::runtime_error("cannot write " + tmp.string());
    });
  }
}

/// What a case's engines left in its folder, and why it failed when `code` says it did.
compare::StudyReportCase report_case(const StudyCase &c, int code)
{
  compare::StudyReportCase rc;
  rc.name = c.name;
  rc.label = c.label;
  rc.file = c.file;
  rc.x = c.x;
  rc.kind = compare::curve_kind_for(c.description.program);
  rc.axial = compare::axial_axis_for(c.description.program);
  std::string failures;
  for (const auto &engine : engine_names()) {
    if (std::find(c.description.engines.begin(), c.description.engines.end(), engine) == c.description.engines.end())
      continue;
    const fs::path file = fs::path(c.folder) / results_file(engine);
    if (!fs::exists(file)) {
      failures += (failures.empty() ? "" : "; ") + engine + ": no results";
      continue;
    }
    try {
      const Response r = read_response(file);
      const std::string status = completion_status(r, c.description.program);
      if (status != "complete")
        failures += (failures.empty() ? "" : "; ") + engine + ": " + status;
      rc.runs.push_back({engine_label(engine), with_interval_means(r)});
    } catch (const std::exception &e) {
      failures += (failures.empty() ? "" : "; ") + engine + ": " + e.what();
    }
  }
  if (code != ok)
    rc.failure = failures.empty() ? std::string(code == bad_input ? "refused" : "failed") + " (exit " +
                                      std::to_string(code) + "; the log says why)"
                                  : failures;
  return rc;
}

/// The report of the study (rank 0): every case's results as they are now.
void write_study_report_and_say(const Study &s, const std::vector<int> &codes)
{
  compare::StudyReportInput in;
  in.title = s.parameters.title.empty() ? "geocomp study: " + s.file : s.parameters.title;
  in.study_file = s.file;
  in.against = s.parameters.against;
  for (std::size_t k = 0; k < s.cases.size(); ++k)
    in.cases.push_back(report_case(s.cases[k], codes[k]));
  const compare::StudyReportOutcome out = compare::write_study_report(in, fs::path(s.output) / "report");
  log::info("study report: " + (out.dir / "index.html").string());
  if (!out.plots_made)
    log::info("  (" + out.message + ")");
  for (const auto &c : in.cases)
    if (!c.failure.empty())
      log::error("study: case " + c.name + " failed: " + c.failure);
}

int run_study(const Study &s, bool reuse)
{
  ensure_mpi();
  const bool root = rank_in(MPI_COMM_WORLD) == 0;
  const auto lock = lock_for_run(s.output, s.file, "study/output directory", MPI_COMM_WORLD);
  int written = 1;
  if (root) {
    try {
      write_case_files(s);
    } catch (const std::exception &e) {
      log::error(std::string("study: ") + e.what());
      written = 0;
    }
  }
  MPI_Bcast(&written, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!written)
    return run_failure;
  std::vector<CaseDescription> cases;
  for (const StudyCase &c : s.cases)
    cases.push_back(c.description);
  const std::vector<int> codes = pair_over_ranks(cases, reuse, "study");
  if (root)
    write_study_report_and_say(s, codes);
  return std::all_of(codes.begin(), codes.end(), [](int code) { return code == ok; }) ? ok : run_failure;
}
} // namespace

Command study_command()
{
  Command c;
  c.name = "study";
  c.summary = "run a study's cases as one job (mpirun -np N) and report them against one entry";
  c.usage = "usage: [mpirun -np N] geocomp study <study.prm> [--force] [--check] [--print-parameters]\n\n"
            "Reads the study file (a list of cases, or one case with an entry swept over values;\n"
            "docs/studies.md), checks every case it makes (any bad input: exit 2, nothing written),\n"
            "writes each as <output>/cases/<name>/<name>.prm, runs `pair` on each (reusing up-to-date\n"
            "results unless --force; case k on rank k mod N, as `sweep`), then writes\n"
            "<output>/report/index.html and study.json: every case's curves overlaid, and the peak\n"
            "stress, secant modulus, elastic limit, dilatancy angle and V_r against the study's\n"
            "'against' entry. Exit 1 if a case failed (the report says which). --check only reads\n"
            "and checks the study and its cases; --print-parameters prints the study file's entries.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {}, {"force", "check", "print-parameters"});
    if (a.has("print-parameters")) {
      std::cout << describe_study_parameters();
      return static_cast<int>(ok);
    }
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one study file");
    Study s;
    try {
      s = read_valid_study(a.positional[0]);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    if (a.has("check")) {
      std::cout << s.file << ": ok (" << s.cases.size() << " case(s), against " << s.parameters.against << ")\n";
      for (const StudyCase &c : s.cases)
        std::cout << "  " << c.name << ": " << s.parameters.against << " = " << c.x << ", engines "
                  << c.description.engines.size() << " -> " << c.folder << "\n";
      return static_cast<int>(ok);
    }
    try {
      return run_study(s, !a.has("force"));
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
  };
  return c;
}

} // namespace geocomp::cli
