// The deal.II cube under the ProgramRunner: closed-form elastic states, the homogeneous
// plastic cube against the material point, Newton's convergence rate with the consistent
// tangent, exact save/restore, and mesh convergence of the regularized post-peak curve.
#include "EngineTestSupport.h"

#include "common/ElasticLimitBracket.h"
#include "common/ProgramRunner.h"
#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/fe/CubeEngine.h"
#include "continuum/fe/RigidBodyModes.h"
#include "continuum/models/MohrCoulombModel.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/base/quadrature_lib.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <map>
#include <string>

using namespace geocomp;
using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {
const double E = 1.0e8, nu = 0.3, p = 1.0e5;
const double G = E / (2.0 * (1.0 + nu)), lambda_L = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));

std::shared_ptr<const MaterialFactory> elastic()
{
  return fixed_material(std::make_shared<LinearElasticModel>(E, nu));
}

CubeParameters small_cube(unsigned n, unsigned degree = 1)
{
  CubeParameters c;
  c.cells_per_side = n;
  c.degree = degree;
  c.newton_tolerance = 1e-10;
  c.linear_tolerance = 1e-12;
  return c;
}

LoadingProgram triaxial(double strain, double interval = 0.5)
{
  LoadingProgram program;
  program.sample_interval = interval;
  program.stages = {isotropic_stage(p, 1.0), triaxial_stage(p, 1e-3, strain)};
  program.validate();
  return program;
}

/// Elastic triaxial state with sigma_xx = sigma_yy = -p at the axial strain eps_zz: the
/// lateral strain and sigma_zz. Small strain: eps_xx = (-p - lambda eps_zz) / (2 (lambda + G)),
/// sigma_zz = lambda (2 eps_xx + eps_zz) + 2 G eps_zz. Finite strain (Hencky, tau = lambda tr(e) 1
/// + 2 G e in the log strains e, sigma = tau / J, J = exp(tr e)): e_x solves
/// lambda (2 e_x + e_z) + 2 G e_x = -p exp(2 e_x + e_z) (scalar Newton).
std::pair<double, double> elastic_triaxial(Kinematics kinematics, double eps_zz)
{
  if (kinematics == Kinematics::small_strain) {
    const double ex = (-p - lambda_L * eps_zz) / (2.0 * (lambda_L + G));
    return {ex, lambda_L * (2.0 * ex + eps_zz) + 2.0 * G * eps_zz};
  }
  const double ez = std::log1p(eps_zz);
  double ex = 0.0;
  for (int it = 0; it < 50; ++it) {
    const double J = std::exp(2.0 * ex + ez);
    const double r = lambda_L * (2.0 * ex + ez) + 2.0 * G * ex + p * J;
    ex -= r / (2.0 * lambda_L + 2.0 * G + 2.0 * p * J);
  }
  const double J = std::exp(2.0 * ex + ez);
  return {std::expm1(ex), (lambda_L * (2.0 * ex + ez) + 2.0 * G * ez) / J};
}

/// Index of an engine's extra column.
std::size_t column(const LoadingEngine &engine, const std::string &name)
{
  const auto columns = engine.extra_columns();
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k].name == name)
      return k;
  throw std::invalid_argument("no extra column " + name);
}

/// Softening Mohr-Coulomb: c from c0 at kappa = 0.002 down to 0.2 c0 at kappa = 0.02.
MohrCoulombParameters softening_material()
{
  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(5));
  m.cohesion = PiecewiseLinear({0.0, 0.002, 0.02}, {20e3, 20e3, 4e3});
  return m;
}

/// Plane strain compression: x held at -p, y fixed, z shortened to eps_zz = -strain.
LoadingProgram plane_strain(double strain, double interval)
{
  LoadingProgram program;
  program.sample_interval = interval;
  Stage s = triaxial_stage(p, 1e-3, strain);
  s.name = "plane strain";
  s.axes[1] = AxisDrive::rate(0.0);
  program.stages = {isotropic_stage(p, 1.0), s};
  program.validate();
  return program;
}
/// Every shear-stage sample of `r` is the closed-form elastic triaxial state (to 1e-8);
/// returns how many were checked.
int expect_elastic_triaxial(const Response &r, Kinematics kinematics, const std::string &label)
{
  int checked = 0;
  for (const auto &s : r.samples) {
    if (s.stage != 1)
      continue;
    const auto [ex, sz] = elastic_triaxial(kinematics, s.strain(2, 2));
    EXPECT_NEAR(s.strain(0, 0) / ex, 1.0, 1e-8) << to_string(kinematics) << " " << label << " t " << s.time;
    EXPECT_NEAR(s.strain(1, 1) / ex, 1.0, 1e-8);
    EXPECT_NEAR(s.stress(0, 0) / -p, 1.0, 1e-8);
    EXPECT_NEAR(s.stress(1, 1) / -p, 1.0, 1e-8);
    EXPECT_NEAR(s.stress(2, 2) / sz, 1.0, 1e-8);
    EXPECT_NEAR(s.stress(0, 1) / p, 0.0, 1e-8);
    ++checked;
  }
  return checked;
}
} // namespace

