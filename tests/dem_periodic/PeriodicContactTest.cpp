// Contacts across the cell's faces: the same force as inside, through the existing laws;
// Love-Weber stress against the hand calculation; equal and opposite forces.
#include "dem/periodic/PeriodicCell.h"
#include "TestCells.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace geocomp::dem;

namespace {
HertzMindlin hertz_mindlin()
{
  HertzNormal::Parameters n;
  n.youngs_modulus = 7e7;
  n.poisson_ratio = 0.25;
  n.restitution = 0.6;
  MindlinTangential::Parameters t;
  t.youngs_modulus = 7e7;
  t.poisson_ratio = 0.25;
  return HertzMindlin(HertzNormal(n), MindlinTangential(t));
}

struct PairRun
{
  std::vector<Vec3> force_i, force_j, torque_j;
  bool through_image = false;  ///< the pair was listed with a nonzero shift
};

/// Two spheres at x_i and x_j (j given by any image) with velocities, in cell h under the
/// velocity gradient l, for 300 steps: the loads after each step.
PairRun run_pair(const ContactModel& law, const Mat3& h, const Mat3& l, const Vec3& xi, const Vec3& xj)
{
  PeriodicCell::Parameters cp;
  cp.time_step = 2e-6;
  cp.friction = 0.4;
  PeriodicCell cell(CellMatrix(h), law, cp);
  cell.add_sphere(xi, 0.0703125, 2650.0, Vec3(0.01, 0.02, 0.0), Vec3(0.0, 0.0, 1.0));
  cell.add_sphere(xj, 0.0703125, 2650.0, Vec3(-0.01, -0.01, 0.005), Vec3(0.5, 0.0, -1.0));
  cell.set_velocity_gradient(l);
  PairRun r;
  for (int k = 0; k < 300; ++k) {
    cell.step();
    r.force_i.push_back(cell.force(0));
    r.force_j.push_back(cell.force(1));
    r.torque_j.push_back(cell.torque(1));
    for (const PeriodicPair& p : cell.neighbours().pairs)
      r.through_image = r.through_image || p.shift != std::array<std::int32_t, 3>{{0, 0, 0}};
  }
  return r;
}

void expect_same_loads(const PairRun& across, const PairRun& inside)
{
  EXPECT_TRUE(across.through_image);
  EXPECT_FALSE(inside.through_image);
  ASSERT_EQ(across.force_j.size(), inside.force_j.size());
  const double scale = inside.force_j.front().norm();
  ASSERT_GT(scale, 0.0);
  for (std::size_t k = 0; k < inside.force_j.size(); ++k) {
    EXPECT_LT((across.force_j[k] - inside.force_j[k]).norm(), 1e-9 * scale) << "step " << k;
    EXPECT_LT((across.force_i[k] - inside.force_i[k]).norm(), 1e-9 * scale) << "step " << k;
    EXPECT_LT((across.torque_j[k] - inside.torque_j[k]).norm(), 1e-9 * scale) << "step " << k;
  }
  // The pair kept touching and carried a tangential force (friction and spin at work).
  EXPECT_GT(inside.force_j.back().norm(), 0.0);
  EXPECT_GT(std::abs(inside.force_j.back().y()) + std::abs(inside.force_j.back().z()), 1e-6 * scale);
}
}  // namespace

TEST(PeriodicContact, TwoSpheresTouchingAcrossTheBoundaryFeelTheSameForceAsInsideTheCell)
{
  // Centres 0.125 apart along x (overlap 1/64), once straddling the face x = 0 and once in
  // the middle of the cell, under a gradient with stretch and shear; three laws (linear,
  // Hertz-Mindlin, linear with rolling resistance and its ContactMemory).
  Mat3 l = Mat3::Zero();
  l(0, 0) = -0.5;
  l(0, 1) = 0.3;
  const Mat3 h = Mat3::Identity();
  const Vec3 a(0.0625, 0.5, 0.5), b(0.9375, 0.5, 0.5);          // across x = 0
  const Vec3 c(0.4375, 0.5, 0.5), d(0.5625, 0.5, 0.5);          // inside
  const LinearRollingResistance rolling(LinearNormal::with_stiffness(1e6, 0.5), LinearTangential::with_ratio(2.0 / 7.0),
                                        LinearRolling(LinearRolling::Parameters{0.3, 1.0}));
  const ContactModel laws[3] = {test::periodic_linear_law(1e6, 0.5), hertz_mindlin(), rolling};
  for (const ContactModel& law : laws) {
    // i = b, j = a: j's image a + h1 is b's partner, 0.125 further along x.
    const PairRun across = run_pair(law, h, l, b, a);
    const PairRun inside = run_pair(law, h, l, c, d);
    expect_same_loads(across, inside);
  }
}

