// See TargetCases.h: calibration targets named by their case, run before the fit.
#include "TargetCases.h"
#include "CaseValidation.h"
#include "Engines.h"
#include "Log.h"
#include "Mpi.h"
#include "OutputFolderLock.h"

#include "common/case/CaseError.h"

#include <filesystem>

namespace geocomp::cli {

namespace fs = std::filesystem;

bool names_target_case(const std::string &target)
{
  const std::string ext = fs::path(target).extension().string();
  return ext == ".prm" || ext == ".json";
}

std::string target_results_file(const std::string &target)
{
  if (!names_target_case(target))
    return target;
  return (fs::path(read_case(target).output.directory) / results_file("dem")).string();
}

void validate_target_cases(const CaseDescription &c)
{
  for (const std::string &f : c.calibration.targets) {
    if (!names_target_case(f))
      continue;
    const CaseDescription target = read_case(f); // CaseError naming the target's own file
    validate_engine("dem", target);
    if (fs::weakly_canonical(target.output.directory) == fs::weakly_canonical(c.output.directory))
      throw CaseError(c.file, "calibration/targets",
                      "the target case '" + f + "' writes into this case's output folder '" + c.output.directory +
                        "': expected a target case with an output/directory of its own");
  }
}

void run_target_cases(const CaseDescription &c, const RunSettings &settings)
{
  for (const std::string &f : c.calibration.targets) {
    if (!names_target_case(f))
      continue;
    const CaseDescription target = read_case(f);
    const OutputFolderLock lock(target.output.directory, target.file, "output/directory");
    run_engine("dem", target, target.output.directory, settings);
    if (rank_in(settings.comm) == 0)
      log::info("calibration target " + f + ": " + (fs::path(target.output.directory) / results_file("dem")).string());
  }
}

} // namespace geocomp::cli
