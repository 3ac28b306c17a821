// Metric extraction on synthetic curves whose answers follow from closed forms
// (Synthetic.h), on noisy versions of them, and on responses made by the ProgramRunner.
#include "compare/Metrics.h"
#include "Synthetic.h"
#include "common/ProgramRunner.h"
#include "continuum/driver/MaterialPointEngine.h"
#include "tests/common/HystereticShearEngine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp;
using namespace geocomp::compare;
using geocomp::compare::testing::Backbone;
using geocomp::compare::testing::shear_response;

namespace {
constexpr double deg = 180.0 / 3.14159265358979323846;

/// A perfectly plastic Mohr-Coulomb material point material (nu 0.25; phi, psi in degrees).
continuum::MaterialParameters perfect_point(double E, double c, double phi_deg, double psi_deg)
{
  continuum::MaterialParameters m;
  m.mohr_coulomb.youngs_modulus = E;
  m.mohr_coulomb.poisson_ratio = 0.25;
  m.mohr_coulomb.cohesion = continuum::PiecewiseLinear(c);
  m.mohr_coulomb.friction_angle = continuum::PiecewiseLinear(phi_deg / deg);
  m.mohr_coulomb.dilatancy_angle = continuum::PiecewiseLinear(psi_deg / deg);
  return m;
}

MetricOptions shear_options()
{
  MetricOptions o;
  o.kind = CurveKind::ShearIsochoric;
  return o;
}

/// Where the parabola leaves the initial line by tol * tau_p (no branches): the deviation
/// there is (tau_p - tau_e) u^2, u = (g - g_e)/D.
double linearity_limit(const Backbone &b, double tol)
{
  return b.g_e() + b.D() * std::sqrt(tol * b.tau_p / (b.tau_p - b.tau_e));
}

/// Strain where tau = f tau_p on the parabola: (tau_p - tau_e)(2u - u^2) = f tau_p - tau_e.
double strain_at_fraction(const Backbone &b, double f)
{
  const double c = (f * b.tau_p - b.tau_e) / (b.tau_p - b.tau_e);
  return b.g_e() + b.D() * (1.0 - std::sqrt(1.0 - c));
}
} // namespace

TEST(Metrics, PiecewiseShearCurveGivesItsPlantedMetrics)
{
  const Backbone b;
  const Response r = shear_response(b, 1e-4);
  const MetricSet m = compute_metrics(r, shear_options());
  EXPECT_EQ(m.kind, CurveKind::ShearIsochoric);
  // Initial window is on the linear part and the fit uses raw data: exact.
  EXPECT_NEAR(m.initial_modulus, b.E, 1e-6 * b.E);
  // Secant at 50 % of the peak lies on the parabola.
  EXPECT_NEAR(m.secant_modulus, 0.5 * b.tau_p / strain_at_fraction(b, 0.5), 5e-3 * b.E);
  // Peak: 5-sample smoothing lowers a peak with a corner by < 0.6 H dg (= 6 kPa here).
  EXPECT_NEAR(m.peak_stress, b.tau_p, 0.6 * b.H * 1e-4 + 1.0);
  EXPECT_NEAR(m.peak_strain, b.g_p(), 2.5e-4);
  // No branches: deviation from linearity at 2 % of the peak rise.
  EXPECT_EQ(m.elastic_limit_method, "deviation from linearity");
  EXPECT_NEAR(m.elastic_limit_strain, linearity_limit(b, 0.02), 0.01 * linearity_limit(b, 0.02));
  EXPECT_NEAR(m.elastic_limit_stress, b.tau(linearity_limit(b, 0.02)), 0.01 * b.tau_p);
  // The softening window (20-80 % of the drop) lies on the straight drop: exact slope.
  EXPECT_NEAR(m.softening_modulus, -b.H, 1e-6 * b.H);
  EXPECT_NEAR(m.residual_stress, b.tau_r, 1e-6 * b.tau_r);
  // Cohesionless mobilized friction: sin phi = tau / p0 for sigma_1,3 = p0 -+ tau.
  EXPECT_NEAR(m.friction_peak_deg, std::asin(b.tau_p / 8e6) * deg, 0.1);
  EXPECT_NEAR(m.friction_residual_deg, std::asin(b.tau_r / 8e6) * deg, 1e-6);
  // Isochoric: the volume never changes, so dilatancy needs a given K.
  EXPECT_TRUE(std::isnan(m.dilatancy_angle_deg));
  EXPECT_FALSE(m.notes.empty());
}

