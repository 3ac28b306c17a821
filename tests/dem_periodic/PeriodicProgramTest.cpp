// The stand-alone RVE programs: servo isotropic compression to a pressure, triaxial shear
// at constant lateral stress; the same bits for repeated runs.
#include "dem/periodic/PeriodicProgram.h"
#include "TestCells.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <vector>

using namespace geocomp::dem;

namespace {
TriaxialShear triaxial(const test::RveSetup& s, double strain)
{
  TriaxialShear t;
  t.axis = 2;
  t.lateral_pressure = s.pressure;
  t.strain_rate = 2.0;  // inertial number 2 * 2e-3 * sqrt(2650 / 1e5) = 6.5e-4
  t.axial_strain = strain;
  t.record_interval = 200;
  return t;
}
}  // namespace

TEST(PeriodicProgram, IsotropicCompressionReachesThePressureByServoThenTriaxialShearRaisesTheDeviator)
{
  const test::RveSetup s;
  const auto t0 = std::chrono::steady_clock::now();
  test::Consolidated c = test::consolidated_rve(s);
  ASSERT_TRUE(c.compression.converged) << "after " << c.compression.steps << " steps, stress\n" << c.compression.stress;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(c.compression.stress(a, a), -s.pressure, 0.01 * s.pressure);
  EXPECT_GT(c.compression.packing_fraction, 0.55);
  EXPECT_GT(c.cell.coordination(), 3.5);
  const auto recs = shear_triaxial(c.cell, triaxial(s, 0.03));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_GT(recs.size(), 10u);
  // The deviator rises from ~0 and is well up by 1 % axial strain.
  EXPECT_LT(std::abs(recs.front().deviator), 0.05 * s.pressure);
  const auto at = [&](double strain) {
    for (const TriaxialRecord& r : recs)
      if (r.axial_strain >= strain) return r;
    return recs.back();
  };
  EXPECT_GT(at(0.002).deviator, 0.1 * s.pressure);
  EXPECT_GT(at(0.01).deviator, at(0.002).deviator);
  EXPECT_GT(at(0.01).deviator, 0.5 * s.pressure);
  // The lateral stresses stay at -p by servo (after the first records).
  for (std::size_t k = 2; k < recs.size(); ++k) EXPECT_LT(recs[k].lateral_error, 0.05) << "record " << k;
  // A loose-to-medium packing first contracts.
  EXPECT_LT(at(0.002).volumetric_strain, 0.0);
  std::printf("[ RVE      ] N = %zu, compression %llu steps, phi = %.4f, Z = %.2f; q/p at 0.2, 1, 3 %%: %.3f %.3f %.3f;"
              " eps_v at 3 %%: %.4f; %.2f s\n",
              c.cell.n_particles(), (unsigned long long)c.compression.steps, c.compression.packing_fraction,
              c.cell.coordination(), at(0.002).deviator / s.pressure, at(0.01).deviator / s.pressure,
              recs.back().deviator / s.pressure, recs.back().volumetric_strain, seconds);
}

TEST(PeriodicProgram, RepeatedRunsGiveTheSameBits)
{
  test::RveSetup s;
  s.particles = 120;
  const auto run = [&] {
    test::Consolidated c = test::consolidated_rve(s);
    shear_triaxial(c.cell, triaxial(s, 0.002));
    return c;
  };
  const test::Consolidated a = run(), b = run();
  ASSERT_EQ(a.cell.n_particles(), b.cell.n_particles());
  EXPECT_EQ(a.cell.steps(), b.cell.steps());
  EXPECT_EQ(0, std::memcmp(a.cell.particles().x.data(), b.cell.particles().x.data(), a.cell.n_particles() * sizeof(Vec3)));
  EXPECT_EQ(0, std::memcmp(a.cell.particles().v.data(), b.cell.particles().v.data(), a.cell.n_particles() * sizeof(Vec3)));
  const Mat3 sa = a.cell.stress().total(), sb = b.cell.stress().total();
  const Mat3 ha = a.cell.cell().h(), hb = b.cell.cell().h();
  EXPECT_EQ(0, std::memcmp(sa.data(), sb.data(), sizeof(Mat3)));
  EXPECT_EQ(0, std::memcmp(ha.data(), hb.data(), sizeof(Mat3)));
}

