#pragma once
// Synthetic responses with known answers for the compare tests.
//
// Backbone of the shear curve tau(gamma) (all closed form, so every expected metric is
// computed in the test from these formulas):
//   linear      tau = E g                                  for g <= g_e = tau_e / E
//   parabola    tau = tau_e + (tau_p - tau_e)(2u - u^2),   u = (g - g_e)/D, D = 2(tau_p - tau_e)/E
//               (slope E at g_e, zero at the peak g_p = g_e + D: tangent-continuous)
//   softening   tau = tau_p - H (g - g_p)                  down to tau_r
//   residual    tau = tau_r
#include "common/Response.h"

#include <cmath>
#include <random>

namespace geocomp::compare::testing {

struct Backbone {
  double E = 500e6, tau_e = 2e6, tau_p = 5e6, H = 100e6, tau_r = 3e6;
  double g_end = 0.06;

  double g_e() const { return tau_e / E; }
  double D() const { return 2.0 * (tau_p - tau_e) / E; }
  double g_p() const { return g_e() + D(); }
  double g_r() const { return g_p() + (tau_p - tau_r) / H; }
  double tau(double g) const
  {
    if (g <= g_e())
      return E * g;
    if (g <= g_p()) {
      const double u = (g - g_e()) / D();
      return tau_e + (tau_p - tau_e) * (2 * u - u * u);
    }
    return std::max(tau_r, tau_p - H * (g - g_p()));
  }
};

/// Isochoric lambda = 0 box strain whose logarithmic gamma_max is g exactly (the metrics'
/// measure): log strains (-g/2, 0, g/2), engineering strains exp(.) - 1.
inline Tensor3 isochoric_strain(double g)
{
  Tensor3 e = Tensor3::Zero();
  e(0, 0) = std::expm1(-0.5 * g);
  e(2, 2) = std::expm1(0.5 * g);
  return e;
}

/// Stress with tau_max = tau about the mean -p0 (sigma_x most compressive).
inline Tensor3 shear_stress(double tau, double p0)
{
  Tensor3 s = -p0 * Tensor3::Identity();
  s(0, 0) -= tau;
  s(2, 2) += tau;
  return s;
}

inline ResponseSample shear_sample(double t, double g, double tau, double p0, int branch = 0)
{
  ResponseSample s;
  s.time = t;
  s.strain = isochoric_strain(g);
  s.stress = shear_stress(tau, p0);
  s.branch = branch;
  return s;
}

/// Main path sampled every dg; optional Gaussian noise on tau (fixed seed); optional
/// unloading branches (elastic, slope E_unload, down to tau = 0) at the given gammas.
inline Response shear_response(const Backbone &b, double dg, double noise = 0.0,
                               const std::vector<double> &branch_at = {}, double E_unload = 0.0,
                               double p0 = 8e6, unsigned seed = 7)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Response r;
  r.engine = "synthetic";
  std::size_t next_branch = 0;
  const int n = static_cast<int>(std::lround(b.g_end / dg));
  for (int i = 0; i <= n; ++i) {
    const double g = i * dg;
    const double tau = b.tau(g) + (i > 0 ? noise * normal(rng) : 0.0);
    r.samples.push_back(shear_sample(i, g, tau, p0));
    while (next_branch < branch_at.size() && g >= branch_at[next_branch] - 1e-12) {
      BranchRecord rec;
      rec.id = static_cast<int>(next_branch) + 1;
      rec.first_sample = r.samples.size() - 1;
      rec.tau_start = tau;
      rec.gamma_start = g;
      const int m = 20;
      for (int k = 1; k <= m; ++k) {
        const double tk = tau * (1.0 - double(k) / m);
        r.samples.push_back(shear_sample(i + 0.01 * k, g - (tau - tk) / E_unload, tk, p0, rec.id));
      }
      rec.last_sample = r.samples.size() - 1;
      rec.residual_gamma = g - tau / E_unload;
      rec.reached_target = true;
      r.branches.push_back(rec);
      ++next_branch;
    }
  }
  return r;
}

} // namespace geocomp::compare::testing