TEST(CubeEngine, ElasticTriaxialMatchesClosedFormOnQ1AndQ2)
{
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain})
    for (unsigned degree : {1u, 2u}) {
      CubeParameters cp = small_cube(3, degree);
      cp.kinematics = kinematics;
      CubeEngine engine(cp, elastic(), MPI_COMM_WORLD);
      const Response r = ProgramRunner(triaxial(0.004), engine).run();
      EXPECT_GE(expect_elastic_triaxial(r, kinematics, "degree " + std::to_string(degree)), 7);
      // Small strain is linear: every load step converges in the predictor solve.
      if (kinematics == Kinematics::small_strain) {
        EXPECT_EQ(engine.statistics().newton_iterations, engine.statistics().steps);
      }
    }
}

TEST(CubeEngine, ElasticUniaxialStrainMatchesOedometricModulus)
{
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    CubeParameters cp = small_cube(2);
    cp.kinematics = kinematics;
    CubeEngine engine(cp, elastic(), MPI_COMM_WORLD);
    LoadingProgram program;
    program.sample_interval = 0.5;
    Stage s;
    s.name = "oedometer";
    s.axes = {{AxisDrive::rate(0.0), AxisDrive::rate(0.0), AxisDrive::rate(-1e-3)}};
    s.stop_any = {parse_condition("eps_zz <= -0.002", "test")};
    s.max_duration = 10.0;
    program.stages = {s};
    const Response r = ProgramRunner(program, engine).run();
    const ResponseSample &last = r.samples.back();
    EXPECT_NEAR(last.strain(2, 2), -0.002, 1e-15);
    // sigma_zz = (lambda + 2G) e_zz (oedometric modulus K + 4G/3), sigma_xx = lambda e_zz, with
    // e_zz = eps_zz at small strain; at finite strain (Hencky) e_zz = ln(1 + eps_zz) and the
    // Cauchy stress is tau / J, J = 1 + eps_zz.
    const bool finite = kinematics == Kinematics::finite_strain;
    const double e = finite ? std::log1p(-0.002) : -0.002, J = finite ? 1.0 - 0.002 : 1.0;
    EXPECT_NEAR(last.stress(2, 2) / ((lambda_L + 2.0 * G) * e / J), 1.0, 1e-9) << to_string(kinematics);
    EXPECT_NEAR(last.stress(0, 0) / (lambda_L * e / J), 1.0, 1e-9);
    EXPECT_NEAR(last.stress(1, 1) / (lambda_L * e / J), 1.0, 1e-9);
  }
}

TEST(CubeEngine, FirstSampleCarriesTheInitialStress)
{
  // The walls hold the initial isotropic stress before any load step (the first sample
  // once reported zero wall stress).
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    CubeParameters cp = small_cube(2);
    cp.kinematics = kinematics;
    cp.initial_stress = -p;
    CubeEngine engine(cp, elastic(), MPI_COMM_WORLD);
    const Response r = ProgramRunner(s0_isochoric(0.01, 0.05), engine).run();
    ASSERT_GT(r.samples.size(), 2u);
    EXPECT_EQ(r.samples.front().time, 0.0);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(r.samples.front().stress(a, a) / -p, 1.0, 1e-12) << to_string(kinematics) << " axis " << a;
  }
}

TEST(CubeEngine, MidPlaneShowsTheHomogeneousDisplacementAndPlasticStrain)
{
  // Homogeneous deformation of the cube [0, L]^3 with the lower faces held: on the plane
  // y = L/2 the displacement is u_a = eps_a x_a, and kappa is the same everywhere.
  const MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(10));
  const CubeParameters cp = small_cube(2);
  CubeEngine cube(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const Response r = ProgramRunner(triaxial(0.01), cube).run();
  const ResponseSample &last = r.samples.back();
  const MidPlaneSample plane = cube.mid_plane();
  ASSERT_EQ(plane.x.size(), 2u * 2u * 9u); // the plane cuts the upper layer of a 2^3 mesh
  for (std::size_t k = 0; k < plane.x.size(); ++k) {
    EXPECT_NEAR(plane.ux[k], last.strain(0, 0) * plane.x[k], 1e-9 * cp.side) << k;
    EXPECT_NEAR(plane.uz[k], last.strain(2, 2) * plane.z[k], 1e-9 * cp.side) << k;
    EXPECT_NEAR(plane.kappa[k], plane.kappa[0], 1e-9) << k;
  }
  EXPECT_GT(plane.kappa[0], 1e-3); // past the peak of the triaxial program
}

