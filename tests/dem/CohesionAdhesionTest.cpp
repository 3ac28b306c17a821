// S3 bonds: a cohesive bond breaks at its limit and never forms again (also across
// rebuilds and checkpoints); adhesion acts while delta > -delta*, ruptures beyond and
// forms again at the next contact; S3's anchor-spring friction with k_phi.
#include "dem/DemSystem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace geocomp::dem;

namespace {
constexpr double kR = 0.01, kKn = 1e5, kDelta0 = 1e-6, kV = 1e-3, kDt = 1e-5;
// Pair radius r_ij = 2R* = R for equal spheres.
constexpr double kRij = kR;

/// Sphere 0 fixed at the origin, sphere 1 (so heavy that its velocity stays what is set)
/// overlapping it by delta0 along x. Linear normal spring without damping.
DemSystem bonded_pair(const S3Bonding::Parameters& bonds)
{
  DemSystem sys;
  sys.set_contact_model(LinearCohesive(LinearNormal::with_stiffness(kKn, 1.0), LinearTangential::with_ratio(2.0 / 7.0),
                                       LinearRolling({0.0, 1.0}), S3Bonding(bonds)));
  sys.add_sphere(Vec3::Zero(), kR, 2650.0);
  sys.add_sphere(Vec3(2.0 * kR - kDelta0, 0, 0), kR, 1e15);
  sys.set_fixed(0, true);
  sys.set_time_step(kDt);
  return sys;
}

double overlap(const DemSystem& sys) { return 2.0 * kR - (sys.position(1) - sys.position(0)).norm(); }

/// Normal force on sphere 1 along +x (> 0 repulsive), 0 when no contact is reported.
double normal_force(const DemSystem& sys)
{
  const auto c = sys.contacts();
  return c.empty() ? 0.0 : c.front().force.x();
}

/// Moves sphere 1 with velocity v until its overlap crosses `target`, calling check(delta, F) each step.
template <class Check>
void move_until(DemSystem& sys, double v, double target, Check check)
{
  sys.set_velocity(1, Vec3(v, 0, 0));
  const bool apart = v > 0.0;
  while (apart ? overlap(sys) > target : overlap(sys) < target) {
    sys.step();
    check(overlap(sys), normal_force(sys));
  }
}
}  // namespace

TEST(Cohesion, BondBreaksAtItsLimitAndIsNeverRestored)
{
  S3Bonding::Parameters p;
  p.cohesion = 1e4;          // C_c [Pa]
  p.cohesion_modulus = 1e6;  // E_c [Pa]
  const double kc = p.cohesion_modulus * kRij, eps = kRij * p.cohesion / p.cohesion_modulus;  // S3 eq. (8)
  DemSystem sys = bonded_pair(p);
  double largest_pull = 0.0;
  bool broken = false;
  // Pull apart: the bond spring pulls back with E_c r_ij e until |e| = eps*, then nothing.
  move_until(sys, kV, -2.0 * eps, [&](double delta, double f) {
    const double e_n = kDelta0 - delta;
    if (e_n < eps - 2.0 * kV * kDt && !broken) {
      EXPECT_NEAR(f, kKn * std::max(delta, 0.0) - kc * e_n, 1e-9 * kc * eps);
      largest_pull = std::max(largest_pull, -f);
    } else if (e_n >= eps) {
      broken = true;
      EXPECT_EQ(f, 0.0);
    }
  });
  EXPECT_TRUE(broken);
  EXPECT_NEAR(largest_pull / (p.cohesion * kRij * kRij), 1.0, 1e-3);  // strength C_c r_ij^2
  // Back into contact and out again: only the repulsive spring, no bond.
  move_until(sys, -kV, 2.0 * kDelta0,
             [&](double delta, double f) { EXPECT_NEAR(f, kKn * std::max(delta, 0.0), 1e-12); });
  move_until(sys, kV, -0.5 * eps, [&](double delta, double f) { EXPECT_NEAR(f, kKn * std::max(delta, 0.0), 1e-12); });
  // Far away (the pair leaves the lists), through a checkpoint, and back: still broken.
  sys.set_position(1, Vec3(10.0 * kR, 0, 0));
  sys.step();
  ASSERT_EQ(sys.n_touching_pairs(), 0u);
  std::stringstream state;
  sys.write_state(state);
  DemSystem restored;
  restored.read_state(state);
  restored.set_position(1, Vec3(2.0 * kR - kDelta0, 0, 0));
  restored.step();
  ASSERT_EQ(restored.n_touching_pairs(), 1u);
  move_until(restored, kV, -0.5 * eps, [&](double, double f) { EXPECT_GE(f, 0.0); });
  // The same through exported contact state.
  DemSystem fresh = bonded_pair(p);
  fresh.import_contact_state(sys.export_contact_state());
  fresh.step();
  move_until(fresh, kV, -0.5 * eps, [&](double, double f) { EXPECT_GE(f, 0.0); });
  // A new pair at the same place does bond (the test above could fail).
  DemSystem control = bonded_pair(p);
  double pull = 0.0;
  move_until(control, kV, -0.5 * eps, [&](double, double f) { pull = std::max(pull, -f); });
  EXPECT_GT(pull, 0.4 * p.cohesion * kRij * kRij);
}