// Noise of 20 kPa (0.4 % of the peak) with a fixed seed. Tolerances, from the LS and
// extreme-value error of that noise: modulus 5 %, peak 1.5 %, peak strain 1.5e-3,
// elastic limit 10 % (it inherits the modulus error), softening 3 %, residual 0.5 %.
TEST(Metrics, NoisyShearCurveStaysWithinStatedTolerances)
{
  const Backbone b;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Response r = shear_response(b, 1e-4, 20e3, {}, 0.0, 8e6, seed);
    const MetricSet m = compute_metrics(r, shear_options());
    SCOPED_TRACE(seed);
    EXPECT_NEAR(m.initial_modulus, b.E, 0.05 * b.E);
    EXPECT_NEAR(m.peak_stress, b.tau_p, 0.015 * b.tau_p);
    EXPECT_NEAR(m.peak_strain, b.g_p(), 1.5e-3);
    EXPECT_NEAR(m.elastic_limit_strain, linearity_limit(b, 0.02), 0.1 * linearity_limit(b, 0.02));
    EXPECT_NEAR(m.softening_modulus, -b.H, 0.03 * b.H);
    EXPECT_NEAR(m.residual_stress, b.tau_r, 0.005 * b.tau_r);
  }
}

// S0's elastic limit: residual r(g) = g - tau(g)/E after elastic unloading, threshold 1 %,
// interpolated linearly in the branch start strain between the bracketing branches.
TEST(Metrics, ElasticLimitInterpolatesBetweenUnloadingResiduals)
{
  const Backbone b;
  const std::vector<double> at = {0.002, 0.008, 0.014, 0.020, 0.030};
  const Response r = shear_response(b, 1e-4, 0.0, at, b.E);
  const MetricSet m = compute_metrics(r, shear_options());
  ASSERT_EQ(m.branches.size(), at.size());
  auto residual = [&](double g) { return g - b.tau(g) / b.E; };
  for (std::size_t k = 0; k < at.size(); ++k)
    EXPECT_NEAR(m.branches[k].residual, residual(at[k]), 1e-9);
  // The first residual >= 1 % decides the bracket.
  std::size_t k = 0;
  while (residual(at[k]) < 0.01)
    ++k;
  ASSERT_GT(k, 0u);
  const double r0 = residual(at[k - 1]), r1 = residual(at[k]);
  const double expected = at[k - 1] + (0.01 - r0) * (at[k] - at[k - 1]) / (r1 - r0);
  EXPECT_EQ(m.elastic_limit_method, "unloading residual");
  EXPECT_NEAR(m.elastic_limit_strain, expected, 1e-9);
  EXPECT_NEAR(m.elastic_limit_stress, b.tau(expected), 0.002 * b.tau_p); // smoothed curve
  // A threshold above every residual leaves the limit undetermined, and says so.
  MetricOptions o = shear_options();
  o.residual_threshold = 0.5;
  const MetricSet none = compute_metrics(r, o);
  EXPECT_TRUE(std::isnan(none.elastic_limit_strain));
  EXPECT_FALSE(none.notes.empty());
}