TEST(CubeEngine, HomogeneousPlasticCubeEqualsMaterialPointAndPeak)
{
  const MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(10));
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    CubeParameters cp = small_cube(2);
    cp.kinematics = kinematics;
    CubeEngine cube(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
    MaterialPointParameters mpp;
    mpp.substeps_per_advance = 2; // the cube's load steps
    mpp.kinematics = kinematics;
    MaterialPointEngine point(std::make_shared<MohrCoulombModel>(m), mpp);
    const LoadingProgram program = triaxial(0.01);
    const Response rc = ProgramRunner(program, cube).run();
    const Response rp = ProgramRunner(program, point).run();
    ASSERT_EQ(rc.samples.size(), rp.samples.size());
    // On the sigma_xx = sigma_yy corner the split of the lateral strain between x and y is
    // indeterminate (no stress changes with it), so the cube may split it differently from
    // the point; the stresses, the axial strain and the lateral sum are determined (the sum
    // of the logarithmic strains at finite strain, where the flow is additive in them).
    auto lateral = [&](const ResponseSample &s) {
      if (kinematics == Kinematics::small_strain)
        return s.strain(0, 0) + s.strain(1, 1);
      return std::log1p(s.strain(0, 0)) + std::log1p(s.strain(1, 1));
    };
    for (std::size_t k = 0; k < rc.samples.size(); ++k) {
      const ResponseSample &a = rc.samples[k], &b = rp.samples[k];
      EXPECT_LT((a.stress - b.stress).norm(), 1e-7 * p) << to_string(kinematics) << " sample " << k;
      EXPECT_NEAR(a.strain(2, 2), b.strain(2, 2), 1e-12) << "sample " << k;
      EXPECT_NEAR(lateral(a), lateral(b), 1e-9) << to_string(kinematics) << " sample " << k;
    }
    // sigma_1 = sigma_3 N_phi + 2 (c / J) sqrt(N_phi) (compression positive; J = 1 at small
    // strain; at finite strain the surface is on the Kirchhoff stress J sigma).
    const ResponseSample &last = rc.samples.back();
    const double J = kinematics == Kinematics::finite_strain ? volumetric_strain(last.strain) + 1.0 : 1.0;
    const double peak = -(p * N_of(deg(30)) + 2.0 * (20e3 / J) * std::sqrt(N_of(deg(30))));
    EXPECT_NEAR(last.stress(2, 2) / peak, 1.0, 1e-8) << to_string(kinematics);
  }
}

// A box of unequal edges and cells (the biaxial specimen's mesh: continuum/box edges, box
// cells): its walls, face areas and box strains are the box's, so a homogeneous plastic box
// is the material point as the cube is.
TEST(CubeEngine, AHomogeneousPlasticBoxOfUnequalEdgesAndCellsEqualsTheMaterialPoint)
{
  const MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(10));
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    CubeParameters cp = small_cube(1);
    cp.kinematics = kinematics;
    cp.box_edges = Vector3(0.5, 0.125, 1.0);
    cp.box_cells = {{2, 1, 4}};
    CubeEngine box(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
    EXPECT_NEAR(box.element_size(), std::cbrt(0.25 * 0.125 * 0.25), 1e-15);
    MaterialPointParameters mpp;
    mpp.substeps_per_advance = 2;
    mpp.kinematics = kinematics;
    MaterialPointEngine point(std::make_shared<MohrCoulombModel>(m), mpp);
    const LoadingProgram program = triaxial(0.01);
    const Response rb = ProgramRunner(program, box).run();
    const Response rp = ProgramRunner(program, point).run();
    ASSERT_EQ(rb.samples.size(), rp.samples.size());
    const auto lateral = [&](const ResponseSample &s) {
      return kinematics == Kinematics::small_strain ? s.strain(0, 0) + s.strain(1, 1)
                                                    : std::log1p(s.strain(0, 0)) + std::log1p(s.strain(1, 1));
    };
    for (std::size_t k = 0; k < rb.samples.size(); ++k) {
      const ResponseSample &a = rb.samples[k], &b = rp.samples[k];
      EXPECT_LT((a.stress - b.stress).norm(), 1e-7 * p) << to_string(kinematics) << " sample " << k;
      EXPECT_NEAR(a.strain(2, 2), b.strain(2, 2), 1e-12) << to_string(kinematics) << " sample " << k;
      EXPECT_NEAR(lateral(a), lateral(b), 1e-9) << to_string(kinematics) << " sample " << k;
    }
    EXPECT_LT(rb.samples.back().stress(2, 2), -2.0 * p); // loaded past yield
  }
}