TEST(Adhesion, ActsWhileDeltaAboveMinusDeltaStarAndFormsAgainAtTheNextContact)
{
  S3Bonding::Parameters p;
  p.adhesion = 1e4;          // C_a [Pa]
  p.adhesion_modulus = 1e6;  // E_a [Pa]
  const double ka = p.adhesion_modulus * kRij, range = kRij * p.adhesion / p.adhesion_modulus;  // S3 eq. (7)
  DemSystem sys = bonded_pair(p);
  for (int cycle = 0; cycle < 2; ++cycle) {
    int pulling = 0;
    // Separation: F = k_n max(delta, 0) - E_a r_ij (delta* + delta) down to -delta*, then 0.
    move_until(sys, kV, -2.0 * range, [&](double delta, double f) {
      if (delta > -range) {
        EXPECT_NEAR(f, kKn * std::max(delta, 0.0) - ka * (range + delta), 1e-9 * ka * range);
        pulling += f < 0.0 ? 1 : 0;
      } else {
        EXPECT_EQ(f, 0.0);
      }
    });
    EXPECT_GT(pulling, 100);
    // Approach: no pull before the grains touch (the bridge needs a contact) ...
    move_until(sys, -kV, 0.0, [&](double delta, double f) {
      if (delta <= 0.0) EXPECT_EQ(f, 0.0);
    });
    // ... and at contact the adhesion is back.
    move_until(sys, -kV, kDelta0, [&](double delta, double f) {
      if (delta > 0.0) EXPECT_NEAR(f, kKn * delta - ka * (range + delta), 1e-9 * ka * range);
    });
  }
}

TEST(StickSlipFriction, AnchorSpringReachesCoulombAtDeltaStarThenShrinksToKPhi)
{
  // S3 eq. (9): F = mu F_n xi / delta*; at |xi| = delta* the spring is re-placed at k_phi delta*.
  const double mu = 0.5, fn = 10.0, dstar = 1e-4, v = 1e-3, dt = 1e-3;  // 1e-6 per step
  for (double k_phi : {0.0, 0.5, 1.0}) {
    const StickSlipTangential law({dstar, k_phi});
    ContactKinematics k;
    k.normal = Vec3::UnitZ();
    k.v_t = Vec3(v, 0, 0);
    k.overlap = 1e-5;
    k.dt = dt;
    k.mu = mu;
    NormalResponse nr;
    nr.force = fn;
    Vec3 xi = Vec3::Zero();
    int slips = 0;
    double previous = 0.0;
    for (int s = 1; s <= 350; ++s) {
      const TangentialResponse t = law.evaluate(k, nr, xi);
      const double f = -t.force.x();
      if (t.friction_loss > 0.0) {
        ++slips;
        EXPECT_NEAR(f, k_phi * mu * fn, 1e-9) << "k_phi " << k_phi;
      } else {
        EXPECT_NEAR(f, mu * fn * xi.x() / dstar, 1e-9);
        EXPECT_LT(f, mu * fn * (1.0 + 1e-9));
        EXPECT_GT(f, previous);  // loading between slips
      }
      previous = f;
    }
    // Slip every (1 - k_phi) delta* / (v dt) steps after the first delta* / (v dt).
    if (k_phi == 0.0) EXPECT_EQ(slips, 3);
    if (k_phi == 0.5) EXPECT_NEAR(slips, 6, 1);
    if (k_phi == 1.0) EXPECT_GT(slips, 200);
  }
}
