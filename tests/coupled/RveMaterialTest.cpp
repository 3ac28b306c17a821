// FEM x DEM at one element: the deal.II cube whose quadrature points each own a periodic DEM
// cell (coupled/RveMaterial.h) against the same cell driven alone by the same strain history.
#include "continuum/fe/CubeEngine.h"
#include "coupled/RveMaterial.h"
#include "coupled/RveMaterialFactory.h"
#include "tests/dem_periodic/TestCells.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace geocomp;
using namespace geocomp::coupled;

namespace {

const double pressure = 1e5; // [Pa]

/// A tiny consolidated RVE (60 spheres at 100 kPa), prepared once for every test.
const dem::PeriodicCell &prepared_rve()
{
  static const dem::PeriodicCell cell = [] {
    dem::test::RveSetup s;
    s.particles = 60;
    s.pressure = pressure;
    dem::test::Consolidated c = dem::test::consolidated_rve(s);
    if (!c.compression.converged)
      throw std::runtime_error("prepared_rve: the isotropic compression did not converge");
    return std::move(c.cell);
  }();
  return cell;
}

/// Every axis kinematic: the axial compression with lateral extension of a drained test.
Stage kinematic_stage()
{
  Stage st;
  st.name = "kinematic";
  st.axes = {{AxisDrive::rate(1.5e-3), AxisDrive::rate(1.0e-3), AxisDrive::rate(-5.0e-3)}};
  return st;
}

/// One trilinear element, small strain, one load step per sample.
continuum::CubeParameters single_element()
{
  continuum::CubeParameters c;
  c.side = 1.0;
  c.cells_per_side = 1;
  c.kinematics = continuum::Kinematics::small_strain;
  c.regularization = "none";
  c.steps_per_advance = 1;
  return c;
}

/// Triaxial compression: lateral walls under -p (tractions), the axial wall at -5e-3 /s.
Stage triaxial_stage()
{
  Stage st;
  st.name = "triaxial";
  st.axes = {{AxisDrive::stress(-pressure), AxisDrive::stress(-pressure), AxisDrive::rate(-5.0e-3)}};
  return st;
}

/// The single element for triaxial compression: every step to 1e-6 (no relaxed acceptance),
/// the walls starting at the RVE's preparation pressure.
continuum::CubeParameters triaxial_element()
{
  continuum::CubeParameters cp = single_element();
  cp.newton_tolerance = 1e-6;
  cp.newton_stagnation_factor = 0.0;
  cp.max_newton_iterations = 40;
  cp.initial_stress = -pressure;
  return cp;
}

struct CubeRun {
  std::vector<ResponseSample> samples;
  std::unique_ptr<continuum::CubeEngine> cube;
};

/// The single-element cube of RVEs under the kinematic stage, sampled at t = 0.2, 0.4, ... 1.
CubeRun run_cube(const std::shared_ptr<const RveMaterial> &rve, const Stage &stage)
{
  CubeRun r;
  r.cube = std::make_unique<continuum::CubeEngine>(single_element(), continuum::fixed_material(rve), MPI_COMM_WORLD);
  StageControl control;
  control.stage = &stage;
  r.cube->begin_control(control);
  for (int k = 1; k <= 5; ++k) {
    r.cube->advance_to(0.2 * k);
    r.samples.push_back(r.cube->measure());
  }
  return r;
}

} // namespace