// The plane-strain slab's rule (continuum/quadrature points = 3, 2, 3 on Q2: two Gauss points
// across the thickness, GaussPoints.h): a Q2 box under it keeps the closed-form homogeneous
// elastic triaxial state, and updates 18 points an element, not 27.
TEST(CubeEngine, AQ2BoxWithTwoGaussPointsAcrossItsThicknessKeepsTheClosedFormAndUpdatesEighteenAnElement)
{
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    CubeParameters cp = small_cube(1, 2);
    cp.kinematics = kinematics;
    cp.box_edges = Vector3(0.5, 0.125, 1.0);
    cp.box_cells = {{2, 1, 4}};
    cp.quadrature_points = {{3, 2, 3}};
    CubeEngine box(cp, elastic(), MPI_COMM_WORLD);
    const Response r = ProgramRunner(triaxial(0.004), box).run();
    EXPECT_GE(expect_elastic_triaxial(r, kinematics, "Q2, 3 x 2 x 3 Gauss points"), 7);
    // The same passes with the full rule update 27 points an element.
    cp.quadrature_points = {{0, 0, 0}};
    CubeEngine full(cp, elastic(), MPI_COMM_WORLD);
    ProgramRunner(triaxial(0.004), full).run();
    const CubeStatistics &a = box.statistics(), &b = full.statistics();
    ASSERT_EQ(a.residual_assemblies, b.residual_assemblies) << to_string(kinematics);
    ASSERT_EQ(a.steps + a.cutbacks, b.steps + b.cutbacks) << to_string(kinematics);
    EXPECT_EQ(27 * a.material_updates, 18 * b.material_updates) << to_string(kinematics);
    EXPECT_GT(a.material_updates, 0ul);
  }
}

TEST(CubeEngine, NewtonConvergesQuadraticallyOnPlasticSteps)
{
  // An imperfect cube: the plastic zone is not homogeneous, so the global tangent matters.
  CubeParameters cp = small_cube(4);
  cp.linear_solver = "direct"; // exact linear solves: the rate is Newton's alone
  cp.steps_per_advance = 1;
  cp.newton_tolerance = 1e-11;
  cp.imperfection_radius = 0.3;
  cp.imperfection_cohesion_factor = 0.8;
  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(5));
  m.cohesion = PiecewiseLinear({0.0, 0.01}, {20e3, 30e3}); // hardening
  CubeEngine engine(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  unsigned worst = 0, plastic_steps = 0, quadratic_pairs = 0;
  double worst_order = 10.0;
  const LoadingProgram program = plane_strain(0.006, 0.5);
  ProgramRunner runner(program, engine);
  runner.on_progress([&](const RunProgress &progress) {
    const CubeStatistics &st = engine.statistics();
    if (progress.stage != 1 || progress.sample->extras[column(engine, "plastic_fraction")] == 0.0)
      return;
    ++plastic_steps;
    worst = std::max(worst, st.last_step_iterations);
    const auto &r = st.last_step_residuals;
    for (std::size_t k = 0; k + 1 < r.size(); ++k)
      if (r[k] < 1e-2 && r[k + 1] > 1e-12) { // in the asymptotic range, above round-off (the
                                             // logarithms of FiniteStrain.h: ~1e-13)
        worst_order = std::min(worst_order, std::log(r[k + 1]) / std::log(r[k]));
        ++quadratic_pairs;
      }
  });
  runner.run();
  std::printf("plastic steps %u, most Newton iterations %u, %u asymptotic pairs, lowest order %.2f\n",
              plastic_steps, worst, quadratic_pairs, worst_order);
  EXPECT_GE(plastic_steps, 5u);
  EXPECT_LE(worst, 6u);
  EXPECT_GE(quadratic_pairs, 3u);
  EXPECT_GT(worst_order, 1.7) << "Newton lost its quadratic rate";
}

// Each point memorizes its last update (CubeEngineImpl.h, Memo): the tangent Newton assembles
// at the iterate whose residual the line search has just evaluated takes those updates, so a
// point is updated once per predictor (the committed state of each step tried) and once per
// residual assembly, never for a tangent. Counted on plastic steps of an imperfect cube,
// where every step needs correctors (whose tangents would otherwise cost a pass each).
TEST(CubeEngine, TheTangentAtAnIterateTheLineSearchEvaluatedCostsNoMaterialUpdate)
{
  CubeParameters cp = small_cube(4);
  cp.steps_per_advance = 1;
  cp.imperfection_radius = 0.3;
  cp.imperfection_cohesion_factor = 0.8;
  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(5));
  m.cohesion = PiecewiseLinear({0.0, 0.01}, {20e3, 30e3});
  CubeEngine engine(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const LoadingProgram program = plane_strain(0.006, 0.5);
  ProgramRunner runner(program, engine);
  runner.run();
  const CubeStatistics &st = engine.statistics();
  const unsigned long points = 4 * 4 * 4 * 8, predictors = st.steps + st.cutbacks;
  std::printf("steps %u, cut-backs %u, Newton iterations %u, residual assemblies %lu, material updates %lu\n",
              st.steps, st.cutbacks, st.newton_iterations, st.residual_assemblies, st.material_updates);
  EXPECT_GT(st.newton_iterations, st.steps + 5); // correctors: tangents at evaluated iterates
  EXPECT_EQ(st.material_updates, points * (predictors + st.residual_assemblies));
}

