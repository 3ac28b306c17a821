// Contact-law properties: objectivity of the tangential spring, one law for pairs and
// walls, Mindlin stiffness, time-step estimates.
#include "dem/ContactKinematics.h"
#include "dem/ContactLaw.h"
#include "dem/DemSystem.h"
#include "dem/TimeStep.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::dem;

namespace {

/// Loads a pair tangentially below mu F_n, then turns it rigidly by 90 degrees about
/// `axis` in n_steps steps, evaluating the law from exact positions and rigid-body
/// velocities. Returns the largest relative drifts of |F_t| and F_n and of F_t . n.
template <class Law>
void check_rigid_rotation(const Law& law, const Vec3& axis_in, double* dft, double* dfn, double* normal_part,
                          double* direction_error)
{
  const double R = 0.01, m = 0.011, delta = 1e-4, dt = 1e-6;
  const Vec3 c = Vec3(0.3, -0.2, 0.1);
  const Vec3 x0i = c - Vec3(R - 0.5 * delta, 0, 0), x0j = c + Vec3(R - 0.5 * delta, 0, 0);
  Vec3 shear = Vec3::Zero();
  ContactKinematics k;
  // Loading: j slides along +y relative to i for 20 steps at small speed.
  ContactForce f{};
  for (int s = 0; s < 20; ++s) {
    sphere_sphere_kinematics(k, x0j - x0i, (x0j - x0i).norm(), R, R, Vec3::Zero(), Vec3(0, 1e-3, 0),
                             Vec3::Zero(), Vec3::Zero(), 1.0 / m, 1.0 / m);
    k.dt = dt;
    k.mu = 0.5;
    f = law.evaluate(k, shear);
  }
  const double ft0 = f.tangential.norm(), fn0 = f.normal;
  const Vec3 dir0 = f.tangential / ft0;
  ASSERT_GT(ft0, 0.0);
  ASSERT_LT(ft0, 0.5 * fn0);  // sticking
  const Vec3 axis = axis_in.normalized();
  const int n_steps = 10000;
  const double omega = (M_PI / 2) / (n_steps * dt);
  *dft = *dfn = *normal_part = 0.0;
  for (int s = 1; s <= n_steps; ++s) {
    const Eigen::AngleAxisd rot(omega * dt * s, axis);
    const Vec3 xi = c + rot * (x0i - c), xj = c + rot * (x0j - c);
    const Vec3 W = omega * axis;
    const Vec3 vi = W.cross(xi - c), vj = W.cross(xj - c);
    sphere_sphere_kinematics(k, xj - xi, (xj - xi).norm(), R, R, vi, vj, W, W, 1.0 / m, 1.0 / m);
    k.overlap_old = delta;
    k.dt = dt;
    k.mu = 0.5;
    f = law.evaluate(k, shear);
    *dft = std::max(*dft, std::abs(f.tangential.norm() - ft0) / ft0);
    *dfn = std::max(*dfn, std::abs(f.normal - fn0) / fn0);
    *normal_part = std::max(*normal_part, std::abs(f.tangential.dot(k.normal)) / ft0);
  }
  const Eigen::AngleAxisd rot(M_PI / 2, axis);
  *direction_error = ((rot * dir0) - f.tangential.normalized()).norm();
}

}  // namespace

TEST(RigidRotation, LoadedLinearPairKeepsItsForces)
{
  const auto law = test::linear_law(1e5, 0.5);
  for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1, 2, 3)}) {
    double dft, dfn, np, dir;
    check_rigid_rotation(law, axis, &dft, &dfn, &np, &dir);
    EXPECT_LT(dft, 1e-10) << axis.transpose();
    EXPECT_LT(dfn, 1e-10) << axis.transpose();
    EXPECT_LT(np, 1e-10) << axis.transpose();
    EXPECT_LT(dir, 1e-3) << axis.transpose();  // the spring turned with the pair
  }
}

TEST(RigidRotation, LoadedHertzMindlinPairKeepsItsForces)
{
  const HertzMindlin law(HertzNormal({7e10, 0.25, HertzNormal::Damping::restitution, 0.5, 0.0, true}),
                         MindlinTangential({7e10, 0.25, 1.0}));
  for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(1, 2, 3)}) {
    double dft, dfn, np, dir;
    check_rigid_rotation(law, axis, &dft, &dfn, &np, &dir);
    // Mindlin's unloading rescale k_t(delta)/k_t(delta_old) acts on the round-off
    // fluctuations of delta (~1e-13 relative per step) and only ever shrinks the spring:
    // over 1e4 steps that is ~1e-9, not a frame error.
    EXPECT_LT(dft, 1e-8) << axis.transpose();
    EXPECT_LT(dfn, 1e-10) << axis.transpose();
    EXPECT_LT(np, 1e-10) << axis.transpose();
    EXPECT_LT(dir, 1e-3) << axis.transpose();
  }
}

