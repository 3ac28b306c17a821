// The batched AVX2 pair kernel (dem/PairBatchKernel.h) is the scalar linear spring-dashpot
// law, bit for bit: the same specimen run with the kernel and with the scalar path ends in
// the same positions, velocities, spins, forces, tangential springs and energy ledger.
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
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0;
  sys.set_time_step(0.1 * std::sqrt(m / 1e5));
  sys.set_num_threads(threads);
  sys.set_energy_tracking(true);
  sys.set_batched_pairs(batched);
}

void expect_same_run(LawVariant v, int threads)
{
  DemSystem batched, scalar;
  make_specimen(batched, v, true, threads);
  make_specimen(scalar, v, false, threads);
  if (!batched.batched_pairs()) GTEST_SKIP() << "no AVX2 kernel in this build or on this processor";
  ASSERT_FALSE(scalar.batched_pairs());
  batched.run(1500);
  scalar.run(1500);
  ASSERT_GT(batched.n_touching_pairs(), 300u);  // a loaded specimen, not a gas
  const EnergyLedger eb = batched.energy(), es = scalar.energy();
  ASSERT_GT(es.dissipated_friction, 0.0);       // contacts slid
  ASSERT_GT(es.dissipated_damping, 0.0);
  EXPECT_TRUE(test::bitwise_equal(test::state_bits(batched, true), test::state_bits(scalar, true)));
  EXPECT_EQ(eb.dissipated_damping, es.dissipated_damping);
  EXPECT_EQ(eb.dissipated_friction, es.dissipated_friction);
  EXPECT_EQ(eb.kinetic(), es.kinetic());
  for (std::size_t w = 0; w < 6; ++w) EXPECT_EQ(batched.wall(w).force, scalar.wall(w).force);
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
