// The Rudnicki-Rice prediction evaluated along a material-point path agrees with the
// acoustic-tensor onset of the same path when the model is the Drucker-Prager cone the
// prediction is built on: then the theory is exact and only sampling separates the two.
#include "common/ProgramRunner.h"
#include "compare/LocalizationOnsets.h"
#include "continuum/driver/MaterialPointEngine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp;

namespace {
LoadingProgram isochoric(double rate, double interval)
{
  LoadingProgram p;
  p.sample_interval = interval;
  Stage s;
  s.name = "shear";
  s.isochoric = true;
  s.lambda = 0.0;
  s.isochoric_rate = rate;
  s.stop_any = {parse_condition("gamma_max >= 0.08", "test")};
  s.max_duration = 100;
  p.stages = {s};
  return p;
}
} // namespace

TEST(RudnickiRiceAlongPath, MatchesAcousticTensorOnsetOfDruckerPragerPath)
{
  continuum::MaterialParameters m;
  m.model = "drucker-prager";
  m.mohr_coulomb.youngs_modulus = 300e6;
  m.mohr_coulomb.poisson_ratio = 0.25;
  m.mohr_coulomb.cohesion = continuum::PiecewiseLinear(std::vector<std::pair<double, double>>{{0.0, 50e3}, {0.01, 50e3}, {0.05, 5e3}});
  m.mohr_coulomb.friction_angle = continuum::PiecewiseLinear(std::vector<std::pair<double, double>>{{0.0, 25 * M_PI / 180}, {0.05, 25 * M_PI / 180}});
  m.mohr_coulomb.dilatancy_angle = continuum::PiecewiseLinear(std::vector<std::pair<double, double>>{{0.0, 5 * M_PI / 180}, {0.05, 5 * M_PI / 180}});
  m.drucker_prager_matching = continuum::DruckerPragerMatching::outer_cone;
  continuum::MaterialPointParameters mp;
  mp.initial_stress = -2e6;
  continuum::MaterialPointEngine engine(m, mp);
  const LoadingProgram program = isochoric(0.1, 0.002);
  const Response r = ProgramRunner(program, engine).run();
  const auto kind = compare::CurveKind::ShearIsochoric;
  const compare::OnsetEstimate theory =
    compare::rudnicki_rice_onset(r, m.mohr_coulomb, m.drucker_prager_matching, kind);
  const compare::OnsetEstimate scan = compare::acoustic_tensor_onset(r, "material point", kind);
  ASSERT_TRUE(theory.found) << theory.note;
  ASSERT_TRUE(scan.found) << scan.note;
  const double per_sample = 2 * 0.1 * 0.002 * 1.05; // gamma_max per sample, with margin
  EXPECT_NEAR(theory.strain, scan.strain, per_sample);
  EXPECT_NEAR(theory.angle_deg, scan.angle_deg, 1.0);
}

TEST(RudnickiRiceAlongPath, NoOnsetWhileHardeningStaysAboveCritical)
{
  // Associated (psi = phi), strongly hardening cohesion: h >> h_cr, no localization.
  continuum::MaterialParameters m;
  m.model = "drucker-prager";
  m.mohr_coulomb.youngs_modulus = 300e6;
  m.mohr_coulomb.poisson_ratio = 0.25;
  m.mohr_coulomb.cohesion = continuum::PiecewiseLinear(std::vector<std::pair<double, double>>{{0.0, 50e3}, {1.0, 50e3 + 50e6}});
  m.mohr_coulomb.friction_angle = continuum::PiecewiseLinear(20 * M_PI / 180);
  m.mohr_coulomb.dilatancy_angle = continuum::PiecewiseLinear(20 * M_PI / 180);
  continuum::MaterialPointParameters mp;
  mp.initial_stress = -2e6;
  continuum::MaterialPointEngine engine(m, mp);
  const Response r = ProgramRunner(isochoric(0.1, 0.005), engine).run();
  const auto kind = compare::CurveKind::ShearIsochoric;
  EXPECT_FALSE(compare::rudnicki_rice_onset(r, m.mohr_coulomb, m.drucker_prager_matching, kind).found);
  EXPECT_FALSE(compare::acoustic_tensor_onset(r, "material point", kind).found);
}
