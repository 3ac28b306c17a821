// The material-point engine under the ProgramRunner: mixed control (stress axes solved by
// Newton with the consistent tangent), S0's isochoric program, and exact save/restore.
#include "EngineTestSupport.h"

#include "common/ProgramRunner.h"
#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/models/FiniteStrain.h"
#include "continuum/models/MohrCoulombModel.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace geocomp;
using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {
const double E = 1.0e9, nu = 0.25, c = 50e3, phi = deg(30), psi = deg(10), p = 1.0e6;

std::shared_ptr<const ConstitutiveModel> perfect_material()
{
  return std::make_shared<MohrCoulombModel>(perfect_mohr_coulomb(E, nu, c, phi, psi));
}

/// Isotropic consolidation to p, then S0's isochoric shear (eq. 3, lambda = 0) until `stop`.
LoadingProgram isochoric_program(double sample_interval, const std::string &stop)
{
  LoadingProgram program;
  program.sample_interval = sample_interval;
  Stage shear;
  shear.name = "isochoric";
  shear.isochoric = true;
  shear.lambda = 0.0;
  shear.isochoric_rate = 0.01;
  shear.stop_any = {parse_condition(stop, "test")};
  shear.max_duration = 100.0;
  program.stages = {isotropic_stage(p, 1.0), shear};
  program.validate();
  return program;
}

LoadingProgram triaxial_program()
{
  LoadingProgram program;
  program.sample_interval = 0.05;
  program.stages = {isotropic_stage(p, 0.2), triaxial_stage(p, 1e-3, 0.01)};
  program.validate();
  return program;
}
} // namespace

TEST(MaterialPointEngine, TriaxialPeakEqualsMohrCoulombClosedForm)
{
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    MaterialPointParameters prm;
    prm.kinematics = kinematics;
    MaterialPointEngine engine(perfect_material(), prm);
    const LoadingProgram program = triaxial_program();
    const Response r = ProgramRunner(program, engine).run();

    // Compression positive: sigma_1 = sigma_3 N_phi + 2 c sqrt(N_phi). At finite strain the
    // surface is on the Kirchhoff stress tau = J sigma, so sigma_1 = sigma_3 N_phi +
    // 2 (c / J) sqrt(N_phi); tension positive sigma_zz = -(p N_phi + 2 (c / J) sqrt(N_phi)).
    auto peak = [&](const ResponseSample &s) {
      const double J = kinematics == Kinematics::finite_strain ? volumetric_strain(s.strain) + 1.0 : 1.0;
      return -(p * N_of(phi) + 2.0 * (c / J) * std::sqrt(N_of(phi)));
    };
    const ResponseSample *lowest = &r.samples.front();
    for (const auto &s : r.samples)
      if (s.stress(2, 2) < lowest->stress(2, 2))
        lowest = &s;
    EXPECT_NEAR(lowest->stress(2, 2) / peak(*lowest), 1.0, 1e-8) << to_string(kinematics);
    // It reached the peak plateau well before the end, on the compression corner.
    EXPECT_NEAR(r.samples.back().stress(2, 2) / peak(r.samples.back()), 1.0, 1e-8) << to_string(kinematics);
    // Plastic, and symmetric: the corner sigma_xx = sigma_yy leaves the lateral split
    // indeterminate, the engine must keep eps_xx = eps_yy.
    EXPECT_NE(r.samples.back().extras[r.extra_index("state_flag")], 0.0);
    for (const auto &s : r.samples)
      EXPECT_NEAR(s.strain(0, 0), s.strain(1, 1), 1e-14) << "t = " << s.time;
    EXPECT_EQ(r.stage_end_reasons[1], program.stages[1].stop_any[0].text);
  }
}

TEST(MaterialPointEngine, EverySampleOfAFlowingPointIsFlaggedPlastic)
{
  // A sample ends on the advance's last increment. Summed increments miss the sample time
  // by round-off; a tolerance below that round-off once added a vanishing, elastic extra
  // increment at about every other sample, which then reported the flowing point as
  // elastic (state flag 0) and its acoustic tensor as untouched (q = 1).
  MaterialPointEngine engine(perfect_material());
  const Response r = ProgramRunner(triaxial_program(), engine).run();
  const std::size_t kappa = r.extra_index("kappa"), flag = r.extra_index("state_flag");
  std::size_t flowing = 0;
  for (std::size_t k = 1; k < r.samples.size(); ++k) {
    if (!(r.samples[k].extras[kappa] > r.samples[k - 1].extras[kappa]))
      continue;
    ++flowing;
    EXPECT_NE(r.samples[k].extras[flag], 0.0) << "t = " << r.samples[k].time;
  }
  EXPECT_GT(flowing, 50u);
}

