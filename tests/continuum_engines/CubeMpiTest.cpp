// np = 1 and np = 2 play the same program on the same imperfect, softening cube and must
// give the same Response to solver tolerance; at finite strain both keep S0's isochoric
// shear isochoric to 30 %. Run under `mpirun -np 2`: rank 0 also runs the serial case on
// MPI_COMM_SELF.
#include "EngineTestSupport.h"

#include "common/ProgramRunner.h"
#include "continuum/fe/CubeEngine.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace geocomp;
using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

TEST(CubeEngineMpi, TwoRanksGiveTheResponseOfOne)
{
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (size < 2)
    GTEST_SKIP() << "needs mpirun -np 2";

  const double p = 1e5;
  MohrCoulombParameters m = perfect_mohr_coulomb(1e8, 0.3, 20e3, deg(30), deg(5));
  m.cohesion = PiecewiseLinear({0.0, 0.002, 0.02}, {20e3, 20e3, 4e3});
  CubeParameters cp;
  cp.cells_per_side = 4;
  cp.imperfection_radius = 0.25;
  cp.imperfection_cohesion_factor = 0.8;
  cp.newton_tolerance = 1e-11;
  cp.linear_tolerance = 1e-12;
  LoadingProgram program;
  program.sample_interval = 1.0;
  program.stages = {isotropic_stage(p, 1.0), triaxial_stage(p, 1e-3, 0.008)};

  Response serial;
  if (rank == 0) {
    CubeEngine engine(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_SELF);
    serial = ProgramRunner(program, engine).run();
  }
  CubeEngine engine(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const Response parallel = ProgramRunner(program, engine).run();
  if (rank != 0)
    return;
  ASSERT_EQ(serial.samples.size(), parallel.samples.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < serial.samples.size(); ++k) {
    worst = std::max(worst, (serial.samples[k].stress - parallel.samples[k].stress).norm() / p);
    // Strains to 1e-8: after the peak the softening tangent is nearly singular, and the
    // round-off of the finite-strain update (~1e-13 of the forces) moves the free faces by
    // ~1e-9 between partitions.
    EXPECT_LT((serial.samples[k].strain - parallel.samples[k].strain).norm(), 1e-8) << "sample " << k;
  }
  std::printf("largest |sigma_np1 - sigma_np2| / p over %zu samples: %.3e\n", serial.samples.size(), worst);
  EXPECT_LT(worst, 1e-7);
  // And the run was plastic (the comparison covers the nonlinear part).
  EXPECT_GT(parallel.samples.back().extras[parallel.extra_index("kappa_max")], 0.0);
}

TEST(CubeEngineMpi, IsochoricShearKeepsTheMeanStressAndThePlateauOnOneAndTwoRanks)
{
  // Perfect Mohr-Coulomb, psi = 0, from -p, S0's isochoric program (lambda = 0) to
  // gamma_max = 30 %: the mean stress stays at -p and the plateau is c cos(phi) + p sin(phi)
  // to 1e-8 (finite strain: det F = 1 exactly, the flow is isochoric).
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const double p = 1e5, c = 10e3, phi = deg(30);
  const MohrCoulombParameters m = perfect_mohr_coulomb(1e8, 0.25, c, phi, 0.0);
  CubeParameters cp;
  cp.cells_per_side = 2;
  cp.initial_stress = -p;
  cp.newton_tolerance = 1e-11;
  cp.linear_tolerance = 1e-12;
  const LoadingProgram program = s0_isochoric(0.3, 0.05);
  if (rank == 0) {
    CubeEngine serial(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_SELF);
    const Response r = ProgramRunner(program, serial).run();
    EXPECT_EQ(r.stage_end_reasons[0], "gamma_max >= 0.300000");
    EXPECT_GT(expect_isochoric_plateau(r, p, c, phi, 1e-8), 50) << "np = 1";
  }
  if (size < 2)
    return;
  CubeEngine parallel(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const Response r = ProgramRunner(program, parallel).run();
  if (rank == 0) {
    EXPECT_GT(expect_isochoric_plateau(r, p, c, phi, 1e-8), 50) << "np = 2";
  }
}