// Branches played by the real ProgramRunner on the closed-form hysteretic engine: the
// residual the metrics read equals the runner's BranchRecord, and the elastic limit lies
// within the interpolation bracket of the exact solution of g - tau_b(g)/K = 1 %.
TEST(Metrics, ElasticLimitFromRunnerBranchesBracketsTheExactOne)
{
  const LoadingProgram p = geocomp::testing::shear_program(
    {"gamma_max >= 0.01", "gamma_max >= 0.02", "gamma_max >= 0.03", "gamma_max >= 0.05"}, 0.12);
  geocomp::testing::HystereticShearEngine engine;
  const Response r = ProgramRunner(p, engine).run();
  ASSERT_EQ(curve_kind_for(p), CurveKind::ShearIsochoric);
  EXPECT_EQ(guess_curve_kind(r), CurveKind::ShearIsochoric);

  const MetricSet m = compute_metrics(r, MetricOptions{});
  ASSERT_EQ(m.branches.size(), r.branches.size());
  // The runner records residuals in the program's (engineering) strain; the metrics read
  // the log strain of the same samples.
  for (std::size_t k = 0; k < r.branches.size(); ++k) {
    const Tensor3 &end = r.samples[r.branches[k].last_sample].strain;
    EXPECT_NEAR(m.branches[k].residual, gamma_max(relative_log_strain(end, r.samples.front().strain)), 1e-12);
    EXPECT_NEAR(m.branches[k].residual, r.branches[k].residual_gamma, 0.1 * r.branches[k].residual_gamma);
  }

  // Exact: bisection on the residual function of the engine.
  auto residual = [&](double g) { return g - engine.backbone(g) / engine.K; };
  double lo = 0.0, hi = 0.05;
  for (int i = 0; i < 80; ++i)
    (residual(0.5 * (lo + hi)) < 0.01 ? lo : hi) = 0.5 * (lo + hi);
  const double exact = 0.5 * (lo + hi);
  std::size_t k = 0;
  while (m.branches[k].residual < 0.01)
    ++k;
  ASSERT_GT(k, 0u);
  EXPECT_GT(m.elastic_limit_strain, m.branches[k - 1].x_start);
  EXPECT_LT(m.elastic_limit_strain, m.branches[k].x_start);
  // Two errors move it off the exact point: the chord between branches (the residual is
  // convex, so the chord reaches 1 % early) and the runner stopping a branch at the first
  // sample past its target (residuals up to one sample of gamma, 1e-3, too small: late).
  // Both stay well inside a tenth of the bracket here.
  EXPECT_NEAR(m.elastic_limit_strain, exact, 0.1 * (m.branches[k].x_start - m.branches[k - 1].x_start));
  // The backbone's peak A at g0.
  EXPECT_NEAR(m.peak_stress, engine.A, 1e-3 * engine.A);
  EXPECT_NEAR(m.peak_strain, engine.g0, 2e-3);
}

