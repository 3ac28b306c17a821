// One validation path: `geocomp check` accepts a case exactly when every engine it names
// accepts it. For every case in cases/ and tests/bad_cases, check's exit code is set
// against the engines built from the case the way the command line builds them - the
// material point and the FE cube constructed (their constructors' own checks included),
// the DEM's specimen checked as prepare_specimen() checks it before the first step (the
// preparation itself, minutes of DEM time per case, is left out).
#include "compare/cli/CaseValidation.h"
#include "compare/cli/Engines.h"
#include "compare/cli/PairCalibration.h"
#include "dem/program/DemEngine.h"
#include "dem/program/SpecimenPreparation.h"
#include "tests/common/CommandRun.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace {
fs::path source_dir() { return fs::path(std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : "."); }

/// Case files in the case-file format (S1's rate sweeps, S2's crush and S4's shear-box
/// files have formats and checkers of their own).
std::vector<fs::path> case_files()
{
  std::vector<fs::path> out;
  for (const auto &e : fs::recursive_directory_iterator(source_dir() / "cases")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".prm" && e.path().extension() != ".json")
      continue;
    std::stringstream text;
    text << std::ifstream(e.path()).rdbuf();
    const bool other_format = (name.rfind("s1_", 0) == 0 && text.str().find("subsection program") == std::string::npos) ||
                              name.rfind("s2_", 0) == 0 || name.rfind("s4_", 0) == 0 ||
                              e.path().parent_path().filename() == "studies";
    if (!other_format)
      out.push_back(fs::absolute(e.path()));
  }
  for (const auto &e : fs::directory_iterator(source_dir() / "tests/bad_cases"))
    if (e.is_regular_file() && e.path().filename() != "expected.txt")
      out.push_back(fs::absolute(e.path()));
  std::sort(out.begin(), out.end());
  return out;
}

/// Why the engines of the case refuse it, or "" when they all accept it.
std::string engines_refusal(const fs::path &file, const fs::path &scratch)
{
  try {
    const geocomp::CaseDescription c = geocomp::read_case(file.string());
    for (const std::string &engine : c.engines) {
      if (engine == "dem") {
        geocomp::dem::check_specimen(c);
        geocomp::dem::DemEngineParameters::from_case(c.dem);
      } else if (engine == "liggghts") { // runs outside this process: its exporter's checks
        geocomp::cli::validate_engine(engine, c);
      } else {
        geocomp::cli::make_engine(engine, c, scratch.string(), MPI_COMM_SELF);
      }
    }
    geocomp::cli::validate_pair_calibration(c); // targets and scatter files, as `pair` needs them
  } catch (const std::exception &e) {
    const std::string what = e.what();
    return what.empty() ? "refused" : what;
  }
  return "";
}
} // namespace

TEST(OneValidationPath, CheckAcceptsExactlyTheCasesEveryEngineTheyNameAccepts)
{
  // Store files in the cases are named relative to the repository root.
  fs::current_path(source_dir());
  const fs::path scratch = fs::temp_directory_path() / ("geocomp-agreement-" + std::to_string(::getpid()));
  int accepted = 0, refused = 0;
  for (const fs::path &file : case_files()) {
    const auto check = geocomp::test::run_program({GEOCOMP_EXE, "check", file.string()}, source_dir(), 60.0);
    ASSERT_TRUE(check.code == 0 || check.code == 2) << file << ": " << check.err;
    fs::create_directories(scratch);
    const std::string refusal = engines_refusal(file, scratch);
    fs::remove_all(scratch);
    EXPECT_EQ(check.code == 0, refusal.empty())
      << file << "\n  check: exit " << check.code << " " << check.err << "  engines: " << (refusal.empty() ? "accept" : refusal);
    (check.code == 0 ? accepted : refused) += 1;
  }
  // Both kinds are there: the shipped cases check accepts, the bad cases it refuses.
  EXPECT_GE(accepted, 20);
  EXPECT_GE(refused, 50);
}