TEST(CubeEngine, BBarKeepsHomogeneousStatesAndNewtonsQuadraticRate)
{
  // B-bar only replaces the volumetric strain by its cell average, so (1) a homogeneous
  // elastic triaxial state is reproduced exactly, and (2) with the B-bar tangent Newton
  // stays quadratic on the imperfect plastic cube, whose heterogeneous field B-bar does
  // change (the curve differs from full integration).
  CubeParameters elastic_cube = small_cube(3);
  elastic_cube.volumetric_integration = "b-bar";
  elastic_cube.kinematics = Kinematics::small_strain; // b-bar is a small-strain method
  CubeEngine homogeneous(elastic_cube, elastic(), MPI_COMM_WORLD);
  const Response e = ProgramRunner(triaxial(0.004), homogeneous).run();
  const double ez = e.samples.back().strain(2, 2);
  const double ex = (-p - lambda_L * ez) / (2.0 * (lambda_L + G));
  EXPECT_NEAR(e.samples.back().strain(0, 0) / ex, 1.0, 1e-8);
  EXPECT_NEAR(e.samples.back().stress(2, 2) / (lambda_L * (2.0 * ex + ez) + 2.0 * G * ez), 1.0, 1e-8);

  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(5));
  m.cohesion = PiecewiseLinear({0.0, 0.01}, {20e3, 30e3}); // hardening
  std::map<std::string, Response> runs;
  for (const std::string integration : {"full", "b-bar"}) {
    CubeParameters cp = small_cube(4);
    cp.linear_solver = "direct";
    cp.steps_per_advance = 1;
    cp.newton_tolerance = 1e-11;
    cp.imperfection_radius = 0.3;
    cp.imperfection_cohesion_factor = 0.8;
    cp.volumetric_integration = integration;
    cp.kinematics = Kinematics::small_strain;
    CubeEngine engine(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
    const LoadingProgram program = plane_strain(0.006, 0.5); // the runner keeps a reference
    ProgramRunner runner(program, engine);
    double worst_order = 10.0;
    unsigned pairs = 0, worst = 0;
    runner.on_progress([&](const RunProgress &progress) {
      if (progress.stage != 1 || progress.sample->extras[column(engine, "plastic_fraction")] == 0.0)
        return;
      const CubeStatistics &st = engine.statistics();
      worst = std::max(worst, st.last_step_iterations);
      const auto &r = st.last_step_residuals;
      for (std::size_t k = 0; k + 1 < r.size(); ++k)
        if (r[k] < 1e-2 && r[k + 1] > 1e-15) { // small strain: round-off ~1e-15
          worst_order = std::min(worst_order, std::log(r[k + 1]) / std::log(r[k]));
          ++pairs;
        }
    });
    runs[integration] = runner.run();
    std::printf("%s: most Newton iterations %u, %u asymptotic pairs, lowest order %.2f\n", integration.c_str(),
                worst, pairs, worst_order);
    EXPECT_LE(worst, 6u) << integration;
    EXPECT_GE(pairs, 3u) << integration;
    EXPECT_GT(worst_order, 1.7) << integration << ": Newton lost its quadratic rate";
  }
  double difference = 0.0;
  const auto &full = runs["full"].samples, &bbar = runs["b-bar"].samples;
  ASSERT_EQ(full.size(), bbar.size());
  for (std::size_t k = 0; k < full.size(); ++k)
    difference = std::max(difference, std::abs(tau_max(full[k].stress) - tau_max(bbar[k].stress)) / p);
  std::printf("largest |tau_full - tau_bbar| / p = %.2e\n", difference);
  EXPECT_GT(difference, 1e-6) << "B-bar must change the heterogeneous solution";
}

/// The times of a PVD index, in file order.
std::vector<double> pvd_times(const std::string &file)
{
  std::ifstream in(file);
  std::vector<double> times;
  for (std::string line; std::getline(in, line);)
    if (const auto at = line.find("timestep=\""); at != std::string::npos)
      times.push_back(std::stod(line.substr(at + 10)));
  return times;
}

