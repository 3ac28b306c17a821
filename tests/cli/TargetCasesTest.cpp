// Calibration targets named by their case (compare/cli/TargetCases.h): the case's DEM runs
// into its own folder before the fit, is reused by the next run, and is the curve the fit
// sees (its program and pressure); a target case that would write into the calibrated
// case's own folder is refused before anything runs.
#include "compare/calibrate/FitTarget.h"
#include "compare/cli/EngineRun.h"
#include "compare/cli/PairCalibration.h"
#include "compare/cli/TargetCases.h"

#include "common/case/CaseError.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace {
using namespace geocomp;
namespace fs = std::filesystem;

/// A 250-sphere specimen under 1 MPa lateral pressure, compressed by 0.5 %.
std::string target_case(const fs::path &out)
{
  return R"(set engines = dem
set seed = 3
subsection specimen
  set particles = 250
  set isotropic pressure = 1e6
end
subsection program
  set sampling interval = 0.002
  subsection stage 1
    set x = stress -1e6
    set y = stress -1e6
    set z = rate -0.5
    set stop when = eps_zz <= -0.005
    set max duration = 1
  end
end
subsection output
  set directory = )" + out.string() + "\nend\n";
}

struct Folder {
  fs::path dir = fs::temp_directory_path() / ("geocomp-target-cases-" + std::to_string(::getpid()));
  Folder() { fs::create_directories(dir); }
  ~Folder() { fs::remove_all(dir); }
};

CaseDescription calibrated_case(const fs::path &file, const std::string &target, const fs::path &out)
{
  std::ofstream(file) << "set engines = material-point\nsubsection program\n  subsection stage 1\n"
                      << "    set z = rate -1\n    set stop when = eps_zz <= -0.01\n  end\nend\n"
                      << "subsection calibration\n  set targets = " << target
                      << "\n  set free parameters = E\nend\nsubsection output\n  set directory = " << out.string()
                      << "\nend\n";
  return read_case(file.string());
}

TEST(TargetCases, ACaseTargetRunsItsDemOnceIntoItsOwnFolderAndIsTheCurveTheFitSees)
{
  const Folder f;
  const fs::path target = f.dir / "target.prm", results = f.dir / "target-out" / "dem.h5";
  std::ofstream(target) << target_case(f.dir / "target-out");
  const CaseDescription c = calibrated_case(f.dir / "fit.prm", target.string(), f.dir / "fit-out");
  EXPECT_TRUE(cli::names_target_case(target.string()));
  EXPECT_FALSE(cli::names_target_case(results.string()));
  EXPECT_EQ(cli::target_results_file(target.string()), results.string());
  cli::validate_target_cases(c);
  EXPECT_FALSE(fs::exists(results)) << "validation runs nothing";

  cli::RunSettings settings;
  settings.comm = MPI_COMM_SELF;
  cli::run_target_cases(c, settings);
  ASSERT_TRUE(fs::is_regular_file(results));
  const auto made = fs::last_write_time(results);
  cli::run_target_cases(c, settings); // up to date: reused, not run again
  EXPECT_EQ(fs::last_write_time(results), made);

  const std::vector<calibration::FitTarget> targets = cli::case_targets(c);
  ASSERT_EQ(targets.size(), 1u);
  const CaseDescription t = read_case(target.string());
  EXPECT_EQ(targets[0].initial_stress, -t.specimen.isotropic_pressure);
  ASSERT_EQ(targets[0].program.stages.size(), 1u);
  EXPECT_EQ(targets[0].program.sample_interval, t.program.sample_interval);
}

TEST(TargetCases, ATargetCaseWritingIntoTheCalibratedCasesFolderIsRefusedNamingTheEntry)
{
  const Folder f;
  const fs::path target = f.dir / "target.prm";
  std::ofstream(target) << target_case(f.dir / "shared");
  const CaseDescription c = calibrated_case(f.dir / "fit.prm", target.string(), f.dir / "shared");
  try {
    cli::validate_target_cases(c);
    FAIL() << "not refused";
  } catch (const CaseError &e) {
    EXPECT_NE(std::string(e.what()).find("calibration/targets"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("output/directory of its own"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(f.dir / "shared"));
}
} // namespace
