// The DEM engine in its wall box on a small consolidated specimen: the servo holds its
// goal, the isochoric program of S0 eq. (3) keeps the box volume to round-off, wall and
// Love-Weber stresses agree in an isotropic quasi-static state, save/restore and
// checkpoints resume bit for bit, and the case-file law maps onto the core's.
#include "Specimen.h"

#include "common/ProgramRunner.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;

namespace {
StageControl control_of(const Stage &stage, double t0, const Vector3 &eps0 = Vector3::Zero())
{
  StageControl c;
  c.stage = &stage;
  c.t0 = t0;
  c.eps0 = eps0;
  return c;
}
} // namespace

TEST(DemEngine, ConsolidationReachesSigmaZeroQuasiStatically)
{
  const Consolidated &c = consolidated();
  EXPECT_TRUE(c.frictionless.converged);
  EXPECT_TRUE(c.frictional.converged);
  DemEngine engine(c.system, engine_parameters());
  const ResponseSample s = engine.measure();
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(s.stress(a, a), -kPressure, 0.005 * kPressure) << "axis " << a;
  EXPECT_LT(s.extras[DemEngine::kUnbalancedForceRatio], 1e-3);
  EXPECT_GT(s.extras[DemEngine::kCoordination], 3.5);
  EXPECT_GT(s.extras[DemEngine::kMechanicalCoordination], s.extras[DemEngine::kCoordination] - 1e-12);
  EXPECT_GT(1.0 - s.extras[DemEngine::kPorosity], 0.55);
  std::printf("[specimen] packing fraction %.4f, Z %.3f, Z_m %.3f, fabric anisotropy %.4f, UFR %.2e, dt %.3e s\n",
              1.0 - s.extras[DemEngine::kPorosity], s.extras[DemEngine::kCoordination],
              s.extras[DemEngine::kMechanicalCoordination], s.extras[DemEngine::kFabricAnisotropy],
              s.extras[DemEngine::kUnbalancedForceRatio], engine.system().time_step());
}

namespace {
/// Love-Weber vs wall stress on a consolidated isotropic specimen: diagonals equal within
/// 1 %, walls and Love-Weber within 2 %, off-diagonals within twice the finite-size scale
/// 1/sqrt(C) of DEM-NOTES section 10.7 (C: particle-particle contacts; the scale is a
/// standard deviation, so one specimen may exceed it). Returns the largest off-diagonal
/// relative to the mean.
double check_isotropic_state(const Consolidated &specimen)
{
  DemEngine engine(specimen.system, engine_parameters());
  const Tensor3 wall = engine.wall_stress(), lw = engine.love_weber_stress();
  const double p = -lw.trace() / 3.0;
  EXPECT_GT(p, 0.0);
  double off = 0.0;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lw(a, a), -p, 0.01 * p) << "diagonal " << a;
    EXPECT_NEAR(lw(a, a), wall(a, a), 0.02 * std::abs(wall(a, a))) << "wall vs Love-Weber, axis " << a;
    for (int b = a + 1; b < 3; ++b)
      off = std::max(off, std::abs(lw(a, b)) / p);
  }
  // The extras carry the same tensor.
  const ResponseSample s = engine.measure();
  EXPECT_DOUBLE_EQ(s.extras[DemEngine::kLoveWeberXX], lw(0, 0));
  EXPECT_DOUBLE_EQ(s.extras[DemEngine::kLoveWeberMean], -p);
  const double C = 0.5 * s.extras[DemEngine::kCoordination] * double(engine.system().n_particles());
  EXPECT_LT(off, 2.0 / std::sqrt(C));
  double diag = 0.0, wall_vs_lw = 0.0;
  for (int a = 0; a < 3; ++a) {
    diag = std::max(diag, std::abs(lw(a, a) + p) / p);
    wall_vs_lw = std::max(wall_vs_lw, std::abs(lw(a, a) - wall(a, a)) / std::abs(wall(a, a)));
  }
  std::printf("[love-weber %zu spheres] p_LW = %.6g Pa; max |LW_aa - p|/p %.2e; max |LW_aa - wall_aa|/|wall_aa| "
              "%.2e; max |LW_ab|/p %.2e, 1/sqrt(C) %.2e (UFR %.1e)\n",
              engine.system().n_particles(), p, diag, wall_vs_lw, off, 1.0 / std::sqrt(C),
              s.extras[DemEngine::kUnbalancedForceRatio]);
  return off;
}
} // namespace