TEST(PeriodicContact, TwoSpheresTouchingThroughATiltedFaceFeelTheSameForceAsInsideTheCell)
{
  // A sheared cell: h2 = (0.25, 1, 0). Sphere i sits near the top face y = 1 and touches
  // j, whose centre lies beyond that face and is wrapped to near y = 0, through j's image
  // x_j + h2.
  Mat3 h = Mat3::Identity();
  h(0, 1) = 0.25;
  Mat3 l = Mat3::Zero();
  l(0, 1) = 0.4;
  l(1, 1) = -0.2;
  const Vec3 branch(0.03125, 0.0625, -0.09375);  // |branch| < 2R
  const Vec3 xi(0.5, 0.96875, 0.5);
  const PairRun across = run_pair(ContactModel(test::periodic_linear_law(1e6, 0.5)), h, l, xi, xi + branch);
  const Vec3 yi(0.5, 0.4375, 0.5);
  const PairRun inside = run_pair(ContactModel(test::periodic_linear_law(1e6, 0.5)), h, l, yi, yi + branch);
  expect_same_loads(across, inside);
}

TEST(LoveWeber, TheStressOfAStaticPairAcrossTheBoundaryMatchesTheHandCalculation)
{
  // Box 0.5 x 0.6 x 0.7 m; spheres of R = 0.05 m, centres 0.09 m apart along a skew
  // direction across the corner; linear law k_n = 1e6 N/m: F = k_n (2R - r) = 1e4 N.
  PeriodicCell::Parameters cp;
  cp.time_step = 1e-6;
  cp.kinetic_stress = true;
  const Vec3 edges(0.5, 0.6, 0.7);
  PeriodicCell cell(CellMatrix::box(edges), test::periodic_linear_law(1e6, 0.5), cp);
  const Vec3 n = Vec3(2.0, -1.0, 2.0) / 3.0;
  const double r = 0.09, R = 0.05;
  const Vec3 xi(0.48, 0.02, 0.69);
  cell.add_sphere(xi, R, 2000.0);
  cell.add_sphere(xi + r * n - Vec3(edges.x(), 0.0, edges.z()), R, 2000.0);  // wrapped image
  const Vec3 u(0.3, 0.0, -0.4);
  cell.add_sphere(Vec3(0.25, 0.3, 0.35), 0.01, 1000.0, u);                     // alone, moving
  cell.evaluate();
  const double V = edges.prod();
  const double F = 1e6 * (2.0 * R - r);
  const Mat3 hand = -(F * r / V) * n * n.transpose();  // -(1/V) F l, tension positive
  const double m3 = 1000.0 * 4.0 / 3.0 * M_PI * 1e-6;
  const Mat3 kinetic = -(m3 / V) * u * u.transpose();
  EXPECT_EQ(cell.stress().contacts, 1u);
  EXPECT_LT((cell.stress().contact - hand).norm(), 1e-10 * hand.norm());
  EXPECT_LT((cell.stress().kinetic - kinetic).norm(), 1e-12 * kinetic.norm());
  EXPECT_LT(cell.stress().skew.norm(), 1e-12 * hand.norm());
  EXPECT_NEAR(cell.stress().pressure(), F * r / (3.0 * V) - kinetic.trace() / 3.0, 1e-10 * F * r / V);
  EXPECT_NEAR(cell.force(1).dot(n), F, 1e-9 * F);
}

TEST(PeriodicContact, ContactForcesSumToZeroAndTheFluctuationsKeepTheirMomentum)
{
  test::RveSetup s;
  s.particles = 150;
  PeriodicCell cell = test::consolidated_rve(s).cell;
  PeriodicCell::Parameters cp = cell.parameters();
  cp.local_damping = 0.0;  // local damping is an external force; the contacts alone conserve momentum
  cell.set_parameters(cp);
  for (Index p = 0; p < cell.n_particles(); ++p) cell.set_velocity(p, Vec3::Zero(), Vec3::Zero());
  Mat3 l = Mat3::Zero();
  l(0, 1) = 2.0;
  l(2, 2) = -1.0;
  cell.set_velocity_gradient(l);
  double max_net = 0.0, max_momentum = 0.0, momentum_scale = 0.0;
  for (int k = 0; k < 400; ++k) {
    cell.step();
    Vec3 net = Vec3::Zero(), momentum = Vec3::Zero();
    double scale = 0.0;
    for (Index p = 0; p < cell.n_particles(); ++p) {
      net += cell.force(p);
      const double m = cell.particles().mass[p];
      momentum += m * cell.fluctuation(p);
      scale += m * cell.fluctuation(p).norm();
    }
    max_net = std::max(max_net, net.norm() / (cell.stress().mean_contact_force * double(cell.n_particles())));
    max_momentum = std::max(max_momentum, momentum.norm());
    momentum_scale = std::max(momentum_scale, scale);
  }
  EXPECT_GT(cell.stress().contacts, 100u);
  EXPECT_GT(momentum_scale, 0.0);
  EXPECT_LT(max_net, 1e-14);
  EXPECT_LT(max_momentum, 1e-12 * momentum_scale);
}
