// The batched AVX2 pair kernel (dem/PairBatchKernel.h) is the scalar linear spring-dashpot
// law, and the batched kick-drift sweep (dem/ParticleSweepKernel.h) the scalar integrator,
// bit for bit: the same specimen run with the kernels and with the scalar paths ends in the
// same positions, velocities, spins, orientations, forces, tangential springs and energy
// ledger.
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <random>

using namespace geocomp::dem;

namespace {

enum class LawVariant { direct_per_unit_mass, s0_restitution_damped_tangent };

LinearSpringDashpot make_law(LawVariant v)
{
  LinearNormal::Parameters np;
  LinearTangential::Parameters tp;
  if (v == LawVariant::direct_per_unit_mass) {
    // The shared benchmark's constants (k_n in N/m, gamma_n, k_t in N/m), unclamped.
    np.k_n = 1e5;
    np.damping_input = LinearNormal::Damping::per_unit_mass;
    np.gamma_n = 400.0;
    np.clamp_tensile = false;
    tp.stiffness_is_ratio = false;
    tp.k_t = 2.0 / 7.0 * 1e5;
    tp.damping_is_ratio = false;
    tp.c_t = 0.0;
  } else {
    // S0: k_n from E, nu, V_c (a power law in m*, R*), c_n from restitution, clamped;
    // k_t and c_t as ratios (a tangential dashpot too).
    np.stiffness_input = LinearNormal::Stiffness::from_impact_velocity;
    np.youngs_modulus = 5e7;
    np.poisson_ratio = 0.25;
    np.impact_velocity = 1.0;
    np.damping_input = LinearNormal::Damping::restitution;
    np.restitution = 0.5;
    tp.stiffness_is_ratio = true;
    tp.k_t = 1.0;
    tp.damping_is_ratio = true;
    tp.c_t = 0.3;
  }
  return LinearSpringDashpot(LinearNormal(np), LinearTangential(tp));
}

/// A polydisperse frictional specimen squeezed by its walls (so contacts stick, slide,
/// open and close, and (m*, R*) change from pair to pair).
void make_specimen(DemSystem& sys, LawVariant v, bool batched, int threads)
{
  sys.set_contact_model(make_law(v));
  sys.set_friction(0.3);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.01, a = 1.9 * R;  // spacing below the diameter: the lattice starts loaded
  const int per_edge = 7;
  for (int i = 0; i < per_edge; ++i)
    for (int j = 0; j < per_edge; ++j)
      for (int k = 0; k < per_edge; ++k) {
        const Vec3 x = Vec3(R + a * i, R + a * j, R + a * k) + 0.02 * R * Vec3(u(rng), u(rng), u(rng));
        const double r = R * (0.95 + 0.05 * u(rng));
        sys.add_sphere(x, r, 2650.0, 0.05 * Vec3(u(rng), u(rng), u(rng)), 5.0 * Vec3(u(rng), u(rng), u(rng)));
      }
  const double L = a * (per_edge - 1) + 2.0 * R;
  sys.add_box(Vec3::Zero(), Vec3::Constant(L), 0.2);
  for (std::size_t w = 0; w < 6; ++w) sys.set_wall_velocity(w, 0.1 * sys.wall(w).normal);
  // A tilted plane across the corner at the origin, touching the corner sphere (an
  // axis-aligned normal would make many of the wall kinematics' roundings exact).
  PlaneWall tilted;
  tilted.normal = Vec3(1.0, 2.0, 3.0).normalized();
  tilted.point = Vec3::Constant(R) - 0.97 * R * tilted.normal;
  tilted.mu = 0.4;
  tilted.velocity = 0.05 * tilted.normal;  // pressing on, so it keeps contacts
  sys.add_wall(tilted);
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0;
  sys.set_time_step(0.1 * std::sqrt(m / 1e5));
  sys.set_num_threads(threads);
  sys.set_energy_tracking(true);
  sys.set_batched_pairs(batched);
}

void expect_same_run(LawVariant v, int threads, DemSystem::Prefetch prefetch = DemSystem::Prefetch::automatic)
{
  DemSystem batched, scalar;
  make_specimen(batched, v, true, threads);
  make_specimen(scalar, v, false, threads);
  batched.set_prefetch(prefetch);
  if (!batched.batched_pairs()) GTEST_SKIP() << "no AVX2 kernel in this build or on this processor";
  ASSERT_FALSE(scalar.batched_pairs());
  batched.run(1500);
  scalar.run(1500);
  ASSERT_EQ(batched.prefetching(), prefetch == DemSystem::Prefetch::on);  // 343 spheres: automatic is off
  ASSERT_GT(batched.n_touching_pairs(), 300u);  // a loaded specimen, not a gas
  const EnergyLedger eb = batched.energy(), es = scalar.energy();
  ASSERT_GT(es.dissipated_friction, 0.0);       // contacts slid
  ASSERT_GT(es.dissipated_damping, 0.0);
  EXPECT_TRUE(test::bitwise_equal(test::state_bits(batched, true), test::state_bits(scalar, true)));
  EXPECT_EQ(eb.dissipated_damping, es.dissipated_damping);
  EXPECT_EQ(eb.dissipated_friction, es.dissipated_friction);
  EXPECT_EQ(eb.kinetic(), es.kinetic());
  for (std::size_t w = 0; w < 7; ++w) EXPECT_EQ(batched.wall(w).force, scalar.wall(w).force);
  EXPECT_GT(std::abs(scalar.wall(6).work), 0.0);  // the tilted plane was met
}

}  // namespace