TEST(SphereWall, SameForceAsSphereOnHugeFixedSphere)
{
  // The wall is the limit of a sphere of infinite radius and mass: same overlap, same
  // relative motion, same force and torque on the particle (to the O(R/R_big) limit).
  const double R = 0.01, R_big = 1e5 * R, delta = 2e-5;
  const Vec3 v(0.02, -0.01, -0.05), w(3.0, -1.0, 2.0);
  auto build = [&](DemSystem& sys, const ContactModel& law, bool wall) {
    sys.set_contact_model(law);
    sys.set_friction(0.3);
    sys.add_sphere(Vec3(0, 0, R - delta), R, 2650.0, v, w);
    if (wall) {
      PlaneWall p;
      p.normal = Vec3::UnitZ();
      p.mu = 0.3;
      sys.add_wall(p);
    } else {
      const ParticleId b = sys.add_sphere(Vec3(0, 0, -R_big), R_big, 2650.0);
      sys.set_fixed(b, true);
    }
    sys.set_time_step(1e-7);
  };
  LinearNormal::Parameters s0;
  s0.stiffness_input = LinearNormal::Stiffness::from_impact_velocity;
  s0.youngs_modulus = 1e9;
  s0.poisson_ratio = 0.3;
  s0.impact_velocity = 1.0;
  s0.restitution = 0.4;
  const ContactModel laws[] = {
    test::linear_law(1e5, 0.5),
    LinearSpringDashpot(LinearNormal(s0), LinearTangential::with_ratio(1.0)),
    HertzMindlin(HertzNormal({7e10, 0.25, HertzNormal::Damping::restitution, 0.5, 0.0, true}),
                 MindlinTangential({7e10, 0.25, 0.5}))};
  for (const ContactModel& law : laws) {
    DemSystem a, b;
    build(a, law, true);
    build(b, law, false);
    for (int s = 0; s < 5; ++s) {
      a.step();
      b.step();
    }
    const Vec3 fa = a.force(0), fb = b.force(0), ta = a.torque(0), tb = b.torque(0);
    ASSERT_GT(fa.norm(), 0.0);
    EXPECT_LT((fa - fb).norm() / fa.norm(), 2e-5) << fa.transpose() << " vs " << fb.transpose();
    EXPECT_LT((ta - tb).norm() / ta.norm(), 2e-5) << ta.transpose() << " vs " << tb.transpose();
    EXPECT_GT(ta.norm(), 0.0);
  }
}

TEST(Mindlin, TangentialStiffnessIsEightGStarContactRadius)
{
  const double E = 7e10, nu = 0.25, R_eff = 0.005, delta = 1e-5, dt = 1e-6, vt = 1e-4;
  const HertzMindlin law(HertzNormal({E, nu, HertzNormal::Damping::restitution, 1.0, 0.0, true}),
                         MindlinTangential({E, nu, 1.0}));
  const double G = E / (2.0 * (1.0 + nu));
  const double g_star = G / (2.0 * (2.0 - nu));  // Mindlin G* for like materials
  ContactKinematics k;
  k.normal = Vec3::UnitX();
  k.overlap = k.overlap_old = delta;
  k.r_eff = R_eff;
  k.m_eff = 0.01;
  k.v_t = Vec3(0, vt, 0);
  k.dt = dt;
  k.mu = 1.0;
  Vec3 shear = Vec3::Zero();
  const ContactForce f = law.evaluate(k, shear);
  const double expected = 8.0 * g_star * std::sqrt(R_eff * delta) * vt * dt;
  EXPECT_NEAR(-f.tangential.y() / expected, 1.0, 1e-12);
  // Unloading scales the stored force with k_t(delta): half the overlap, 1/sqrt(2).
  k.overlap = 0.5 * delta;
  k.v_t.setZero();
  const ContactForce g = law.evaluate(k, shear);
  EXPECT_NEAR(g.tangential.y() / f.tangential.y(), std::sqrt(0.5), 1e-12);
}

TEST(TimeStep, EstimatesFollowTheirFormulas)
{
  DemSystem sys;
  const double R = 0.0118, rho = 2650.0;
  sys.add_sphere(Vec3::Zero(), R, rho);
  sys.add_sphere(Vec3(1, 0, 0), 2 * R, rho);
  const double m = 4.0 / 3.0 * M_PI * R * R * R * rho;
  sys.set_contact_model(test::linear_law(1e6, 0.5, 2.0 / 7.0));
  EXPECT_NEAR(sys.critical_time_step(), std::sqrt(m / 1e6), 1e-15);
  sys.set_contact_model(test::linear_law(1e6, 0.5, 1.0));  // S0: k_t = k_n, tangential mode governs
  EXPECT_NEAR(sys.critical_time_step(), std::sqrt(m / 3.5e6), 1e-15);
  const double E = 7e10, nu = 0.25, G = E / (2 * (1 + nu));
  sys.set_contact_model(HertzMindlin(HertzNormal({E, nu, HertzNormal::Damping::restitution, 0.5, 0.0, true}),
                                     MindlinTangential({E, nu, 1.0})));
  EXPECT_NEAR(sys.critical_time_step() / (M_PI * R * std::sqrt(rho / G) / (0.1631 * nu + 0.8766)), 1.0, 1e-12);
}