TEST(RveMaterial, ASingleElementCubeOfRvesEqualsTheStandAloneRveUnderTheSameStrainHistory)
{
  RveParameters rp;
  rp.steps_per_increment = 200;
  const auto rve = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  const Stage stage = kinematic_stage();
  const auto t0 = std::chrono::steady_clock::now();
  const CubeRun fe = run_cube(rve, stage);
  const double fe_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(fe.cube->statistics().cutbacks, 0u);

  // The stand-alone RVE: the same increments of the program's strain, one per load step.
  StageControl control;
  control.stage = &stage;
  dem::PeriodicCell alone = prepared_rve();
  continuum::Vector6 previous = continuum::Vector6::Zero();
  double worst = 0.0;
  for (int k = 1; k <= 5; ++k) {
    continuum::Vector6 eps = continuum::Vector6::Zero();
    for (int a = 0; a < 3; ++a)
      eps[a] = control.strain(a, 0.2 * k);
    alone.set_velocity_gradient(RveMaterial::velocity_gradient(eps - previous, rp.steps_per_increment,
                                                               alone.parameters().time_step));
    alone.run(rp.steps_per_increment);
    previous = eps;
    const dem::Mat3 expected = alone.stress().total();
    const ResponseSample &s = fe.samples[k - 1];
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(s.strain(a, a), eps[a], 1e-15) << "sample " << k << " axis " << a;
      for (int b = 0; b < 3; ++b) {
        // Diagonal: the wall reactions over the face area; off-diagonal: the volume average.
        // Round-off only: the element's 8 Gauss points see the program's strain to within an
        // ulp (sums of shape-function gradients), which 1000 DEM steps amplify to ~1e-13 p.
        EXPECT_NEAR(s.stress(a, b), expected(a, b), 1e-11 * pressure) << "sample " << k << " (" << a << b << ")";
        worst = std::max(worst, std::abs(s.stress(a, b) - expected(a, b)) / pressure);
      }
    }
  }
  // The RVE carried load and the deviatoric loading changed its stress (not a trivial path).
  EXPECT_GT(-alone.stress().total()(2, 2), 1.2 * pressure);
  std::printf("single element of RVEs: %.2f s, largest |sigma_FE - sigma_RVE| / p = %.3g, sigma_zz = %.6g Pa\n",
              fe_seconds, worst, alone.stress().total()(2, 2));
}

// Through the constitutive interface with exactly the program's strains, the same bits as the
// stand-alone cell: a trial (a Newton iterate later cut back) leaves the committed cell as it was.
TEST(RveMaterial, ItsCommittedHistoryEqualsTheStandAloneRveBitForBitAndATrialLeavesItUntouched)
{
  RveParameters rp;
  rp.steps_per_increment = 150;
  const RveMaterial rve(prepared_rve(), rp);
  dem::PeriodicCell alone = prepared_rve();
  continuum::PlasticHistory committed = rve.initial_history(continuum::Vector6::Zero());
  const continuum::Vector6 rate = (continuum::Vector6() << 1e-3, -2e-3, -3e-3, 1e-3, 0.0, 5e-4).finished();
  for (int k = 1; k <= 4; ++k) {
    const continuum::Vector6 eps = (0.5 * k) * rate;
    const continuum::Vector6 before = RveMaterial::stress(static_cast<const RveState &>(*committed.state).cell);
    // A rejected iterate: twice the increment, then dropped.
    const continuum::MaterialPointUpdate rejected = rve.update(2.0 * eps - (0.5 * (k - 1)) * rate, committed);
    EXPECT_NE(rejected.stress, before);
    EXPECT_EQ(RveMaterial::stress(static_cast<const RveState &>(*committed.state).cell), before);
    const continuum::MaterialPointUpdate accepted = rve.update(eps, committed);
    committed = accepted.history; // commit

    alone.set_velocity_gradient(RveMaterial::velocity_gradient(eps - (0.5 * (k - 1)) * rate, rp.steps_per_increment,
                                                               alone.parameters().time_step));
    alone.run(rp.steps_per_increment);
    EXPECT_EQ(accepted.stress, RveMaterial::stress(alone)) << "increment " << k;
    // The tangent along the branch: the contact stiffness carrying the secant of the increment.
    const continuum::Vector6 step = eps - (0.5 * (k - 1)) * rate;
    EXPECT_EQ(accepted.tangent,
              RveMaterial::branch_tangent(RveMaterial::tangent(alone), step, RveMaterial::stress(alone) - before))
      << "increment " << k;
  }
  // An unchanged strain returns the committed state itself.
  const auto &last = static_cast<const RveState &>(*committed.state);
  const continuum::MaterialPointUpdate same = rve.update(last.strain, committed);
  EXPECT_EQ(same.history.state, committed.state);
}

