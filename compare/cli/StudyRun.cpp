// run_study() and read_valid_study() (StudyRun.h): the body of `geocomp study` and of
// Python's geocomp.study.
#include "StudyRun.h"

#include "CaseValidation.h"
#include "Commands.h"
#include "Engines.h"
#include "Log.h"
#include "Mpi.h"
#include "OutputFolderLock.h"
#include "Pair.h"

#include "common/AtomicFile.h"
#include "common/ResponseFile.h"
#include "common/case/CaseError.h"

#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

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

bool StudyOutcome::complete() const
{
  return std::all_of(codes.begin(), codes.end(), [](int code) { return code == ok; });
}

namespace {
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
void write_study_report_and_say(const Study &s, StudyOutcome &out)
{
  compare::StudyReportInput &in = out.report;
  in.title = s.parameters.title.empty() ? "geocomp study: " + s.file : s.parameters.title;
  in.study_file = s.file;
  in.against = s.parameters.against;
  for (std::size_t k = 0; k < s.cases.size(); ++k)
    in.cases.push_back(report_case(s.cases[k], out.codes[k]));
  out.written = compare::write_study_report(in, fs::path(s.output) / "report");
  log::info("study report: " + (out.written.dir / "index.html").string());
  if (!out.written.plots_made)
    log::info("  (" + out.written.message + ")");
  for (const auto &c : in.cases)
    if (!c.failure.empty())
      log::error("study: case " + c.name + " failed: " + c.failure);
}
} // namespace

StudyOutcome run_study(const Study &s, const RunSettings &settings, const CaseProgress &progress)
{
  ensure_mpi();
  const bool root = rank_in(MPI_COMM_WORLD) == 0;
  const auto lock = lock_for_run(s.output, s.file, "study/output directory", MPI_COMM_WORLD);
  StudyOutcome out;
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
  if (!written) {
    out.codes.assign(s.cases.size(), run_failure);
    return out;
  }
  std::vector<CaseDescription> cases;
  for (const StudyCase &c : s.cases)
    cases.push_back(c.description);
  out.codes = pair_over_ranks(cases, settings, "study", progress);
  if (root)
    write_study_report_and_say(s, out);
  return out;
}

} // namespace geocomp::cli
