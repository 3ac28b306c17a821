// Head-on impacts against the closed forms of DEM-NOTES section 3 and S0/S4.
#include "dem/DemSystem.h"
#include "dem/TimeStep.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::dem;

namespace {

struct ImpactResult
{
  double duration = 0.0;
  double restitution = 0.0;
  double max_overlap = 0.0;
};

/// Two equal spheres approaching along x at relative speed v0; runs until they separate.
ImpactResult pair_impact(const ContactModel& law, double R, double v0, double dt)
{
  DemSystem sys;
  sys.set_contact_model(law);
  sys.add_sphere(Vec3(0.0, 0.0, 0.0), R, 2650.0, Vec3(0.5 * v0, 0, 0));
  sys.add_sphere(Vec3(2.0 * R + 2.0 * v0 * dt, 0.0, 0.0), R, 2650.0, Vec3(-0.5 * v0, 0, 0));
  sys.set_time_step(dt);
  ImpactResult r;
  double t_start = -1.0, t_end = -1.0;
  double prev_overlap = 0.0, prev_time = 0.0;
  for (int s = 0; s < 10'000'000; ++s) {
    sys.step();
    const Vec3 d = sys.position(1) - sys.position(0);
    const double overlap = 2.0 * R - d.norm();
    r.max_overlap = std::max(r.max_overlap, overlap);
    // Linear interpolation of the overlap's zero crossings.
    if (t_start < 0.0 && overlap > 0.0) t_start = prev_time + dt * (0.0 - prev_overlap) / (overlap - prev_overlap);
    if (t_start >= 0.0 && overlap <= 0.0) {
      t_end = prev_time + dt * (0.0 - prev_overlap) / (overlap - prev_overlap);
      break;
    }
    prev_overlap = overlap;
    prev_time = sys.time();
  }
  r.duration = t_end - t_start;
  const double v_after = (sys.velocity(1) - sys.velocity(0)).x();
  r.restitution = v_after / v0;
  return r;
}

/// Restitution of the clamped linear oscillator m x'' = -max(k x + c x', 0), by RK4
/// with a tiny step: the reference for the clamped law (DEM-NOTES section 3 table).
double clamped_restitution_by_ode(double m, double k, double c, double v0)
{
  double x = 0.0, v = v0;  // x: overlap, v: d(overlap)/dt
  const double h = 1e-4 * M_PI * std::sqrt(m / k);
  auto acc = [&](double xx, double vv) { return -std::max(k * xx + c * vv, 0.0) / m; };
  for (int s = 0; s < 10'000'000; ++s) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x <= 0.0 && v < 0.0) break;
  }
  return -v / v0;
}

}  // namespace

TEST(LinearImpact, ContactDurationAndRestitutionMatchDampedOscillator)
{
  const double R = 0.01, k = 1e5, e = 0.5, v0 = 0.2;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0, m_eff = 0.5 * m;
  // Closed forms, computed here: zeta from e, c = 2 zeta sqrt(m* k), t_c = pi/(w0 sqrt(1-zeta^2)).
  const double zeta = -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e));
  const double w0 = std::sqrt(k / m_eff);
  const double t_c = M_PI / (w0 * std::sqrt(1.0 - zeta * zeta));
  const ImpactResult r = pair_impact(test::linear_law(k, e), R, v0, t_c / 1000.0);
  EXPECT_NEAR(r.duration / t_c, 1.0, 0.01);
  EXPECT_NEAR(r.restitution / e, 1.0, 0.01);
}

TEST(LinearImpact, DirectDashpotGivesOscillatorDurationAndRestitution)
{
  const double R = 0.0118, k = 1e6, c = 41.149, v0 = 0.5;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0, m_eff = 0.5 * m;
  LinearNormal::Parameters p;
  p.k_n = k;
  p.damping_input = LinearNormal::Damping::direct;
  p.c_n = c;
  p.clamp_tensile = false;
  const LinearSpringDashpot law(LinearNormal(p), LinearTangential::with_ratio(2.0 / 7.0));
  const double w2 = k / m_eff - std::pow(c / (2.0 * m_eff), 2);
  const double t_c = M_PI / std::sqrt(w2);
  const double e = std::exp(-c / (2.0 * m_eff) * t_c);
  const ImpactResult r = pair_impact(law, R, v0, t_c / 1000.0);
  EXPECT_NEAR(r.duration / t_c, 1.0, 0.01);
  EXPECT_NEAR(r.restitution / e, 1.0, 0.01);
}

TEST(LinearImpact, ClampedLawMatchesClampedOscillator)
{
  const double R = 0.01, k = 1e5, e = 0.3, v0 = 0.2;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0, m_eff = 0.5 * m;
  const double zeta = -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e));
  const double c = 2.0 * zeta * std::sqrt(m_eff * k);
  const double e_clamped = clamped_restitution_by_ode(m_eff, k, c, v0);
  EXPECT_GT(e_clamped, e + 0.05);  // the clamp raises e (DEM-NOTES table)
  const ImpactResult r = pair_impact(test::linear_law(k, e, 2.0 / 7.0, true), R, v0, 1e-3 * M_PI * std::sqrt(m_eff / k));
  EXPECT_NEAR(r.restitution / e_clamped, 1.0, 0.01);
}