// The cube's save()/restore() keep the RVEs (shared immutable committed states): a path
// replayed from a saved state gives the same bits as the first time.
TEST(RveMaterial, TheCubeReplaysARestoredPathOfRvesBitForBit)
{
  RveParameters rp;
  rp.steps_per_increment = 100;
  const auto rve = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  const Stage stage = kinematic_stage();
  continuum::CubeEngine cube(single_element(), continuum::fixed_material(rve), MPI_COMM_WORLD);
  StageControl control;
  control.stage = &stage;
  cube.begin_control(control);
  cube.advance_to(0.2);
  const std::unique_ptr<EngineState> saved = cube.save();
  std::vector<ResponseSample> first, second;
  for (int k = 2; k <= 3; ++k) {
    cube.advance_to(0.2 * k);
    first.push_back(cube.measure());
  }
  cube.restore(*saved);
  for (int k = 2; k <= 3; ++k) {
    cube.advance_to(0.2 * k);
    second.push_back(cube.measure());
  }
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ(first[k].time, second[k].time);
    EXPECT_EQ(first[k].stress, second[k].stress) << "sample " << k;
  }
  EXPECT_GT(-first.back().stress(2, 2), pressure); // loaded beyond the preparation
}

// Triaxial compression of one element of RVEs: lateral walls under -p (tractions), the axial
// wall kinematic. Free dofs make the Newton work with the contact-stiffness tangent (a
// quasi-Newton: linear convergence); every step must reach the tolerance (no relaxed
// acceptance), the lateral walls then carry -p and the axial stress rises above p.
TEST(RveMaterial, ATriaxialElementOfRvesConvergesWithTheContactStiffnessTangentAndHoldsItsLateralStress)
{
  RveParameters rp;
  rp.steps_per_increment = 100;
  rp.tangent = RveTangent::contact_stiffness;
  const auto rve = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  const Stage stage = triaxial_stage();
  continuum::CubeEngine cube(triaxial_element(), continuum::fixed_material(rve), MPI_COMM_WORLD);
  StageControl control;
  control.stage = &stage;
  cube.begin_control(control);
  double previous_axial = -pressure;
  for (int k = 1; k <= 2; ++k) {
    cube.advance_to(0.25 * k);
    const ResponseSample s = cube.measure();
    std::printf("sample %d: Newton iterations per step %.1f, steps %.0f, cut-backs %.0f, eps = (%.4g, %.4g, %.4g), "
                "sigma = (%.6g, %.6g, %.6g) Pa\n",
                k, s.extras[0], s.extras[1], s.extras[2], s.strain(0, 0), s.strain(1, 1), s.strain(2, 2),
                s.stress(0, 0), s.stress(1, 1), s.stress(2, 2));
    EXPECT_EQ(s.extras[3], 0.0); // no relaxed step
    for (int a = 0; a < 2; ++a) {
      EXPECT_NEAR(s.stress(a, a), -pressure, 1e-5 * pressure) << "sample " << k << " axis " << a;
      EXPECT_GT(s.strain(a, a), 0.0) << "sample " << k << " axis " << a; // the sides bulge
    }
    EXPECT_LT(s.stress(2, 2), previous_axial) << "sample " << k; // the deviator grows
    previous_axial = s.stress(2, 2);
  }
}

// The same triaxial element with the BFGS pairs of each step's iterations on the
// contact-stiffness tangent (continuum/fe/SecantPairs.h, the fem-dem engine's Newton): the
// same tolerance in fewer iterations, hence fewer RVE runs, and the same stresses to within
// what the tolerance and the cells' different iterates allow.
TEST(RveMaterial, SecantPairsReachTheTriaxialElementsToleranceInFewerIterationsAndRveRuns)
{
  RveParameters rp;
  rp.steps_per_increment = 100;
  rp.tangent = RveTangent::contact_stiffness;
  const auto rve = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  const Stage stage = triaxial_stage();
  struct Run {
    ResponseSample last;
    continuum::CubeStatistics stats;
  };
  const auto run = [&](unsigned pairs) {
    continuum::CubeParameters cp = triaxial_element();
    cp.stall_iterations = 5;
    cp.secant_pairs = pairs;
    continuum::CubeEngine cube(cp, continuum::fixed_material(rve), MPI_COMM_WORLD);
    StageControl control;
    control.stage = &stage;
    cube.begin_control(control);
    cube.advance_to(0.25);
    cube.advance_to(0.5);
    return Run{cube.measure(), cube.statistics()};
  };
  const Run newton = run(0), secant = run(8);
  std::printf("Newton iterations %u against %u, RVE runs %lu against %lu, cut-backs %u against %u\n",
              newton.stats.newton_iterations, secant.stats.newton_iterations, newton.stats.material_updates,
              secant.stats.material_updates, newton.stats.cutbacks, secant.stats.cutbacks);
  EXPECT_LT(secant.stats.newton_iterations, 0.7 * newton.stats.newton_iterations);
  EXPECT_LT(secant.stats.material_updates, newton.stats.material_updates);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(secant.last.stress(a, a), newton.last.stress(a, a), 2e-3 * pressure) << "axis " << a;
  EXPECT_NEAR(secant.last.stress(0, 0), -pressure, 1e-5 * pressure);
}