// Constant lateral pressure, compression positive: plastic strains planted with a fixed
// dilatancy angle, sin psi = d eps_v^p / d gamma^p, on top of isotropic elasticity.
// The strain is built so that the metrics' measures (gamma_max and tr of the logarithmic
// strain) hold exactly, so psi comes back to round-off.
TEST(Metrics, DilatancyAngleRecoveredFromPlantedPlasticFlow)
{
  const double E = 1e9, nu = 0.25, G = E / (2 * (1 + nu)), K = E / (3 * (1 - 2 * nu));
  const double psi = 10.0 / deg, lateral = 2e6;
  Response r;
  r.engine = "synthetic-triaxial";
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    // Axial stress increment (compression) and plastic shear strain along the path.
    const double ds = t < 0.3 ? 3e6 * t / 0.3 : (t < 0.5 ? 3e6 + 2e6 * std::sin((t - 0.3) / 0.2 * M_PI / 2) : 5e6 - 3e6 * (t - 0.5));
    const double gp = t < 0.3 ? 0.0 : 0.05 * (t - 0.3);
    const double tau = ds / 2, dp = -ds / 3;
    const double gamma = tau / G + gp, ev = dp / K + std::sin(psi) * gp;
    // Log strains e_x = e_y = e_z + gamma with e_x + e_y + e_z = ev.
    const double ez = (ev - 2 * gamma) / 3;
    ResponseSample s;
    s.time = t;
    s.strain = Vector3(std::expm1(ez + gamma), std::expm1(ez + gamma), std::expm1(ez)).asDiagonal();
    s.stress = Vector3(-lateral, -lateral, -lateral - ds).asDiagonal();
    r.samples.push_back(s);
  }
  EXPECT_EQ(guess_curve_kind(r), CurveKind::AxialLateral);
  const MetricSet m = compute_metrics(r, MetricOptions{});
  EXPECT_EQ(m.kind, CurveKind::AxialLateral);
  EXPECT_NEAR(m.shear_modulus, G, 1e-6 * G);
  EXPECT_NEAR(m.bulk_modulus, K, 1e-6 * K);
  EXPECT_NEAR(m.dilatancy_angle_deg, psi * deg, 1e-6);
  // Compression positive: the curve starts at the lateral pressure and peaks 5 MPa above it.
  EXPECT_NEAR(m.y0, lateral, 1e-6);
  EXPECT_NEAR(m.peak_stress, lateral + 5e6, 0.002 * 5e6);
  // Elastic part of -sigma_z vs -eps_z under constant lateral stress has slope E.
  EXPECT_NEAR(m.initial_modulus, E, 1e-3 * E);
}

TEST(Metrics, MetricTableUsesDisplayUnits)
{
  const Backbone b;
  const MetricSet m = compute_metrics(shear_response(b, 1e-4), shear_options());
  const auto t = metric_table(m);
  auto find = [&](const std::string &key) {
    for (const auto &v : t)
      if (v.key == key)
        return v.value;
    ADD_FAILURE() << key;
    return 0.0;
  };
  EXPECT_DOUBLE_EQ(find("peak_stress_MPa"), m.peak_stress * 1e-6);
  EXPECT_DOUBLE_EQ(find("peak_strain_pct"), m.peak_strain * 100);
  EXPECT_DOUBLE_EQ(find("friction_peak_deg"), m.friction_peak_deg);
}

TEST(Metrics, TooShortStageIsRefusedWithItsName)
{
  Response r;
  r.samples.push_back(geocomp::compare::testing::shear_sample(0, 0, 0, 1e6));
  r.samples.push_back(geocomp::compare::testing::shear_sample(1, 0.001, 1e5, 1e6));
  try {
    compute_metrics(r, MetricOptions{});
    FAIL();
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("stage 0"), std::string::npos);
  }
  EXPECT_THROW(parse_curve_kind("bogus"), std::invalid_argument);
  EXPECT_EQ(parse_curve_kind("axial"), CurveKind::AxialLateral);
}