TEST(LinearImpact, S0StiffnessReproducesHertzMaxOverlapAtImpactSpeed)
{
  // S0's k_n is the secant Hertz stiffness at V_c: a linear impact at V_c reaches the
  // Hertz maximum overlap (15 m* V_c^2 / (16 E* sqrt(R*)))^(2/5).
  const double R = 0.01, E = 1e9, nu = 0.25, Vc = 0.5;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0, m_eff = 0.5 * m, r_eff = 0.5 * R;
  const double e_star = E / (2.0 * (1.0 - nu * nu));
  LinearNormal::Parameters p;
  p.stiffness_input = LinearNormal::Stiffness::from_impact_velocity;
  p.youngs_modulus = E;
  p.poisson_ratio = nu;
  p.impact_velocity = Vc;
  p.restitution = 1.0;
  const LinearSpringDashpot law(LinearNormal(p), LinearTangential::with_ratio(1.0));
  const double k = law.normal().stiffness(m_eff, r_eff);
  const double delta_hertz = std::pow(15.0 * m_eff * Vc * Vc / (16.0 * e_star * std::sqrt(r_eff)), 0.4);
  const ImpactResult r = pair_impact(law, R, Vc, 1e-3 * std::sqrt(m_eff / k));
  EXPECT_NEAR(r.max_overlap / delta_hertz, 1.0, 0.01);
  EXPECT_NEAR(r.restitution, 1.0, 1e-3);
}

TEST(HertzImpact, ContactDurationMatchesClosedForm)
{
  const double R = 0.01, E = 7e10, nu = 0.25, v0 = 1.0;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0, m_eff = 0.5 * m, r_eff = 0.5 * R;
  const double e_star = E / (2.0 * (1.0 - nu * nu));
  const double t_h = 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * v0), 0.2);
  const double delta_max = std::pow(15.0 * m_eff * v0 * v0 / (16.0 * e_star * std::sqrt(r_eff)), 0.4);
  const HertzMindlin law(HertzNormal({E, nu, HertzNormal::Damping::restitution, 1.0, 0.0, true}),
                         MindlinTangential({E, nu, 1.0}));
  const ImpactResult r = pair_impact(law, R, v0, t_h / 2000.0);
  EXPECT_NEAR(r.duration / t_h, 1.0, 0.01);
  EXPECT_NEAR(r.max_overlap / delta_max, 1.0, 0.01);
  EXPECT_NEAR(r.restitution, 1.0, 1e-3);
}

TEST(HertzImpact, RestitutionIsTargetAndIndependentOfSpeed)
{
  const double R = 0.01, E = 7e10, nu = 0.25, e = 0.7;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0, m_eff = 0.5 * m, r_eff = 0.5 * R;
  const double e_star = E / (2.0 * (1.0 - nu * nu));
  const HertzMindlin law(HertzNormal({E, nu, HertzNormal::Damping::restitution, e, 0.0, false}),
                         MindlinTangential({E, nu, 1.0}));
  for (double v0 : {0.05, 1.0, 5.0}) {
    const double t_h = 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * v0), 0.2);
    const ImpactResult r = pair_impact(law, R, v0, t_h / 2000.0);
    EXPECT_NEAR(r.restitution / e, 1.0, 0.01) << "v0 = " << v0;
  }
}

TEST(HertzImpact, SphereOnWallUsesSphereMassAndRadius)
{
  // A wall is a body of infinite radius and mass: m* = m, R* = R.
  const double R = 0.01, E = 7e10, nu = 0.25, v0 = 1.0;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0;
  const double e_star = E / (2.0 * (1.0 - nu * nu));
  const double t_h = 2.868 * std::pow(m * m / (R * e_star * e_star * v0), 0.2);
  DemSystem sys;
  sys.set_contact_model(HertzMindlin(HertzNormal({E, nu, HertzNormal::Damping::restitution, 1.0, 0.0, true}),
                                     MindlinTangential({E, nu, 1.0})));
  const double dt = t_h / 2000.0;
  sys.add_sphere(Vec3(0, 0, R + v0 * dt), R, 2650.0, Vec3(0, 0, -v0));
  PlaneWall floor;
  floor.normal = Vec3::UnitZ();
  sys.add_wall(floor);
  sys.set_time_step(dt);
  double t_in = -1.0, t_out = -1.0;
  for (int s = 0; s < 100000 && t_out < 0.0; ++s) {
    sys.step();
    const bool touching = sys.wall(0).n_contacts > 0;
    if (touching && t_in < 0.0) t_in = sys.time();
    if (!touching && t_in >= 0.0) t_out = sys.time();
  }
  EXPECT_NEAR((t_out - t_in) / t_h, 1.0, 0.01);
  EXPECT_NEAR(sys.velocity(0).z() / v0, 1.0, 1e-3);
}