// Finite strain: the single element's Gauss points see F = diag(1 + eps_a) (every axis
// kinematic, so F is the program's); the stand-alone cell driven by ln(F_k F_{k-1}^-1)/(n dt)
// per load step is the same RVE, and the element's Cauchy wall stress is its stress.
TEST(RveMaterial, ASingleElementCubeOfRvesAtFiniteStrainEqualsTheStandAloneRveDrivenByTheSameDeformation)
{
  RveParameters rp;
  rp.steps_per_increment = 200;
  const auto rve = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  const Stage stage = kinematic_stage();
  continuum::CubeParameters cp = single_element();
  cp.kinematics = continuum::Kinematics::finite_strain;
  continuum::CubeEngine cube(cp, continuum::fixed_material(rve), MPI_COMM_WORLD);
  StageControl control;
  control.stage = &stage;
  cube.begin_control(control);

  dem::PeriodicCell alone = prepared_rve();
  continuum::Matrix3 previous = continuum::Matrix3::Identity();
  double worst = 0.0;
  for (int k = 1; k <= 5; ++k) {
    cube.advance_to(0.2 * k);
    const ResponseSample s = cube.measure();
    continuum::Matrix3 F = continuum::Matrix3::Identity();
    for (int a = 0; a < 3; ++a)
      F(a, a) += s.strain(a, a); // the box's engineering strain: exact on kinematic faces
    alone.set_velocity_gradient(RveMaterial::finite_velocity_gradient(F * previous.inverse(), rp.steps_per_increment,
                                                                      alone.parameters().time_step));
    alone.run(rp.steps_per_increment);
    previous = F;
    // The cell followed F: H = F H_0 to round-off.
    EXPECT_LT((alone.cell().h() - F * prepared_rve().cell().h()).norm(), 1e-12 * prepared_rve().cell().h().norm());
    const dem::Mat3 expected = alone.stress().total();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        EXPECT_NEAR(s.stress(a, b), expected(a, b), 1e-10 * pressure) << "sample " << k << " (" << a << b << ")";
        worst = std::max(worst, std::abs(s.stress(a, b) - expected(a, b)) / pressure);
      }
  }
  EXPECT_EQ(cube.statistics().cutbacks, 0u);
  EXPECT_GT(-alone.stress().total()(2, 2), 1.2 * pressure);
  std::printf("finite strain, single element of RVEs: largest |sigma_FE - sigma_RVE| / p = %.3g\n", worst);
}

