// S1 eq. (13): with the kinetic extension a held overstress relaxes linearly and reaches
// the yield surface after exactly T_r(Phi) of eqs. (19)-(21); without it the return is
// immediate.
#include "continuum/kinetic/KineticNikolaevsky.h"

#include <gtest/gtest.h>

using namespace geocomp::kinetic;

namespace {
// Sandstone without hardening, so that the surface stays put while the stress relaxes, and
// without dilatancy, so that J1 stays zero in shear and Phi does not depend on the
// rate-dependent omega of S1 eq. (23).
S1Material perfectly_plastic()
{
  S1Material m = S1Material::sandstone();
  m.plastic_strain_at_strength = 1e6;
  m.dilatancy = 0.0;
  return m;
}
Vector6 shear_strain(double gamma)
{
  Vector6 e = Vector6::Zero();
  e(0) = 0.5 * gamma;
  e(1) = -0.5 * gamma;
  return e;
}
} // namespace

TEST(S1Relaxation, HeldOverstressReachesSurfaceLinearlyInRelaxationTime)
{
  const KineticNikolaevsky model(perfectly_plastic(), true);
  const double Y = model.static_cohesion(0.0);
  // Pure shear overstress Phi = 1.5 Y applied in one very short step.
  const double G = model.elasticity().shear_modulus();
  KineticState s = model.step(model.initial_state(), shear_strain(1.5 * Y / G), 1e-15);
  const double phi0 = model.yield_function(s);
  ASSERT_NEAR(phi0, 1.5 * Y, 1e-6 * Y);
  const double Tr = s.relaxation_time;
  EXPECT_NEAR(Tr, model.relaxation().relaxation_time(1.5), 1e-12 * Tr); // S1 eqs. (19)-(21)
  const int n = 100;
  const double dt = Tr / n;
  for (int i = 1; i <= n + 10; ++i) {
    s = model.step(s, Vector6::Zero(), dt);
    const double expected = i < n ? Y + (phi0 - Y) * (1.0 - double(i) / n) : Y; // S1 eq. (13)
    ASSERT_NEAR(model.yield_function(s), expected, 1e-6 * Y) << "step " << i;
  }
  EXPECT_FALSE(s.relaxing);
}

TEST(S1Relaxation, QuasiStaticModelReturnsInOneStep)
{
  const KineticNikolaevsky model(perfectly_plastic(), false);
  const double Y = model.static_cohesion(0.0);
  const double G = model.elasticity().shear_modulus();
  const KineticState s = model.step(model.initial_state(), shear_strain(1.5 * Y / G), 1e-15);
  EXPECT_NEAR(model.yield_function(s), Y, 1e-9 * Y);
}

TEST(S1Relaxation, RelaxationTimeFallsAsTheDynamicYieldRises)
{
  const KineticNikolaevsky model(S1Material::sandstone(), true);
  const auto &r = model.relaxation();
  double previous = r.relaxation_time(1.0);
  for (double y = 1.1; y < r.maximum_cohesion_ratio(); y += 0.1) {
    EXPECT_LT(r.relaxation_time(y), previous) << y;
    previous = r.relaxation_time(y);
  }
  EXPECT_EQ(r.relaxation_time(r.maximum_cohesion_ratio() + 0.1), 0.0);
}