// A program whose driven axis is x, extended while y and z hold -p (triaxial extension on a
// Mohr-Coulomb point): the axial curve is read on x with x = e_xx, y = sigma_xx (extension
// positive), found from the program and from the response alike, and rises from -p to the
// extension strength (once z was taken whatever the program, and this curve fell).
TEST(Metrics, AxialAxisAndSenseComeFromTheProgram)
{
  const double p = 1e6, c = 50e3, phi = 30.0 / deg;
  const continuum::MaterialParameters m = perfect_point(1e9, c, 30.0, 0.0);
  continuum::MaterialPointParameters mp;
  mp.initial_stress = -p;
  continuum::MaterialPointEngine engine(m, mp);
  LoadingProgram program;
  program.sample_interval = 0.05;
  Stage s;
  s.name = "extension";
  s.axes = {{AxisDrive::rate(1e-3), AxisDrive::stress(-p), AxisDrive::stress(-p)}};
  s.stop_any = {parse_condition("eps_xx >= 0.004", "test")};
  s.max_duration = 100;
  program.stages = {s};
  const Response r = ProgramRunner(program, engine).run();
  const std::optional<AxialAxis> axis = axial_axis_for(program);
  ASSERT_TRUE(axis.has_value());
  EXPECT_EQ(axis->axis, 0);
  EXPECT_EQ(axis->sense, 1.0);
  EXPECT_EQ(guess_axial_axis(r).axis, 0);
  EXPECT_EQ(guess_axial_axis(r).sense, 1.0);
  EXPECT_EQ(axis->describe(), "x, extension positive");
  MetricOptions o;
  o.kind = CurveKind::AxialLateral;
  o.axial = axis;
  const MetricSet metrics = compute_metrics(r, o);
  EXPECT_NEAR(metrics.y0, -p, 1e-6 * p);
  // Tension positive, s1 = sigma_x >= s2 = s3 = -p on (s1 - s3) + (s1 + s3) sin phi = 2 c cos phi:
  // sigma_x = (2 c cos phi - p (1 - sin phi)) / (1 + sin phi) (to O(J - 1): the surface is on
  // the Kirchhoff stress).
  const double sx = (2 * c * std::cos(phi) - p * (1 - std::sin(phi))) / (1 + std::sin(phi));
  EXPECT_NEAR(metrics.peak_stress / sx, 1.0, 2e-3);
  EXPECT_GT(metrics.peak_stress, metrics.y0);
  const auto table = metric_table(metrics);
  EXPECT_NE(table[5].label.find("sigma_x (tension +)"), std::string::npos) << table[5].label;
}

// Issue 29's case: a perfectly plastic, non-dilatant Mohr-Coulomb point (E 100 MPa, nu 0.25,
// c 10 kPa, phi 30 deg, p0 100 kPa) in S0's isochoric shear to gamma_max = 30 %. At finite
// strain the box is isochoric for the continuum too: the plateau is c cos phi + p0 sin phi
// and the metrics report no softening. At small strain the box's tr(eps) = e^2/(1 - e) eats
// the mean stress and the same material "softens".
TEST(Metrics, PerfectMohrCoulombUnderS0IsochoricShearShowsNoSofteningAtFiniteStrain)
{
  const double p0 = 1e5, c = 10e3, phi = 30.0 / deg;
  const continuum::MaterialParameters m = perfect_point(100e6, c, 30.0, 0.0);
  LoadingProgram program;
  program.sample_interval = 0.02;
  Stage s;
  s.name = "isochoric";
  s.isochoric = true;
  s.isochoric_rate = 0.05;
  s.stop_any = {parse_condition("gamma_max >= 0.3", "test")};
  s.max_duration = 100;
  program.stages = {s};
  MetricOptions o;
  o.kind = curve_kind_for(program);
  MetricSet at[2];
  for (const auto kinematics : {continuum::Kinematics::finite_strain, continuum::Kinematics::small_strain}) {
    continuum::MaterialPointParameters mp;
    mp.initial_stress = -p0;
    mp.kinematics = kinematics;
    continuum::MaterialPointEngine engine(m, mp);
    at[kinematics == continuum::Kinematics::small_strain] = compute_metrics(ProgramRunner(program, engine).run(), o);
  }
  const MetricSet &finite = at[0], &small = at[1];
  EXPECT_NEAR(finite.peak_stress / (c * std::cos(phi) + p0 * std::sin(phi)), 1.0, 1e-8);
  EXPECT_TRUE(std::isnan(finite.softening_modulus));
  EXPECT_NEAR(finite.residual_stress / finite.peak_stress, 1.0, 1e-8);
  bool said = false;
  for (const auto &n : finite.notes)
    said = said || n.find("no softening") != std::string::npos || n.find("last sample") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_LT(small.softening_modulus, 0.0); // the small-strain artefact the finite strain removes
  std::printf("isochoric perfect MC: finite strain peak %.6g Pa, no softening; small strain softening modulus %.3g MPa\n",
              finite.peak_stress, small.softening_modulus * 1e-6);
}