// The rate form's spatial tangent (PointStateModel.h) is d tau - tau H^T for a pure spin
// (a rotation of tau) and for a stretch (J C : D + tau tr D - tau D).
TEST(RveMaterial, TheJaumannSpatialTangentRotatesTheKirchhoffStressUnderAPureSpin)
{
  continuum::Matrix3 tau;
  tau << -3.0, 0.4, 0.1, 0.4, -2.0, -0.3, 0.1, -0.3, -1.0;
  continuum::Matrix6 C = continuum::Matrix6::Identity() * 7.0;
  const double J = 1.1;
  const continuum::Matrix9 a = continuum::jaumann_spatial_tangent(C, tau, J);
  const auto apply = [&a](const continuum::Matrix3 &H) {
    continuum::Matrix3 out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        out(i, j) = 0.0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            out(i, j) += a(continuum::pair_index(i, j), continuum::pair_index(k, l)) * H(k, l);
      }
    return out;
  };
  continuum::Matrix3 W;
  W << 0.0, 0.2, -0.1, -0.2, 0.0, 0.3, 0.1, -0.3, 0.0;
  EXPECT_LT((apply(W) - W * tau).norm(), 1e-14 * tau.norm()); // (J a) : W = W tau
  continuum::Matrix3 D;
  D << 0.1, 0.05, 0.0, 0.05, -0.2, 0.02, 0.0, 0.02, 0.3;
  const continuum::Matrix3 expected = J * 7.0 * D + tau * D.trace() - tau * D; // C = 7 I (Mandel)
  EXPECT_LT((apply(D) - expected).norm(), 1e-14 * expected.norm());
}

// A stressed cell turned by a finite rotation at finite strain: its stress turns with it.
// The 60-sphere cell is not at rest after the 1 % compression that gives it a deviator (it
// relaxes over the next steps whatever the rotation), so the rotated cell is compared with
// the same cell held still for the same steps (a rotation of 1e-12 rad, which makes the
// model run them): sigma_turned = R sigma_still R^T up to what the fluctuating velocities,
// stored in the lab frame, do not turn. Without the affine spin of the grains
// (PeriodicContactPass.h) the rotation would load every tangential spring.
TEST(RveMaterial, AStressedRveTurnedByAFiniteRotationCarriesItsStressRound)
{
  RveParameters rp;
  rp.steps_per_increment = 400;
  const RveMaterial rve(prepared_rve(), rp);
  const auto rotation = [](double angle) {
    continuum::Matrix3 R = continuum::Matrix3::Identity();
    R(0, 0) = R(2, 2) = std::cos(angle);
    R(0, 2) = std::sin(angle);
    R(2, 0) = -std::sin(angle);
    return R;
  };
  // 1 % axial compression at constant volume, then three turns of theta / 3 about y.
  const auto turned = [&](double theta) {
    continuum::FiniteStrainHistory h = continuum::initial_finite_strain_history(rve, continuum::Matrix3::Zero());
    continuum::Matrix3 F = continuum::Matrix3::Identity();
    F(2, 2) = 0.99;
    F(0, 0) = F(1, 1) = 1.0 / std::sqrt(0.99);
    h = continuum::finite_strain_update(rve, F, h).history;
    std::vector<continuum::Matrix3> sigma;
    for (int k = 1; k <= 3; ++k) {
      const continuum::FiniteStrainUpdate u = continuum::finite_strain_update(rve, rotation(theta * k / 3.0) * F, h);
      h = u.history;
      EXPECT_NEAR(u.jacobian, 1.0, 1e-14);
      sigma.push_back(u.cauchy_stress());
    }
    return sigma;
  };
  const double theta = 30.0 * M_PI / 180.0;
  const std::vector<continuum::Matrix3> still = turned(1e-12), turn = turned(theta);
  double worst = 0.0, deviator = 0.0;
  for (int k = 0; k < 3; ++k) {
    const continuum::Matrix3 R = rotation(theta * (k + 1) / 3.0);
    worst = std::max(worst, (turn[k] - R * still[k] * R.transpose()).cwiseAbs().maxCoeff() / pressure);
    const continuum::Matrix3 s = still[k];
    deviator = std::max(deviator, (s - s.trace() / 3.0 * continuum::Matrix3::Identity()).cwiseAbs().maxCoeff() / pressure);
  }
  std::printf("rotated RVE: deviator %.4g p, largest |sigma_turned - R sigma_still R^T| / p = %.3g\n", deviator, worst);
  EXPECT_GT(deviator, 0.05); // a stress with a direction to turn
  EXPECT_LT(worst, 0.02);
}