TEST(PairBatchKernel, EqualsTheScalarLawBitForBitWithTheBenchmarkConstants)
{
  expect_same_run(LawVariant::direct_per_unit_mass, 1);
}

TEST(PairBatchKernel, EqualsTheScalarLawBitForBitWithS0StiffnessAndRestitution)
{
  expect_same_run(LawVariant::s0_restitution_damped_tangent, 1);
}

// The software prefetch (DemSystem::set_prefetch) reads slots ahead of the test up to the
// end of each worker's range (two workers here) and changes nothing.
TEST(PairBatchKernel, SoftwarePrefetchKeepsTheBitsOnTwoWorkers)
{
  expect_same_run(LawVariant::direct_per_unit_mass, 2, DemSystem::Prefetch::on);
}

// The sweep's two rotation branches: spins small enough for the series and spins whose
// half-step angle |omega| dt / 2 reaches 0.01 (sin and cos), in batches of four spheres and
// in the last spheres of a block (1001 spheres: 3 blocks of 256, the last ending in 1).
TEST(PairBatchKernel, KickDriftSweepEqualsTheScalarLoopForSlowAndFastSpins)
{
  const auto make = [](DemSystem& sys, bool batched) {
    sys.set_contact_model(make_law(LawVariant::direct_per_unit_mass));
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double R = 0.01, dt = 1e-4;
    for (int k = 0; k < 1001; ++k) {
      const Vec3 x(3.0 * R * (k % 10), 3.0 * R * ((k / 10) % 10), 3.0 * R * (k / 100));  // apart: no contacts
      const double spin = (k % 7 == 3) ? 400.0 : 20.0;  // |omega| dt / 2 up to 0.035 against ~1e-3
      sys.add_sphere(x, R, 2650.0, Vec3(u(rng), u(rng), u(rng)), spin * Vec3(u(rng), u(rng), u(rng)));
    }
    sys.set_gravity(Vec3(0.0, 0.0, -9.81));
    sys.set_time_step(dt);
    sys.set_batched_pairs(batched);
  };
  DemSystem batched, scalar;
  make(batched, true);
  make(scalar, false);
  if (!batched.batched_pairs()) GTEST_SKIP() << "no AVX2 kernel in this build or on this processor";
  batched.run(200);
  scalar.run(200);
  EXPECT_TRUE(test::bitwise_equal(test::state_bits(batched), test::state_bits(scalar)));
  // The orientations turned (a sweep that skipped the rotation would agree with nothing).
  double turned = 0.0;
  for (ParticleId id = 0; id < batched.n_particles(); ++id) turned = std::max(turned, 1.0 - std::abs(batched.orientation(id).w()));
  EXPECT_GT(turned, 0.1);
}
