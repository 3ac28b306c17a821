// The kinetic model at one homogeneous point (no inertia) gives S1's strength-rate fits
// (14)-(15) within 10 % over 1e-3..1e3 1/s for both materials; the quasi-static model
// stays at the static strength.
#include "continuum/kinetic/HomogeneousUniaxial.h"

#include <gtest/gtest.h>

using namespace geocomp::kinetic;

TEST(S1PointRateSweep, KineticStrengthFollowsEq14AndEq15WithinTenPercent)
{
  for (const S1Material &m : {S1Material::concrete(), S1Material::sandstone()}) {
    const KineticNikolaevsky model(m, true);
    for (double rate = 1e-3; rate <= 1.0001e3; rate *= 10.0) {
      const auto c = run_uniaxial_point(model, LoadingMode::compression, rate, 1000);
      EXPECT_NEAR(c.peak_stress / m.compressive_strength / compressive_strength_factor(rate), 1.0, 0.10)
        << m.name << " compression " << rate;
      const auto t = run_uniaxial_point(model, LoadingMode::tension, rate, 1000);
      EXPECT_NEAR(t.peak_stress / m.tensile_strength / tensile_strength_factor(rate), 1.0, 0.10)
        << m.name << " tension " << rate;
    }
  }
}

TEST(S1PointRateSweep, QuasiStaticModelIgnoresTheRate)
{
  for (const S1Material &m : {S1Material::concrete(), S1Material::sandstone()}) {
    const KineticNikolaevsky model(m, false);
    for (double rate : {1e-3, 1e3}) {
      EXPECT_NEAR(run_uniaxial_point(model, LoadingMode::compression, rate, 1000).peak_stress,
                  m.compressive_strength, 2e-3 * m.compressive_strength);
      EXPECT_NEAR(run_uniaxial_point(model, LoadingMode::tension, rate, 1000).peak_stress, m.tensile_strength,
                  2e-3 * m.tensile_strength);
    }
  }
}