// The imperfection of an FE mesh of RVEs: the same prepared cell with the grains' friction
// times the factor, which carries less deviator under the same deformation.
TEST(RveMaterialFactory, TheWeakVariantIsTheSameCellWithLowerGrainFrictionAndCarriesLessDeviator)
{
  RveParameters rp;
  rp.steps_per_increment = 300;
  const auto base = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  const RveMaterialFactory factory(base);
  continuum::MaterialVariant weak_variant;
  weak_variant.cohesion_factor = 0.5;
  weak_variant.softening_scale = 3.0; // no meaning for a cell: ignored
  const auto weak = std::dynamic_pointer_cast<const RveMaterial>(factory.make(weak_variant));
  ASSERT_TRUE(weak);
  EXPECT_EQ(factory.make(continuum::MaterialVariant{}), base);
  EXPECT_EQ(weak->prepared().parameters().friction, 0.5 * base->prepared().parameters().friction);
  EXPECT_EQ(weak->prepared().n_particles(), base->prepared().n_particles());
  EXPECT_EQ(weak->prepared().cell().h(), base->prepared().cell().h());
  EXPECT_EQ(weak->parameters().steps_per_increment, rp.steps_per_increment);
  // 3 % isochoric compression in three increments: the deviator each carries at the end.
  const auto deviator = [](const RveMaterial &m) {
    continuum::FiniteStrainHistory h = continuum::initial_finite_strain_history(m, continuum::Matrix3::Zero());
    continuum::FiniteStrainUpdate u;
    for (int k = 1; k <= 3; ++k) {
      continuum::Matrix3 F = continuum::Matrix3::Identity();
      F(2, 2) = 1.0 - 0.01 * k;
      F(0, 0) = F(1, 1) = 1.0 / std::sqrt(F(2, 2));
      u = continuum::finite_strain_update(m, F, h);
      h = u.history;
    }
    const continuum::Matrix3 s = u.cauchy_stress();
    return s(0, 0) - s(2, 2);
  };
  const double q_base = deviator(*base), q_weak = deviator(*weak);
  std::printf("deviator at 3 %% isochoric compression: mu %.2f -> %.4g p, mu %.2f -> %.4g p\n",
              base->prepared().parameters().friction, q_base / pressure, weak->prepared().parameters().friction,
              q_weak / pressure);
  EXPECT_GT(q_base, 0.0);
  EXPECT_LT(q_weak, 0.9 * q_base);
}

// Threads over the points (CubeParameters::threads): a two-element box of RVEs under the
// triaxial program at finite strain gives the same bits on 1 and on 3 threads.
TEST(RveMaterial, TheUpdatesOfAMeshOfRvesOnThreadsGiveTheSerialBits)
{
  RveParameters rp;
  rp.steps_per_increment = 100;
  const auto rve = std::make_shared<const RveMaterial>(prepared_rve(), rp);
  Stage stage;
  stage.name = "triaxial";
  stage.axes = {{AxisDrive::stress(-pressure), AxisDrive::rate(0.0), AxisDrive::rate(-5.0e-3)}};
  const auto run = [&](unsigned threads) {
    continuum::CubeParameters cp = single_element();
    cp.kinematics = continuum::Kinematics::finite_strain;
    cp.box_edges = continuum::Vector3(1.0, 1.0, 2.0);
    cp.box_cells = {{1, 1, 2}};
    cp.initial_stress = -pressure;
    cp.newton_tolerance = 1e-6;
    cp.max_newton_iterations = 40;
    cp.threads = threads;
    continuum::CubeEngine cube(cp, std::make_shared<RveMaterialFactory>(rve), MPI_COMM_WORLD);
    StageControl control;
    control.stage = &stage;
    cube.begin_control(control);
    cube.advance_to(0.25);
    return std::make_pair(cube.measure(), cube.statistics().newton_iterations);
  };
  const auto serial = run(1), threaded = run(3);
  EXPECT_EQ(serial.first.stress, threaded.first.stress);
  EXPECT_EQ(serial.first.strain, threaded.first.strain);
  EXPECT_EQ(serial.second, threaded.second);
  EXPECT_LT(serial.first.stress(2, 2), -pressure); // loaded
  std::printf("two elements of RVEs, 1 and 3 threads: %u Newton iterations, sigma_zz = %.9g Pa\n", serial.second,
              serial.first.stress(2, 2));
}