TEST(PeriodicProgram, AProgramStartedOnARunningCellContinuesItsTrajectoryBitForBit)
{
  // refresh() re-evaluates nothing after a step: stopping, starting a program (which
  // refreshes) and going on is the same as stepping through.
  test::RveSetup s;
  s.particles = 120;
  const PeriodicCell start = test::consolidated_rve(s).cell;
  Mat3 l = Mat3::Zero();
  l(2, 2) = -1.0;
  PeriodicCell a = start, b = start;
  a.set_velocity_gradient(l);
  b.set_velocity_gradient(l);
  a.run(300);
  b.run(150);
  b.refresh();
  b.run(150);
  EXPECT_EQ(0, std::memcmp(a.particles().x.data(), b.particles().x.data(), a.n_particles() * sizeof(Vec3)));
  const Mat3 sa = a.stress().total(), sb = b.stress().total();
  EXPECT_EQ(0, std::memcmp(sa.data(), sb.data(), sizeof(Mat3)));
  // evaluate() does re-evaluate (dashpots at the closing kick's velocities): a different path.
  PeriodicCell c = start;
  c.set_velocity_gradient(l);
  c.run(150);
  c.evaluate();
  c.run(150);
  EXPECT_NE(0, std::memcmp(a.particles().x.data(), c.particles().x.data(), a.n_particles() * sizeof(Vec3)));
}

TEST(PeriodicProgram, CellsSteppedOnSeparateThreadsGiveTheBitsOfASerialRun)
{
  // The coupling will run one RVE per thread: a cell holds no shared state.
  test::RveSetup s;
  s.particles = 120;
  const PeriodicCell start = test::consolidated_rve(s).cell;
  std::vector<PeriodicCell> serial(4, start), threaded(4, start);
  const auto drive = [](PeriodicCell& c, int k) {
    Mat3 l = Mat3::Zero();
    l(2, 2) = -0.5 * (k + 1);
    l(0, 1) = 0.3 * k;
    c.set_velocity_gradient(l);
    c.run(300);
  };
  for (int k = 0; k < 4; ++k) drive(serial[k], k);
#pragma omp parallel for num_threads(2) schedule(static, 1)
  for (int k = 0; k < 4; ++k) drive(threaded[k], k);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(0, std::memcmp(serial[k].particles().x.data(), threaded[k].particles().x.data(),
                             serial[k].n_particles() * sizeof(Vec3)))
      << "cell " << k;
    const Mat3 a = serial[k].stress().total(), b = threaded[k].stress().total();
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(Mat3))) << "cell " << k;
  }
  EXPECT_NE(0, std::memcmp(serial[0].particles().x.data(), serial[1].particles().x.data(),
                           serial[0].n_particles() * sizeof(Vec3)));
}

TEST(PeriodicProgram, TriaxialShearRefusesAnAxialRateTheLateralServoCouldNotFollow)
{
  PeriodicCell::Parameters cp;
  cp.time_step = 1e-6;
  PeriodicCell cell(CellMatrix::box(Vec3::Constant(0.1)), test::periodic_linear_law(1e5, 0.5), cp);
  cell.add_sphere(Vec3::Constant(0.05), 0.01, 2650.0);
  cell.control().set_parameters(MixedControl::Parameters{0.2, 3.0});
  TriaxialShear t;
  t.lateral_pressure = 1e5;
  t.axial_strain = 0.01;
  t.strain_rate = 8.0;
  EXPECT_THROW(shear_triaxial(cell, t), std::invalid_argument);
  EXPECT_EQ(cell.steps(), 0u);
}
