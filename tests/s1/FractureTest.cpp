// S1 eq. (6): the Drucker-Prager fracture surface passes through sigma_c in uniaxial
// compression and sigma_t in uniaxial tension; eqs. (8)-(11): with the kinetic extension a
// point at a constant elastic stress rate fractures after T_f(epsdot) of eq. (9), at
// sigma_st k(epsdot); after fracture the point carries no stress in plane stress.
#include "continuum/kinetic/FractureCriterion.h"
#include "continuum/kinetic/HomogeneousUniaxial.h"

#include <gtest/gtest.h>

using namespace geocomp::kinetic;

namespace {
Vector6 uniaxial(double sigma)
{
  Vector6 s = Vector6::Zero();
  s(1) = sigma;
  return s;
}
// Elastic up to fracture (yield just below the strength, near-rigid hardening), so that the
// stress rises at E epsdot as S1 eq. (9) assumes and the test isolates eqs. (8)-(11).
S1Material elastic_until_fracture(S1Material m)
{
  m.yield_stress = 0.999 * m.compressive_strength;
  m.plastic_strain_at_strength = 1e-12;
  m.tensile_strength = m.compressive_strength;
  return m;
}
} // namespace

TEST(S1Fracture, StaticCriterionPassesThroughUniaxialStrengths)
{
  for (const S1Material &m : {S1Material::concrete(), S1Material::sandstone()}) {
    const FractureCriterion f(m);
    const double a = m.compressive_strength / m.tensile_strength;
    EXPECT_NEAR(drucker_prager_parameter(uniaxial(-m.compressive_strength), a), m.compressive_strength, 1e-6);
    EXPECT_NEAR(drucker_prager_parameter(uniaxial(m.tensile_strength), a), m.compressive_strength, 1e-6);
    EXPECT_TRUE(f.static_criterion_met(uniaxial(-1.0001 * m.compressive_strength)));
    EXPECT_FALSE(f.static_criterion_met(uniaxial(-0.9999 * m.compressive_strength)));
    EXPECT_TRUE(f.static_criterion_met(uniaxial(1.0001 * m.tensile_strength)));
    EXPECT_FALSE(f.static_criterion_met(uniaxial(0.9999 * m.tensile_strength)));
  }
}

TEST(S1Fracture, DynamicCriterionIsUniaxialDynamicStrengthAtElapsedTime)
{
  const S1Material m = S1Material::sandstone();
  const FractureCriterion f(m);
  const double T = f.compression().fracture_time(50.0); // the incubation period at 50 1/s
  const double sc = m.compressive_strength * compressive_strength_factor(50.0);
  EXPECT_TRUE(f.dynamic_criterion_met(uniaxial(-1.001 * sc), T));
  EXPECT_FALSE(f.dynamic_criterion_met(uniaxial(-0.999 * sc), T));
  const double Tt = f.tension().fracture_time(50.0);
  const double st = m.tensile_strength * tensile_strength_factor(50.0);
  EXPECT_TRUE(f.dynamic_criterion_met(uniaxial(1.001 * st), Tt));
  EXPECT_FALSE(f.dynamic_criterion_met(uniaxial(0.999 * st), Tt));
}

TEST(S1Fracture, ElasticPointFracturesAfterIncubationAtEq14Strength)
{
  const KineticNikolaevsky model(elastic_until_fracture(S1Material::sandstone()), true);
  // Rates up to 1 1/s: above that the near-rigid hardening of this artificial material
  // interacts with the lateral stress solve (open issue, docs/s1-kinetic-model.md).
  for (double rate : {1e-2, 1e-1, 1.0}) {
    const UniaxialPointResult r = run_uniaxial_point(model, LoadingMode::compression, rate, 4000);
    const double sc = model.material().compressive_strength;
    EXPECT_NEAR(r.peak_stress / sc, compressive_strength_factor(rate), 2e-3 * compressive_strength_factor(rate))
      << rate;
    // Fracture at t0 + T_f, t0 = sigma_c / (E epsdot) (S1 eq. (9)).
    const double t0 = sc / (model.material().youngs_modulus * rate);
    EXPECT_NEAR(r.fracture_time, t0 + model.fracture().compression().fracture_time(rate), 2e-3 * r.fracture_time);
  }
}

TEST(S1Fracture, FracturedPointLosesAllStressInPlaneStress)
{
  const KineticNikolaevsky model(S1Material::concrete(), false);
  const auto r = run_uniaxial_point(model, LoadingMode::tension, 1.0, 500, 1);
  ASSERT_GT(r.fracture_time, 0.0);
  EXPECT_NEAR(r.peak_stress, model.material().tensile_strength, 2e-3 * model.material().tensile_strength);
  EXPECT_EQ(r.curve.back().second, 0.0);
}
