// S1 eqs. (1)-(5): Wilkins' correction lands on the Mises-Schleicher surface with the
// dilatancy ratio of the Nikolaevsky flow rule, I1^p = 2 Lambda sqrt(I2^p).
#include "continuum/kinetic/WilkinsCorrection.h"
#include "continuum/kinetic/S1Material.h"
#include "continuum/models/IsotropicElasticity.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::kinetic;
using geocomp::continuum::IsotropicElasticity;
using geocomp::continuum::mandel_identity;

namespace {
NikolaevskyConstants constants(const S1Material &m)
{
  return {m.shear_modulus(), m.bulk_modulus(), m.omega(), m.dilatancy};
}
// A stress well outside the surface, compressive and sheared, not axisymmetric.
Vector6 trial_stress()
{
  Vector6 s;
  s << -120e6, -30e6, -8e6, 18e6, -10e6, 14e6;
  return s;
}
} // namespace

TEST(S1Wilkins, CorrectionLandsOnYieldSurfaceWithDilatancyRatioOfEq2)
{
  const S1Material m = S1Material::sandstone(); // Lambda = 0.36
  const NikolaevskyConstants c = constants(m);
  const IsotropicElasticity el(m.youngs_modulus, m.poisson_ratio);
  const Vector6 trial = trial_stress();
  const double Y = m.static_cohesion();
  const double phi = c.yield_function(trial);
  ASSERT_GT(phi, 1.5 * Y);
  const WilkinsResult w = wilkins_correction(trial, phi - Y, c);
  ASSERT_FALSE(w.apex);
  EXPECT_NEAR(c.yield_function(w.stress), Y, 1e-9 * Y);
  // The plastic strain of the correction, from elasticity alone: d eps^p = -S : (sigma' - sigma_tr).
  const Vector6 d_eps_p = -el.compliance() * (w.stress - trial);
  const double I1 = d_eps_p(0) + d_eps_p(1) + d_eps_p(2);
  const Vector6 e = d_eps_p - I1 / 3.0 * mandel_identity();
  const double I2 = 0.5 * e.squaredNorm();
  EXPECT_NEAR(I1, 2.0 * m.dilatancy * std::sqrt(I2), 1e-9 * std::abs(I1)); // S1 eq. (2)
  EXPECT_GT(I1, 0.0);                                                      // dilatant
  EXPECT_NEAR(w.plastic_shear, 2.0 * std::sqrt(I2), 1e-12);
}

TEST(S1Wilkins, CorrectedInvariantsMatchDerivedEq5AndKeepDeviatorDirection)
{
  const S1Material m = S1Material::sandstone();
  const NikolaevskyConstants c = constants(m);
  const Vector6 trial = trial_stress();
  const Invariants before = invariants(trial);
  const double delta_phi = 0.3 * (c.yield_function(trial) - m.static_cohesion());
  const WilkinsResult w = wilkins_correction(trial, delta_phi, c);
  const Invariants after = invariants(w.stress);
  const double den = c.shear_modulus + 3.0 * c.bulk_modulus * c.dilatancy * c.omega;
  EXPECT_NEAR(after.tau, before.tau - c.shear_modulus * delta_phi / den, 1e-9 * before.tau);
  EXPECT_NEAR(after.J1, before.J1 - 3.0 * c.bulk_modulus * c.dilatancy * delta_phi / den, 1e-9 * std::abs(before.J1));
  // S1 eq. (4): the deviator is scaled, not rotated.
  EXPECT_NEAR(after.deviator.normalized().dot(before.deviator.normalized()), 1.0, 1e-14);
  EXPECT_NEAR(c.yield_function(w.stress), c.yield_function(trial) - delta_phi, 1e-9 * delta_phi);
}

TEST(S1Wilkins, WithoutDilatancyOnlyTheDeviatorChanges)
{
  const S1Material m = S1Material::concrete(); // Lambda = 0: classic Wilkins scaling
  const NikolaevskyConstants c = constants(m);
  const Vector6 trial = trial_stress();
  const WilkinsResult w = wilkins_correction(trial, c.yield_function(trial) - m.static_cohesion(), c);
  EXPECT_NEAR(invariants(w.stress).J1, invariants(trial).J1, 1e-6);
  EXPECT_NEAR(c.yield_function(w.stress), m.static_cohesion(), 1e-9 * m.static_cohesion());
  EXPECT_DOUBLE_EQ(w.plastic_volumetric, 0.0);
}

TEST(S1Wilkins, ExhaustedDeviatorReturnsToTheApex)
{
  const S1Material m = S1Material::sandstone();
  const NikolaevskyConstants c = constants(m);
  Vector6 trial = Vector6::Zero();
  trial << 60e6, 58e6, 57e6, 0, 0, 1e6; // strong hydrostatic tension, little shear
  const double Y = m.static_cohesion();
  const WilkinsResult w = wilkins_correction(trial, c.yield_function(trial) - Y, c);
  EXPECT_TRUE(w.apex);
  EXPECT_NEAR(invariants(w.stress).tau, 0.0, 1e-6);
  EXPECT_NEAR(c.omega * invariants(w.stress).J1, Y, 1e-9 * Y);
}