TEST(CubeEngine, UnloadingBranchLeavesTheMainPathUnchangedAndWritesItsFieldsAsASeriesOfItsOwn)
{
  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(5));
  m.cohesion = PiecewiseLinear({0.0, 0.01}, {20e3, 30e3});
  CubeParameters cp = small_cube(2);
  cp.imperfection_radius = 0.3;
  LoadingProgram plain = triaxial(0.006);
  LoadingProgram branched = plain;
  branched.stages[1].unload_at = {parse_trigger("eps_zz <= -0.003", "test")};
  CubeEngine a(cp, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const std::string fields = "/tmp/geocomp-cube-branch-series-" + std::to_string(::getpid());
  CubeParameters with_fields = cp;
  with_fields.output_directory = fields;
  CubeEngine b(with_fields, make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const Response ra = ProgramRunner(plain, a).run();
  const Response rb = ProgramRunner(branched, b).run();
  ASSERT_EQ(rb.branches.size(), 1u);
  EXPECT_TRUE(rb.branches[0].reached_target);
  const auto main_a = ra.path(0), main_b = rb.path(0);
  ASSERT_EQ(main_a.size(), main_b.size());
  for (std::size_t k = 0; k < main_a.size(); ++k)
    EXPECT_LT((main_a[k]->stress - main_b[k]->stress).norm(), 1e-9 * p) << "sample " << k;
  // Fields: the main path's series runs forward in time, one entry per main-path sample; the
  // branch has its own (it starts from an earlier state, so mixed in, time would go back).
  const std::vector<double> main_times = pvd_times(fields + "/cube.pvd");
  const std::vector<double> branch_times = pvd_times(fields + "/cube-branch1.pvd");
  EXPECT_EQ(main_times.size(), main_b.size());
  EXPECT_EQ(branch_times.size(), rb.samples.size() - main_b.size());
  EXPECT_TRUE(std::is_sorted(main_times.begin(), main_times.end()) &&
              std::adjacent_find(main_times.begin(), main_times.end()) == main_times.end());
  ASSERT_FALSE(branch_times.empty());
  EXPECT_LT(branch_times.front(), main_times.back()); // the branch left from inside the main path
  std::filesystem::remove_all(fields);
}

TEST(CubeEngine, PostPeakCurvesOnThreeMeshesWithAndWithoutCrackBand)
{
  // Plane strain with a weak sphere at the centre and softening cohesion, on 4^3, 6^3 and
  // 8^3 Q1, with and without the crack band (l_ref = L). What this loading does (measured,
  // docs/continuum-fe.md): the material loses ellipticity at first yield, but the discrete
  // solution stays diffuse (every point plastic), so
  //   - without regularization the post-peak curves agree to round-off level, and
  //   - with the crack band they differ by O(h_e): the softening is stretched by L/h_e at
  //     every point, not just in a one-element band; the differences shrink like h_e.
  const LoadingProgram program = plane_strain(0.02, 1.0);
  auto tau = [](const ResponseSample &s) { return tau_max(s.stress); };
  std::map<std::string, std::vector<Response>> runs;
  for (const std::string regularization : {"none", "crack-band"})
    for (unsigned n : {4u, 6u, 8u}) {
      CubeParameters cp = small_cube(n);
      cp.newton_tolerance = 1e-8;
      cp.linear_tolerance = 1e-10;
      cp.imperfection_radius = 0.2;
      cp.imperfection_cohesion_factor = 0.8;
      cp.regularization = regularization;
      cp.localization_directions = 50;
      CubeEngine engine(cp, make_material_factory({"mohr-coulomb", softening_material(), {}, {}}), MPI_COMM_WORLD);
      runs[regularization].push_back(ProgramRunner(program, engine).run());
      const CubeStatistics &st = engine.statistics();
      std::printf("%s %u^3: %u steps, %.2f Newton its/step, %u cut-backs\n", regularization.c_str(), n, st.steps,
                  double(st.newton_iterations) / st.steps, st.cutbacks);
    }
  std::map<std::string, std::array<double, 2>> difference; // max post-peak |tau_n - tau_8|/tau_peak
  for (auto &[regularization, r] : runs) {
    ASSERT_EQ(r[0].samples.size(), r[2].samples.size());
    std::size_t peak = 0;
    for (std::size_t k = 0; k < r[2].samples.size(); ++k)
      if (tau(r[2].samples[k]) > tau(r[2].samples[peak]))
        peak = k;
    const double tau_peak = tau(r[2].samples[peak]);
    difference[regularization] = {{0.0, 0.0}};
    for (std::size_t k = peak; k < r[2].samples.size(); ++k)
      for (int m = 0; m < 2; ++m)
        difference[regularization][m] = std::max(difference[regularization][m],
                                                 std::abs(tau(r[m].samples[k]) - tau(r[2].samples[k])) / tau_peak);
    const double drop = 1.0 - tau(r[2].samples.back()) / tau_peak;
    std::printf("%s: post-peak max |tau_n - tau_8|/tau_peak: n=4 %.2e, n=6 %.2e; drop on 8^3 %.3f\n",
                regularization.c_str(), difference[regularization][0], difference[regularization][1], drop);
    EXPECT_GT(drop, 0.04) << "the test must reach the softening branch";
  }
  EXPECT_LT(difference["none"][0], 5e-3);
  EXPECT_LT(difference["none"][1], 5e-4);
  EXPECT_LT(difference["crack-band"][1], 0.5 * difference["crack-band"][0]);
  EXPECT_LT(difference["crack-band"][1], 0.03);

  // Onset of localization: in the x-z plane (plane strain in y), the band at the Arthur
  // angle 45 deg + (phi + psi)/4 to the minor principal stress axis x, i.e. the band normal
  // at that angle from the axial direction z.
  const Response &r = runs["none"][2];
  const ResponseSample &last = r.samples.back();
  ASSERT_GT(last.extras[r.extra_index("localization_onset_time")], 0.0);
  const Vector3 n(last.extras[r.extra_index("localization_nx")], last.extras[r.extra_index("localization_ny")],
                  last.extras[r.extra_index("localization_nz")]);
  EXPECT_LT(std::abs(n[1]), 0.02);
  const double angle = std::acos(std::abs(n[2])) * 180.0 / M_PI;
  std::printf("band normal (%.4f, %.4f, %.4f): %.2f deg from z; Arthur %.2f deg\n", n[0], n[1], n[2], angle,
              45.0 + (30.0 + 5.0) / 4.0);
  EXPECT_NEAR(angle, 45.0 + (30.0 + 5.0) / 4.0, 1.0);
}

// The near-null space handed to ML must be exact: each of the six rigid-body modes is a
// zero-energy mode of the unconstrained elastic stiffness, K m = 0 up to round-off
// relative to |K| |m|, on a distorted mesh and for Q1 and Q2; the six are independent
// (the Gram matrix of the normalized columns is far from singular); and the check is
// sharp: the simple shear u = (y, x, 0), a wrong "rotation" with a flipped sign, is not.
TEST(CubeEngine, RigidBodyModesAreZeroEnergyModesOfTheElasticStiffness)
{
  using namespace dealii;
  for (unsigned degree : {1u, 2u}) {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_cube(tria, 3, 0.0, 1.0);
    GridTools::distort_random(0.2, tria, /*keep_boundary=*/false, /*seed=*/5);
    FESystem<3> fe(FE_Q<3>(degree), 3);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const std::size_t n = dof_handler.n_dofs();

    DynamicSparsityPattern dsp(n);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> K(pattern);
    QGauss<3> quadrature(degree + 1);
    FEValues<3> fe_values(fe, quadrature, update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    const unsigned dpc = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dpc, dpc);
    std::vector<types::global_dof_index> dofs(dpc);
    for (const auto &cell : dof_handler.active_cell_iterators()) {
      fe_values.reinit(cell);
      cell_matrix = 0.0;
      for (unsigned q = 0; q < quadrature.size(); ++q)
        for (unsigned i = 0; i < dpc; ++i)
          for (unsigned j = 0; j < dpc; ++j)
            cell_matrix(i, j) += (lambda_L * fe_values[u].divergence(i, q) * fe_values[u].divergence(j, q) +
                                  2.0 * G * fe_values[u].symmetric_gradient(i, q) *
                                    fe_values[u].symmetric_gradient(j, q)) *
                                 fe_values.JxW(q);
      cell->get_dof_indices(dofs);
      K.add(dofs, cell_matrix);
    }

    const Point<3> centre(0.5, 0.5, 0.5);
    const std::vector<double> modes = rigid_body_modes(dof_handler, dof_handler.locally_owned_dofs(), centre);
    ASSERT_EQ(modes.size(), 6 * n);
    auto relative_energy = [&](const Vector<double> &m) {
      Vector<double> Km(n);
      K.vmult(Km, m);
      return Km.linfty_norm() / (K.linfty_norm() * m.linfty_norm());
    };
    Eigen::Matrix<double, 6, 6> gram;
    std::vector<Vector<double>> columns(6, Vector<double>(n));
    for (unsigned k = 0; k < 6; ++k) {
      for (std::size_t i = 0; i < n; ++i)
        columns[k][i] = modes[k * n + i];
      columns[k] /= columns[k].l2_norm();
      EXPECT_LT(relative_energy(columns[k]), 1e-13) << "Q" << degree << " mode " << k;
    }
    for (unsigned k = 0; k < 6; ++k)
      for (unsigned l = 0; l < 6; ++l)
        gram(k, l) = columns[k] * columns[l];
    EXPECT_GT(gram.determinant(), 0.1) << "Q" << degree << ": the six modes are not independent";

    // Sharpness: the same construction with one sign flipped is a simple shear.
    Vector<double> shear(n);
    for (std::size_t i = 0; i < n; ++i)
      shear[i] = (modes[i] == 1.0 ? -1.0 : 1.0) * modes[5 * n + i]; // (y, x, 0), not (-y, x, 0)
    const double shear_energy = relative_energy(shear);
    std::printf("Q%u: simple-shear check |K u| / (|K| |u|) = %.3g\n", degree, shear_energy);
    EXPECT_GT(shear_energy, 1e-3);
  }
}

// The same near-null space in use: on an imperfect, softening 8^3 cube in plane strain the
// ML-preconditioned GMRES needs fewer iterations per solve with the six rigid-body modes
// than with the three translations (measured 1.4x fewer on 16^3, docs/continuum-fe.md).
// A wrong rotation column would leave ML's coarse spaces no better than translations.
TEST(CubeEngine, RigidBodyNearNullSpaceSavesKrylovIterations)
{
  std::map<std::string, double> per_solve;
  for (const std::string space : {"translations", "rigid-body"}) {
    CubeParameters cp = small_cube(8);
    cp.near_null_space = space;
    cp.amg_rebuild_growth = 0.0; // a fresh hierarchy for every solve: the near-null spaces alone differ
    cp.linear_tolerance = 1e-10;
    cp.newton_tolerance = 1e-8;
    cp.imperfection_radius = 0.3;
    cp.imperfection_cohesion_factor = 0.8;
    CubeEngine engine(cp, make_material_factory({"mohr-coulomb", softening_material(), {}, {}}), MPI_COMM_WORLD);
    ProgramRunner(plane_strain(0.006, 1.0), engine).run();
    const CubeStatistics &st = engine.statistics();
    per_solve[space] = double(st.linear_iterations) / st.newton_iterations;
    std::printf("%s: %u Newton iterations, %.1f GMRES iterations per solve\n", space.c_str(),
                st.newton_iterations, per_solve[space]);
  }
  EXPECT_LT(per_solve["rigid-body"], 0.85 * per_solve["translations"]);
}

// ML's hierarchy kept across Newton iterations and load steps (CubeSolver.cpp): on the same
// imperfect, softening cube it is built far less often than once per solve, the run reaches
// the same curve (to the Newton tolerance), and a solve never needs more than the growth
// allowance over the first solve after a build before the next build.
TEST(CubeEngine, KeptAmgHierarchyBuildsRarelyAndGivesTheSameCurve)
{
  std::map<double, Response> runs;
  std::map<double, CubeStatistics> stats;
  for (const double growth : {0.0, 1.5}) {
    CubeParameters cp = small_cube(8);
    cp.amg_rebuild_growth = growth;
    cp.linear_tolerance = 1e-10;
    cp.newton_tolerance = 1e-9;
    cp.imperfection_radius = 0.3;
    cp.imperfection_cohesion_factor = 0.8;
    CubeEngine engine(cp, make_material_factory({"mohr-coulomb", softening_material(), {}, {}}), MPI_COMM_WORLD);
    runs[growth] = ProgramRunner(plane_strain(0.006, 1.0), engine).run();
    stats[growth] = engine.statistics();
    std::printf("growth %.1f: %u Newton iterations, %u AMG builds, %.1f GMRES iterations per solve\n", growth,
                stats[growth].newton_iterations, stats[growth].preconditioner_builds,
                double(stats[growth].linear_iterations) / stats[growth].newton_iterations);
  }
  EXPECT_EQ(stats[0.0].preconditioner_builds, stats[0.0].newton_iterations); // one per solve
  EXPECT_LT(stats[1.5].preconditioner_builds, stats[1.5].newton_iterations / 3);
  ASSERT_EQ(runs[0.0].samples.size(), runs[1.5].samples.size());
  for (std::size_t k = 0; k < runs[0.0].samples.size(); ++k)
    EXPECT_LT((runs[0.0].samples[k].stress - runs[1.5].samples[k].stress).norm(), 1e-6 * p) << "sample " << k;
}

// The elastic limit located by bisection (ProgramRunner, docs/metrics.md) on the deal.II
// cube: its saved states restore the main path for every bisection branch. Hardening
// Mohr-Coulomb (cohesion rising with the plastic strain, so the residual after unloading
// grows with the start strain) in triaxial compression: the bracket ends straddle 1 %,
// it is narrower than the tolerance, and the residuals grow monotonically with the start.
TEST(CubeEngine, LocatesTheElasticLimitByBisectionFromItsSavedStates)
{
  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, 20e3, deg(30), deg(0));
  m.cohesion = PiecewiseLinear({0.0, 0.2}, {20e3, 100e3});
  LoadingProgram program = triaxial(0.03);
  Stage &shear = program.stages[1];
  shear.unload_at = {parse_trigger("eps_zz <= -0.001", "test"), parse_trigger("eps_zz <= -0.025", "test")};
  shear.locate_elastic_limit = true;
  shear.elastic_limit_tolerance = 1e-3;
  program.validate();
  CubeEngine engine(small_cube(2), make_material_factory({"mohr-coulomb", m, {}, {}}), MPI_COMM_WORLD);
  const Response r = ProgramRunner(program, engine).run();
  std::size_t stage_start = 0; // the last sample of the consolidation
  for (std::size_t k = 0; k < r.samples.size(); ++k)
    if (r.samples[k].stage == 0 && r.samples[k].branch == 0)
      stage_start = k;
  const std::vector<BranchPoint> points = branch_points(r, 1, r.samples[stage_start]);
  const LimitSearch s = search_limit(points, s0_residual_threshold);
  ASSERT_TRUE(s.bracketed());
  EXPECT_LT(s.lower->residual, 0.01);
  EXPECT_GE(s.upper->residual, 0.01);
  EXPECT_LE(s.width(), 1e-3);
  int bisections = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    bisections += points[k].bisection ? 1 : 0;
    if (k > 0) {
      EXPECT_GT(points[k].residual, points[k - 1].residual) << "branch " << points[k].id;
    }
  }
  EXPECT_GE(bisections, 3);
  for (const BranchRecord &b : r.branches)
    EXPECT_TRUE(b.reached_target) << "branch " << b.id;
  std::printf("cube bracket [%.4f, %.4f] %%, %d bisection branches\n", 100 * s.lower->x, 100 * s.upper->x,
              bisections);
}