TEST(DemEngine, LoveWeberStressIsIsotropicAndMatchesTheWalls)
{
  // 343 spheres: the diagonals and the wall agreement are tight; the off-diagonals are the
  // finite-size couples of the wall pressure (frictionless walls carry them by an uneven
  // normal traction), ~2 % of p at 7 spheres per edge, falling like 1/n.
  check_isotropic_state(consolidated());
}

TEST(DemEngine, LoveWeberOffDiagonalsStayWithinTheFiniteSizeScaleOnALargerSpecimen)
{
  // 2744 spheres (14 per edge, ~17 s): the off-diagonals stay within 2/sqrt(C) (checked
  // in check_isotropic_state), 2.2 % of p here against 6.6 % at 343 spheres, towards the
  // issue's 1 % (reached only for C >~ 1e4 contacts, i.e. the ~5000-sphere specimens).
  // One specimen's off-diagonal is one draw of a fluctuation of size ~1/sqrt(C): an
  // earlier version compared two single specimens (large < small), which a change in the
  // last bits of the preparation turned over (1.51 % vs 1.25 %) - a coin toss, not a test.
  const double large = check_isotropic_state(consolidated_large());
  EXPECT_LT(large, 0.025);
}

TEST(DemEngine, ServoHoldsLateralStressWhileTheAxialWallsMove)
{
  // Constant lateral pressure (S0 program 2) on a small scale: z compresses by 0.5 %,
  // then stops; the x and y servos hold -p throughout and settle within 0.5 %.
  DemEngine engine(consolidated().system, engine_parameters());
  Stage load;
  load.axes = {{AxisDrive::stress(-kPressure), AxisDrive::stress(-kPressure), AxisDrive::rate(-0.5)}};
  engine.begin_control(control_of(load, 0.0));
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t steps0 = engine.system().n_steps();
  double worst_while_loading = 0.0, max_inertial = 0.0;
  for (int k = 1; k <= 10; ++k) {
    engine.advance_to(0.001 * k);
    const ResponseSample s = engine.measure();
    worst_while_loading = std::max(worst_while_loading, std::abs(s.stress(0, 0) + kPressure) / kPressure);
    max_inertial = std::max(max_inertial, s.extras[DemEngine::kInertialNumber]);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double steps_per_second = double(engine.system().n_steps() - steps0) / seconds;
  ResponseSample s = engine.measure();
  EXPECT_NEAR(s.strain(2, 2), -0.005, 1e-4);
  EXPECT_LT(s.stress(2, 2), -kPressure); // the axial stress rose
  Stage hold;
  hold.axes = {{AxisDrive::stress(-kPressure), AxisDrive::stress(-kPressure), AxisDrive::rate(0.0)}};
  engine.begin_control(control_of(hold, engine.time(), s.strain.diagonal()));
  HoldResult settled;
  for (int k = 1; k <= 40; ++k) {
    engine.advance_to(engine.time() + 0.002);
    s = engine.measure();
    settled.stress_error = std::max(std::abs(s.stress(0, 0) + kPressure), std::abs(s.stress(1, 1) + kPressure)) /
                           kPressure;
    settled.unbalanced = s.extras[DemEngine::kUnbalancedForceRatio];
    if (settled.stress_error < 0.005 && settled.unbalanced < 1e-3)
      break;
  }
  EXPECT_LT(settled.stress_error, 0.005);
  EXPECT_LT(settled.unbalanced, 1e-3);
  EXPECT_NEAR(s.strain(2, 2), -0.005, 1e-4); // the kinematic axis stayed put
  std::printf("[servo] lateral error while loading <= %.3g, after settling %.3g (UFR %.2e); max I %.2e at "
              "eps_zz rate 0.5/s; %.0f steps/s on %zu spheres, 1 thread\n",
              worst_while_loading, settled.stress_error, settled.unbalanced, max_inertial, steps_per_second,
              engine.system().n_particles());
}

TEST(DemEngine, IsochoricProgramKeepsTheBoxVolumeToRoundOff)
{
  for (double lambda : {0.0, 0.5, -1.0}) {
    DemEngine engine(consolidated().system, engine_parameters());
    Stage stage;
    stage.isochoric = true;
    stage.lambda = lambda;
    stage.isochoric_rate = 1.0;
    engine.begin_control(control_of(stage, 0.0));
    const double v0 = engine.box_lengths().prod();
    double worst = 0.0;
    for (int k = 1; k <= 20; ++k) {
      engine.advance_to(0.0005 * k);
      worst = std::max(worst, std::abs(engine.box_lengths().prod() - v0) / v0);
    }
    const ResponseSample s = engine.measure();
    EXPECT_LT(worst, 1e-14) << "lambda " << lambda;
    // The walls sit exactly where eq. (3) puts them at the sample's time.
    EXPECT_NEAR(s.strain(0, 0), -1.0 * s.time, 1e-14);
    EXPECT_NEAR(s.strain(1, 1), -lambda * s.time, 1e-14);
    EXPECT_NEAR(s.time, 0.01, 1e-15); // advance_to lands on the sample time
    EXPECT_NEAR((1 + s.strain(0, 0)) * (1 + s.strain(1, 1)) * (1 + s.strain(2, 2)), 1.0, 1e-14);
    if (lambda == 0.0) {
      EXPECT_GT(tau_max(s.stress), 0.1 * kPressure); // shearing at constant volume loads the specimen
      std::printf("[isochoric] lambda 0: |dV|/V0 <= %.2e, gamma_max %.4f, tau_max %.4g Pa, I %.2e\n", worst,
                  gamma_max(s.strain), tau_max(s.stress), s.extras[DemEngine::kInertialNumber]);
    }
  }
}

TEST(DemEngine, SaveAndRestoreResumeBitForBit)
{
  DemEngine engine(consolidated().system, engine_parameters());
  Stage stage;
  stage.axes = {{AxisDrive::stress(-kPressure), AxisDrive::stress(-kPressure), AxisDrive::rate(-1.0)}};
  engine.begin_control(control_of(stage, 0.0));
  engine.advance_to(0.002);
  const auto saved = engine.save();
  engine.advance_to(0.004);
  const ResponseSample first = engine.measure();
  const ParticleFields f1 = engine.snapshot();
  // Another path in between (a reversed branch), then back to the saved state.
  StageControl back = control_of(stage, 0.002);
  back.direction = -1.0;
  engine.begin_control(back);
  engine.advance_to(0.003);
  engine.restore(*saved);
  engine.advance_to(0.004);
  const ResponseSample second = engine.measure();
  const ParticleFields f2 = engine.snapshot();
  EXPECT_EQ(first.time, second.time);
  EXPECT_EQ(first.strain, second.strain);
  EXPECT_EQ(first.stress, second.stress);
  EXPECT_EQ(first.extras, second.extras);
  EXPECT_EQ(f1.positions, f2.positions);
  EXPECT_EQ(f1.velocities, f2.velocities);
  EXPECT_EQ(f1.contact_forces, f2.contact_forces);
}

TEST(DemEngine, CheckpointFileResumesBitForBit)
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "geocomp_dem_checkpoint_roundtrip";
  std::filesystem::create_directories(dir);
  DemEngine engine(consolidated().system, engine_parameters());
  Stage stage;
  stage.isochoric = true;
  stage.isochoric_rate = 1.0;
  engine.begin_control(control_of(stage, 0.0));
  engine.advance_to(0.001);
  const double t_checkpoint = engine.time();
  engine.write_checkpoint(dir / "c.bin");
  engine.advance_to(0.003);
  const ResponseSample first = engine.measure();
  const ParticleFields f1 = engine.snapshot();

  auto restarted = DemEngine::from_checkpoint(dir / "c.bin", engine_parameters());
  EXPECT_EQ(restarted->time(), t_checkpoint);
  restarted->advance_to(0.003); // the drive came with the checkpoint
  const ResponseSample second = restarted->measure();
  const ParticleFields f2 = restarted->snapshot();
  EXPECT_EQ(first.time, second.time);
  EXPECT_EQ(first.stress, second.stress);
  EXPECT_EQ(first.extras, second.extras);
  EXPECT_EQ(f1.positions, f2.positions);
  EXPECT_EQ(f1.displacements, f2.displacements);
  EXPECT_EQ(f1.angular_velocities, f2.angular_velocities);
  // A truncated file is refused, not misread.
  {
    std::ifstream in(dir / "c.bin", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(dir / "short.bin", std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size() / 2));
  }
  EXPECT_THROW(DemEngine::from_checkpoint(dir / "short.bin", engine_parameters()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(DemEngine, RunsTheProgramRunnerWithUnloadingBranches)
{
  // The engine plays a real program: isochoric shear with one branch from gamma = 0.4 %.
  DemEngine engine(consolidated().system, engine_parameters());
  LoadingProgram program;
  Stage stage;
  stage.name = "shear";
  stage.isochoric = true;
  stage.isochoric_rate = 1.0;
  stage.stop_any = {parse_condition("gamma_max >= 0.008", "test")};
  stage.max_duration = 0.05;
  stage.unload_at = {parse_trigger("gamma_max >= 0.004", "test")};
  program.stages = {stage};
  program.sample_interval = 0.0005;
  program.validate();
  ProgramRunner runner(program, engine);
  const Response r = runner.run();
  ASSERT_EQ(r.branches.size(), 1u);
  EXPECT_EQ(r.extras.size(), std::size_t(DemEngine::kExtraCount));
  EXPECT_LT(r.branches[0].residual_gamma, r.branches[0].gamma_start);
  EXPECT_GE(gamma_max(r.samples.back().strain), 0.008 - 1e-9);
}

TEST(DemEngine, CaseFileLawMapsOntoTheCore)
{
  ContactParameters c;
  c.model = "linear";
  c.youngs_modulus = 7e9;
  c.poisson_ratio = 0.25;
  c.impact_velocity = 1.0;
  c.restitution = 0.5;
  c.tangential_stiffness_ratio = 1.0;
  const ContactModel m = make_contact_model(c);
  const auto &law = std::get<LinearSpringDashpot>(m);
  // S0 k_n for two equal spheres R = 0.0118 m, rho = 2650.
  const double R = 0.0118, mass = 4.0 / 3.0 * M_PI * R * R * R * 2650.0;
  const double m_eff = 0.5 * mass, r_eff = 0.5 * R, e_star = c.youngs_modulus / (2.0 * (1.0 - 0.25 * 0.25));
  const double kn = 16.0 / 15.0 * std::sqrt(r_eff) * e_star *
                    std::pow(15.0 * m_eff * 1.0 / (16.0 * std::sqrt(r_eff) * e_star), 0.2); // S0
  EXPECT_NEAR(law.normal().stiffness(m_eff, r_eff), kn, 1e-9 * kn);
  const double cn = std::sqrt(4.0 * m_eff * kn / (1.0 + std::pow(M_PI / std::log(0.5), 2))); // S0
  EXPECT_NEAR(law.normal().damping(m_eff, kn), cn, 1e-9 * cn);
  c.model = "hertz-mindlin";
  EXPECT_TRUE(std::holds_alternative<HertzMindlin>(make_contact_model(c)));
  c.model = "plastic";
  EXPECT_THROW(make_contact_model(c), std::invalid_argument);

  DemParameters d;
  d.time_step_safety = 0.15;
  const Packing p = jittered_lattice(3, 0.01, 0.0, 0.05, 2000.0, 1);
  const DemSystem s = make_system(p, contact_parameters(), d);
  EXPECT_EQ(s.n_particles(), 27u);
  EXPECT_EQ(s.n_walls(), 6u);
  EXPECT_DOUBLE_EQ(s.time_step(), 0.15 * s.critical_time_step());
  EXPECT_DOUBLE_EQ(s.friction(), 0.4);
  EXPECT_THROW(DemEngine(DemSystem(), engine_parameters()), std::invalid_argument);
}

// `dem/threads = 0` (the default) gives the step the threads its size pays for: one for a
// small specimen, more for a large one (at most the OpenMP maximum, here set to 4); a count
// given overrides.
TEST(DemEngine, CaseThreadsZeroTakesTheThreadsTheSizePaysFor)
{
  const int old_max = omp_get_max_threads();
  omp_set_num_threads(4);
  DemParameters d;
  d.threads = 0;
  const Packing small = jittered_lattice(3, 0.01, 0.0, 0.05, 2000.0, 1);
  EXPECT_EQ(make_system(small, contact_parameters(), d).num_threads(), 1);
  const int edge = int(std::ceil(std::cbrt(2.0 * double(kMinParticlesPerThread))));
  const Packing large = jittered_lattice(edge, 0.01, 0.0, 0.05, 2000.0, 1);
  const int paid = int(std::min<std::size_t>(4, large.size() / kMinParticlesPerThread));
  EXPECT_GE(paid, 2);
  EXPECT_EQ(make_system(large, contact_parameters(), d).num_threads(), paid);
  d.threads = 3;
  EXPECT_EQ(make_system(small, contact_parameters(), d).num_threads(), 3);
  omp_set_num_threads(old_max);
}
