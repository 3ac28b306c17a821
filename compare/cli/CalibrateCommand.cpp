// `geocomp calibrate <case>`: fit the continuum section to the case's target curves
// (compare/calibrate, docs/calibration.md), optionally verified on the FE cube.
#include "CaseValidation.h"
#include "Log.h"
#include "Commands.h"
#include "Engines.h"
#include "Mpi.h"
#include "OutputFolderLock.h"
#include "PairCalibration.h"
#include "TargetCases.h"

#include "common/ProgramRunner.h"
#include "compare/calibrate/Calibration.h"
#include "compare/calibrate/FitReport.h"
#include "compare/calibrate/Ladder.h"
#include "compare/calibrate/StartingValues.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace geocomp::cli {

namespace fs = std::filesystem;
using namespace geocomp::calibration;

namespace {
/// The FE cube with the calibrated section on each target's program, against the
/// material-point fit and the target: largest differences of q at the target's samples,
/// relative to the target's largest q (FitReport.h).
std::vector<Verification> verify_on_cube(const CaseDescription &c, const CalibrationResult &r,
                                         const std::vector<FitTarget> &targets, const fs::path &dir)
{
  const std::vector<ResidualQuantity> q_only = {{ResidualQuantity::Kind::Deviator, 1.0, "q"}};
  std::vector<Verification> out;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    CaseDescription cube_case = c;
    cube_case.continuum = r.calibrated;
    cube_case.program = targets[k].program;
    cube_case.specimen.isotropic_pressure = -targets[k].initial_stress;
    cube_case.output.fields = false;
    const auto t0 = std::chrono::steady_clock::now();
    auto engine = make_engine("continuum", cube_case, dir.string(), MPI_COMM_SELF);
    const Response cube = ProgramRunner(cube_case.program, *engine).run();
    Verification v;
    v.target = targets[k].name;
    v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    FitTarget target = targets[k];
    target.weight = 1.0;
    const std::size_t m = residual_count(target, 1);
    std::vector<double> to_cube(m), to_point(m);
    residuals(target, cube, q_only, to_cube.data());
    residuals(target, r.fitted[k], q_only, to_point.data());
    for (std::size_t i = 0; i < m; ++i) {
      v.cube_vs_point = std::max(v.cube_vs_point, std::abs(to_cube[i] - to_point[i]));
      v.cube_vs_target = std::max(v.cube_vs_target, std::abs(to_cube[i]));
      v.point_vs_target = std::max(v.point_vs_target, std::abs(to_point[i]));
    }
    out.push_back(v);
  }
  return out;
}
} // namespace

Command calibrate_command()
{
  Command cmd;
  cmd.name = "calibrate";
  cmd.summary = "fit the continuum parameters to target curves (e.g. DEM runs) with Ceres";
  cmd.usage = "usage: geocomp calibrate <case> [--output DIR] [--verify]\n\n"
              "Fits the free parameters of the case's continuum section (subsection calibration:\n"
              "targets, free parameters, bounds, weights) to the main-path curves of the target results\n"
              "files by least squares over the material point (Ceres, Levenberg-Marquardt), starting\n"
              "from closed-form estimates. Writes <output>/calibration/: the calibrated section\n"
              "(include it in case files), parameters.tsv, fit.json, index.html with the curves,\n"
              "standard errors, correlations and residuals. --verify reruns the calibrated model on\n"
              "the FE cube for each target's program and adds the differences from the material-point\n"
              "fit and from the target to the report. calibration/ladder fits each rung of the model\n"
              "ladder to the same curves and adds its residual, AIC and BIC (\"Model ladder\").\n"
              "A parameter the targets cannot identify is named and the command exits with 2.\n";
  cmd.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"output"}, {"verify"});
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    CaseDescription c;
    std::vector<FitTarget> targets;
    try {
      c = read_valid_case(a.positional[0], a.has("verify") ? std::vector<std::string>{"material-point", "continuum"}
                                                           : std::vector<std::string>{"material-point"});
      if (c.continuum.model == "nikolaevsky")
        throw CaseError(c.file, "continuum/model",
                        "calibrate fits the Mohr-Coulomb parameters (E, nu, cohesion, friction, dilatancy, also "
                        "behind drucker-prager): expected mohr-coulomb or drucker-prager, got nikolaevsky");
      if (c.calibration.targets.empty())
        throw CaseError(c.file, "calibration/targets", "expected at least one results file to fit");
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    const fs::path out = a.has("output") ? fs::path(a.get("output")) : fs::path(c.output.directory);
    const fs::path dir = out / "calibration";
    std::unique_ptr<OutputFolderLock> lock;
    try {
      lock = std::make_unique<OutputFolderLock>(out, c.file, a.has("output") ? "--output" : "output/directory");
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    try {
      if (std::any_of(c.calibration.targets.begin(), c.calibration.targets.end(), names_target_case)) {
        ensure_mpi();
        RunSettings settings;
        settings.comm = MPI_COMM_SELF;
        settings.command_line = "geocomp calibrate " + c.file;
        run_target_cases(c, settings); // their DEM runs, reused when up to date
      }
      targets = case_targets(c);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    } catch (const std::exception &e) {
      log::error(std::string("run failed: ") + e.what());
      return static_cast<int>(run_failure);
    }
    try {
      const StartingValues start = starting_values(c.continuum, targets, c.calibration);
      CalibrationResult r = calibrate(start.parameters, targets, c.calibration);
      r.notes.insert(r.notes.begin(), start.notes.begin(), start.notes.end());
      std::cout << calibration_summary(r);
      for (const auto &w : r.warnings)
        log::warning(c.file + ": calibration/free parameters: " + w);
      std::vector<Verification> verification;
      if (a.has("verify")) {
        ensure_mpi();
        verification = verify_on_cube(c, r, targets, dir);
        std::cout << "verification on the FE cube (max |q difference| / max q_target):\n";
        for (const auto &v : verification)
          std::cout << "  " << v.target << ": cube vs material point " << v.cube_vs_point << ", cube vs target "
                    << v.cube_vs_target << ", material point vs target " << v.point_vs_target << "\n";
      }
      std::vector<compare::LadderRung> ladder;
      if (!c.calibration.ladder.empty()) {
        ladder = run_ladder({&c.continuum, &targets, &c.calibration, nullptr});
        std::cout << ladder_summary(ladder);
      }
      write_fit_report(dir, c.calibration.output_file, r, targets, c.file, verification, ladder);
      std::cout << "calibrated section: " << (dir / c.calibration.output_file).string() << "\nreport: "
                << (dir / "index.html").string() << "\n";
      return static_cast<int>(ok);
    } catch (const CalibrationError &e) {
      log::error(c.file + ": parameter '" + e.parameter + "': " + e.what());
      return static_cast<int>(bad_input);
    } catch (const std::exception &e) {
      log::error(std::string("run failed: ") + e.what());
      return static_cast<int>(run_failure);
    }
  };
  return cmd;
}

} // namespace geocomp::cli
