// The held-out curve of a calibrated pair (compare/cli/PairCalibration.h): a "DEM" curve made
// by the material point with known parameters is predicted to round-off by the section that
// made it, and visibly missed by a section whose peak friction is 4 degrees lower.
#include "common/ProgramRunner.h"
#include "compare/cli/Engines.h"
#include "compare/cli/PairCalibration.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace {
using namespace geocomp;

const char *const held_out_case = R"(set engines = dem, material-point
subsection specimen
  set isotropic pressure = 2e5
end
subsection continuum
  set model = mohr-coulomb
  set youngs modulus = 80e6
  set poisson ratio = 0.3
  set cohesion = 0:30e3
  set friction angle = 0:20, 0.02:32, 0.08:27
  set dilatancy angle = 0:0, 0.02:8
end
subsection program
  set sampling interval = 0.0015
  subsection stage 1
    set x = stress -2e5
    set y = stress -2e5
    set z = rate -1
    set stop when = eps_zz <= -0.06
    set max duration = 1
  end
end
subsection calibration
  set targets = elsewhere.h5
  set pair continuum = calibrated
  set pair dem = held out
end
)";

TEST(CalibratedPair, AHeldOutCurveMadeByTheCalibratedSectionIsPredictedToRoundOffAndAnotherSectionMissesIt)
{
  const CaseDescription c = parse_case(held_out_case, "held-out.prm");
  const Response truth = ProgramRunner(c.program, *cli::make_engine("material-point", c, "")).run();
  const auto dir = std::filesystem::temp_directory_path() / "geocomp-held-out-none"; // no fit.json there
  const auto same = cli::calibration_curves(c, c, &truth, dir);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].role, "predicted");
  EXPECT_LT(same[0].rms_q, 1e-12);
  EXPECT_LT(same[0].rms_p, 1e-12);
  EXPECT_LT(same[0].rms_eps_v, 1e-12);
  const CaseDescription lower =
    parse_case(std::regex_replace(held_out_case, std::regex("0.02:32"), "0.02:28"), "held-out.prm");
  const auto other = cli::calibration_curves(c, lower, &truth, dir);
  ASSERT_EQ(other.size(), 1u);
  EXPECT_GT(other[0].rms_q, 0.01) << "phi_peak 28 against 32 degrees: the deviator falls visibly short";
  std::printf("[held out] rms q: same section %.3g, phi_peak 4 degrees lower %.3g\n", same[0].rms_q, other[0].rms_q);
}
} // namespace