TEST(MaterialPointEngine, StressAxesHoldTheirTargets)
{
  MaterialPointEngine engine(perfect_material());
  const Response r = ProgramRunner(triaxial_program(), engine).run();
  int checked = 0;
  for (const auto &s : r.samples) {
    if (s.time < 0.05 + 1e-12) // the first interval ramps the targets from zero
      continue;
    EXPECT_NEAR(s.stress(0, 0) / -p, 1.0, 1e-8) << "t = " << s.time;
    EXPECT_NEAR(s.stress(1, 1) / -p, 1.0, 1e-8) << "t = " << s.time;
    if (s.stage == 0)
      EXPECT_NEAR(s.stress(2, 2) / -p, 1.0, 1e-8);
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(MaterialPointEngine, ElasticConsolidationMatchesBulkModulus)
{
  // Small strain: 3 K eps = -p. Finite strain (Hencky): tau = 3 K ln(1 + eps) and
  // sigma = tau / J with J = (1 + eps)^3, i.e. 3 K ln(1 + eps) / (1 + eps)^3 = -p.
  const double K = E / (3.0 * (1.0 - 2.0 * nu));
  for (const Kinematics kinematics : {Kinematics::finite_strain, Kinematics::small_strain}) {
    MaterialPointParameters prm;
    prm.kinematics = kinematics;
    MaterialPointEngine engine(perfect_material(), prm);
    LoadingProgram program;
    program.sample_interval = 0.1;
    program.stages = {isotropic_stage(p, 0.5)};
    const Response r = ProgramRunner(program, engine).run();
    for (int a = 0; a < 3; ++a) {
      const double e = r.samples.back().strain(a, a);
      if (kinematics == Kinematics::small_strain)
        EXPECT_NEAR(e / (-p / (3.0 * K)), 1.0, 1e-10);
      else
        EXPECT_NEAR(3.0 * K * std::log1p(e) / std::pow(1.0 + e, 3) / -p, 1.0, 1e-10);
    }
  }
}

TEST(MaterialPointEngine, IsochoricProgramKeepsTheVolumeAndReachesItsStop)
{
  MaterialPointEngine engine(perfect_material());
  const LoadingProgram program = isochoric_program(0.1, "gamma_max >= 0.05");
  const Response r = ProgramRunner(program, engine).run();
  ASSERT_EQ(r.stage_end_reasons[1], "gamma_max >= 0.05");
  std::vector<const ResponseSample *> stage2;
  for (const auto &s : r.samples)
    if (s.stage == 1)
      stage2.push_back(&s);
  ASSERT_GT(stage2.size(), 5u);
  const double v0 = volumetric_strain(r.samples[stage2.front() - r.samples.data() - 1].strain);
  for (const ResponseSample *s : stage2) {
    EXPECT_NEAR(volumetric_strain(s->strain), v0, 1e-12);
    EXPECT_NEAR(s->strain(1, 1), stage2.front()->strain(1, 1), 1e-15); // lambda = 0
  }
  // Plastic at the end, and with psi > 0 at constant volume the mean pressure has grown.
  EXPECT_NE(stage2.back()->extras[r.extra_index("state_flag")], 0.0);
  EXPECT_LT(mean_stress(stage2.back()->stress), -1.05 * p);
}

TEST(MaterialPointEngine, IsochoricPeakEqualsMohrCoulombClosedFormAtFiniteStrain)
{
  // S0's isochoric shear (eq. 3, lambda = 0) of a perfectly plastic Mohr-Coulomb point
  // without dilatancy, from the initial stress -p, to gamma_max = 30 %. det F = 1 on the
  // whole path and psi = 0 flow is isochoric, so tr(ln V^e) and the mean stress stay at -p;
  // yield comes at tau = (sigma_1 - sigma_3)/2 = c cos(phi) + p sin(phi) and the point stays
  // on that plateau (sigma_2 strictly between the extremes).
  MaterialPointParameters prm;
  prm.initial_stress = -p;
  MaterialPointEngine engine(std::make_shared<MohrCoulombModel>(perfect_mohr_coulomb(E, nu, c, phi, 0.0)), prm);
  const Response r = ProgramRunner(s0_isochoric(0.3, 0.05), engine).run();
  ASSERT_EQ(r.stage_end_reasons[0], "gamma_max >= 0.300000");
  EXPECT_GT(expect_isochoric_plateau(r, p, c, phi, 1e-8), 50);
  for (const auto &s : r.samples) {
    EXPECT_NEAR(volumetric_strain(s.strain), 0.0, 1e-14) << "t = " << s.time;
    const Vector3 sig = principal_values(s.stress); // ascending
    if (s.extras[r.extra_index("state_flag")] != 0.0) {
      EXPECT_GT(sig[1], sig[0] + 1e-3 * tau_max(s.stress));
      EXPECT_LT(sig[1], sig[2] - 1e-3 * tau_max(s.stress));
    }
  }
}

TEST(MaterialPointEngine, FiniteStrainPointEqualsTheExponentialMapOnTheBoxDeformationGradient)
{
  // The point's update on ln(1 + eps) (the box never rotates) against the general update of
  // FiniteStrain.h driven by F = diag(1 + eps) at the same increments: a dilatant point in
  // S0's isochoric program with lambda = 0.5, one increment per sample.
  MaterialPointParameters prm;
  prm.initial_stress = -p;
  prm.substeps_per_advance = 1;
  auto model = std::make_shared<MohrCoulombModel>(perfect_mohr_coulomb(E, nu, c, phi, psi));
  MaterialPointEngine engine(model, prm);
  LoadingProgram program = s0_isochoric(0.2, 0.02);
  program.stages[0].lambda = 0.5;
  const Response r = ProgramRunner(program, engine).run();
  FiniteStrainHistory h = initial_finite_strain_history(*model, -p * Matrix3::Identity());
  int plastic = 0;
  for (const auto &s : r.samples) {
    const FiniteStrainUpdate u = finite_strain_update(*model, Matrix3::Identity() + s.strain, h);
    h = u.history;
    plastic += u.region != ReturnRegion::elastic;
    EXPECT_LT((u.cauchy_stress() - s.stress).cwiseAbs().maxCoeff(), 1e-9 * p) << "t = " << s.time;
  }
  EXPECT_GT(plastic, 50);
}

TEST(MaterialPointEngine, SmallStrainIsochoricShearDriftsFromTheClosedFormAsTheVolumeTermPredicts)
{
  // The same shear at small strain: the imposed box has det(I + eps) = 1 but tr(eps) =
  // e^2/(1 - e) > 0, so the mean stress falls by K tr(eps) and the plateau tau = c cos(phi) -
  // (sigma_1 + sigma_3)/2 sin(phi) follows it down (tension positive) - the bias the finite
  // strain formulation removes.
  MaterialPointParameters prm;
  prm.initial_stress = -p;
  prm.kinematics = Kinematics::small_strain;
  MaterialPointEngine engine(std::make_shared<MohrCoulombModel>(perfect_mohr_coulomb(E, nu, c, phi, 0.0)), prm);
  const LoadingProgram program = s0_isochoric(0.05, 0.05);
  const Response r = ProgramRunner(program, engine).run();
  const double K = E / (3.0 * (1.0 - 2.0 * nu));
  int plastic = 0;
  for (const auto &s : r.samples) {
    // tr(eps) is exactly the small-strain volume change the model sees.
    if (s.time == 0.0)
      continue;
    EXPECT_NEAR((mean_stress(s.stress) + p) / (K * s.strain.trace()), 1.0, 1e-8) << "t = " << s.time;
    if (s.extras[r.extra_index("state_flag")] == 0.0)
      continue;
    ++plastic;
    const Vector3 sig = principal_values(s.stress);
    EXPECT_NEAR(tau_max(s.stress) / (c * std::cos(phi) - 0.5 * (sig[2] + sig[0]) * std::sin(phi)), 1.0, 1e-10);
  }
  EXPECT_GE(plastic, 8);
  // By gamma_max = 5 % (e ~ 2.5 %) the mean stress has lost K e^2/(1 - e): 43 % of p here
  // (E / p = 1000); at gamma_max ~ 8 % this point reaches the apex in tension.
  const double e = -r.samples.back().strain(0, 0);
  EXPECT_NEAR((mean_stress(r.samples.back().stress) + p) / (K * e * e / (1.0 - e)), 1.0, 1e-6);
}

TEST(MaterialPointEngine, UnloadingBranchLeavesTheMainPathUnchanged)
{
  // Hardening material so the branch starts from a state with history.
  MohrCoulombParameters m = perfect_mohr_coulomb(E, nu, c, phi, psi);
  m.cohesion = PiecewiseLinear({0.0, 0.004, 0.02}, {c, 2.0 * c, 0.5 * c});
  auto material = std::make_shared<MohrCoulombModel>(m);
  LoadingProgram plain = triaxial_program();
  LoadingProgram branched = plain;
  branched.stages[1].unload_at = {parse_trigger("eps_zz <= -0.004", "test")};

  MaterialPointEngine a(material), b(material);
  const Response ra = ProgramRunner(plain, a).run();
  const Response rb = ProgramRunner(branched, b).run();
  ASSERT_EQ(rb.branches.size(), 1u);
  EXPECT_TRUE(rb.branches[0].reached_target);
  EXPECT_GT(rb.branches[0].residual_gamma, 1e-4); // plastic strain survives unloading
  const auto main_a = ra.path(0), main_b = rb.path(0);
  ASSERT_EQ(main_a.size(), main_b.size());
  for (std::size_t k = 0; k < main_a.size(); ++k) {
    EXPECT_EQ(main_a[k]->stress, main_b[k]->stress) << "sample " << k;
    EXPECT_EQ(main_a[k]->strain, main_b[k]->strain) << "sample " << k;
  }
}
