#include "compare/calibrate/StartingValues.h"

#include "common/Tensor.h"
#include "compare/Metrics.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace geocomp::calibration {

namespace {
void scale_table(HardeningTable &t, double target_max)
{
  double m = 0.0;
  for (const auto &p : t.points)
    m = std::max(m, p.second);
  if (m <= 0.0) {
    for (auto &p : t.points)
      p.second = target_max;
    return;
  }
  for (auto &p : t.points)
    p.second *= target_max / m;
}

/// The strain and stress in which Hooke's law is linear for the case's kinematics: at finite
/// strain the logarithmic strain ln(I + eps) and the Kirchhoff stress J sigma (Hencky
/// elasticity, FiniteStrain.h), at small strain the engineering strain and the stress.
struct HookeMeasures {
  bool finite = true;
  Tensor3 strain(const ResponseSample &s) const { return finite ? logarithmic_strain(s.strain) : s.strain; }
  Tensor3 stress(const ResponseSample &s) const
  {
    return finite ? Tensor3((Tensor3::Identity() + s.strain).determinant() * s.stress) : s.stress;
  }
};

/// E and nu from the unloading branches, which S0 takes as elastic (the residual strain
/// after unloading from O-A-B is small). Hooke's law in increments from each branch's start,
///   d eps = (1/E) d sigma + (nu/E) (d sigma - tr(d sigma) I),
/// is linear in a = 1/E and b = nu/E; a least-squares fit over every component of the first
/// half of every branch gives both. A purely deviatoric branch (tr d sigma = 0, isochoric
/// shear) sees only a + b = 1/(2G): then only G is returned.
struct Elasticity {
  double E = std::nan(""), nu = std::nan(""), G = std::nan("");
  std::size_t branches = 0;
};

Elasticity unloading_elasticity(const Response &r, const HookeMeasures &m)
{
  std::vector<std::array<double, 3>> rows; // (d sigma_ij, d sigma_ij - tr d sigma delta_ij, d eps_ij)
  Elasticity out;
  for (const BranchRecord &b : r.branches) {
    const std::vector<const ResponseSample *> path = r.path(b.id);
    if (path.size() < 2 || b.first_sample >= r.samples.size())
      continue;
    const ResponseSample &start = r.samples[b.first_sample];
    ++out.branches;
    for (std::size_t k = 0; k < (path.size() + 1) / 2; ++k) {
      const Tensor3 ds = m.stress(*path[k]) - m.stress(start);
      const Tensor3 de = m.strain(*path[k]) - m.strain(start);
      const Tensor3 dev = ds - ds.trace() * Tensor3::Identity();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          rows.push_back({{ds(i, j), dev(i, j), de(i, j)}});
    }
  }
  if (rows.size() < 9)
    return out;
  Eigen::MatrixXd A(rows.size(), 2);
  Eigen::VectorXd y(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    A(k, 0) = rows[k][0];
    A(k, 1) = rows[k][1];
    y(k) = rows[k][2];
  }
  const double scale = A.norm();
  if (!(scale > 0.0))
    return out;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A / scale, Eigen::ComputeThinU | Eigen::ComputeThinV);
  if (svd.singularValues()(1) > 1e-3 * svd.singularValues()(0)) {
    const Eigen::Vector2d ab = svd.solve(y) / scale;
    if (ab(0) > 0.0) {
      out.E = 1.0 / ab(0);
      out.nu = ab(1) / ab(0);
      out.G = out.E / (2.0 * (1.0 + out.nu));
    }
  } else {
    // Only a + b: d eps = (a + b) d sigma on the deviatoric components.
    const Eigen::VectorXd s = A.col(0);
    const double a_plus_b = s.dot(y) / s.squaredNorm();
    if (a_plus_b > 0.0)
      out.G = 0.5 / a_plus_b;
  }
  return out;
}

/// psi of an axial curve at constant lateral stress from the plastic flow at and after
/// the peak, where the return sits on the compression corner of the Mohr-Coulomb cone:
///   d eps_v^p / d(-eps_zz^p) = N_psi - 1,  N_psi = (1 + sin psi)/(1 - sin psi)
/// (dilation positive; CONTINUUM-THEORY section 6, "post-peak d eps_v/d eps_1 = 1 - N_psi"
/// written compression positive). The elastic parts come from the stress change with the
/// estimated E and nu: eps^e = ((1 + nu) d sigma - nu tr(d sigma) I)/E. NaN when fewer
/// than two samples stay within 10 % of the peak deviator.
double axial_dilatancy_deg(const FitTarget &t, double E, double nu, const HookeMeasures &m)
{
  const auto &s = t.response.samples;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < t.samples.size(); ++i)
    if (deviator(s[t.samples[i]].stress) > deviator(s[t.samples[peak]].stress))
      peak = i;
  const double q_peak = deviator(s[t.samples[peak]].stress);
  std::vector<double> x, y;
  auto add = [&](std::size_t i) {
    const ResponseSample &a = s[t.samples[i]];
    const Tensor3 ds = m.stress(a) - m.stress(s[0]);
    const Tensor3 elastic = ((1.0 + nu) * ds - nu * ds.trace() * Tensor3::Identity()) / E;
    const Tensor3 de = m.strain(a) - m.strain(s[0]);
    x.push_back(-(de(2, 2) - elastic(2, 2)));
    // tr of the strain the flow rule speaks of (not det(I + eps) - 1 at small strain).
    y.push_back(de.trace() - elastic.trace());
  };
  for (std::size_t i = peak; i < t.samples.size() && deviator(s[t.samples[i]].stress) >= 0.9 * q_peak; ++i)
    add(i);
  if (x.size() < 2 && peak > 0)
    add(peak - 1);
  const compare::LineFit line = compare::fit_line(x, y, 0, x.size());
  if (!(x.size() >= 2) || !std::isfinite(line.slope) || !(q_peak > 0.0))
    return std::nan("");
  const double N = std::max(1.0 + line.slope, 1.0);
  return std::asin((N - 1.0) / (N + 1.0)) * 180.0 / M_PI;
}

std::string str(double v)
{
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}
} // namespace

StartingValues closed_form_start(const ContinuumParameters &base, const std::vector<FitTarget> &targets)
{
  StartingValues out{base, {}};
  ContinuumParameters &p = out.parameters;
  const HookeMeasures measures{base.kinematics != "small strain"};
  std::vector<double> E_axial, G_shear, nus, psis, E_unload, nu_unload, G_unload;
  std::size_t unloading_branches = 0;
  std::vector<const FitTarget *> axial_targets;
  std::vector<std::pair<double, double>> peaks; // (sigma_3, sigma_1), compression positive
  double phi_single = std::nan("");
  for (const auto &t : targets) {
    const Elasticity unload = unloading_elasticity(t.response, measures);
    unloading_branches += unload.branches;
    if (std::isfinite(unload.E) && unload.nu > -1.0 && unload.nu < 0.5) {
      E_unload.push_back(unload.E);
      nu_unload.push_back(unload.nu);
    } else if (std::isfinite(unload.G)) {
      G_unload.push_back(unload.G);
    }
    compare::MetricOptions o;
    o.kind = compare::curve_kind_for(t.program);
    const compare::MetricSet m = compare::compute_metrics(t.response, o);
    if (o.kind == compare::CurveKind::AxialLateral) {
      axial_targets.push_back(&t);
      if (std::isfinite(m.initial_modulus))
        E_axial.push_back(m.initial_modulus);
      // nu from the first main-path samples up to a quarter of the peak rise.
      const auto &s = t.response.samples;
      double sxz = 0.0, szz = 0.0;
      for (std::size_t k : t.samples) {
        if (std::isfinite(m.peak_stress) &&
            std::abs(-s[k].stress(2, 2) - (-s[0].stress(2, 2))) > 0.25 * std::abs(m.peak_stress - m.y0))
          break;
        const double dz = s[k].strain(2, 2) - s[0].strain(2, 2);
        const double dx = 0.5 * (s[k].strain(0, 0) + s[k].strain(1, 1) - s[0].strain(0, 0) - s[0].strain(1, 1));
        sxz += dx * dz;
        szz += dz * dz;
      }
      if (szz > 0.0)
        nus.push_back(std::clamp(-sxz / szz, 0.0, 0.49));
      if (std::isfinite(m.peak_stress)) {
        // The peak sample's principal stresses, compression positive.
        const auto peak = std::max_element(t.samples.begin(), t.samples.end(), [&](std::size_t a, std::size_t b) {
          return deviator(s[a].stress) < deviator(s[b].stress);
        });
        const Vector3 pv = principal_values(s[*peak].stress); // ascending, tension positive
        peaks.emplace_back(-pv(2), -pv(0));
      }
    } else if (std::isfinite(m.initial_modulus)) {
      G_shear.push_back(m.initial_modulus);
    }
    if (std::isfinite(m.friction_peak_deg))
      phi_single = m.friction_peak_deg;
    if (o.kind != compare::CurveKind::AxialLateral && std::isfinite(m.dilatancy_angle_deg))
      psis.push_back(m.dilatancy_angle_deg); // sin psi = d eps_v^p / d gamma^p (docs/metrics.md)
  }
  auto mean = [](const std::vector<double> &v) {
    double s = 0.0;
    for (double x : v)
      s += x;
    return s / double(v.size());
  };
  // Unloading slopes first (elastic in S0's reading), then the initial loading slopes.
  if (!nu_unload.empty()) {
    p.poisson_ratio = std::clamp(mean(nu_unload), 0.0, 0.49);
    p.youngs_modulus = mean(E_unload);
    out.notes.push_back("E = " + str(p.youngs_modulus) + " Pa, nu = " + str(p.poisson_ratio) + " from " +
                        std::to_string(unloading_branches) + " unloading branches");
  } else {
    if (!nus.empty()) {
      p.poisson_ratio = mean(nus);
      out.notes.push_back("nu = " + str(p.poisson_ratio) + " from the initial lateral/axial strain ratio");
    }
    if (!G_unload.empty()) {
      p.youngs_modulus = 2.0 * mean(G_unload) * (1.0 + p.poisson_ratio);
      out.notes.push_back("E = " + str(p.youngs_modulus) + " Pa from G of " + std::to_string(unloading_branches) +
                          " unloading branches and nu");
    } else if (!E_axial.empty()) {
      p.youngs_modulus = mean(E_axial);
      out.notes.push_back("E = " + str(p.youngs_modulus) + " Pa from the initial axial slope");
    } else if (!G_shear.empty()) {
      p.youngs_modulus = 2.0 * mean(G_shear) * (1.0 + p.poisson_ratio);
      out.notes.push_back("E = " + str(p.youngs_modulus) + " Pa from G = d tau/d gamma and nu");
    }
  }
  // Peak Mohr envelope (compression positive): sigma_1 = N sigma_3 + 2 c sqrt(N).
  std::sort(peaks.begin(), peaks.end());
  if (peaks.size() >= 2 && peaks.back().first - peaks.front().first > 1e-6 * std::abs(peaks.back().first)) {
    Eigen::MatrixXd A(peaks.size(), 2);
    Eigen::VectorXd b(peaks.size());
    for (std::size_t k = 0; k < peaks.size(); ++k) {
      A(k, 0) = peaks[k].first;
      A(k, 1) = 1.0;
      b(k) = peaks[k].second;
    }
    const Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
    const double N = std::max(x(0), 1.0 + 1e-6);
    const double phi = std::asin((N - 1.0) / (N + 1.0)) * 180.0 / M_PI;
    const double c = std::max(0.0, x(1) / (2.0 * std::sqrt(N)));
    scale_table(p.friction_angle, phi);
    scale_table(p.cohesion, c);
    out.notes.push_back("phi = " + str(phi) + " deg, c = " + str(c) + " Pa from the peak Mohr envelope of " +
                        std::to_string(peaks.size()) + " curves");
  } else if (std::isfinite(phi_single)) {
    scale_table(p.friction_angle, phi_single);
    out.notes.push_back("phi = " + str(phi_single) + " deg from the peak (c = 0)");
  }
  // psi from the plastic volumetric slope at the peak of the axial curves (needs E, nu).
  std::vector<double> axial_psis;
  for (const FitTarget *t : axial_targets) {
    const double psi = axial_dilatancy_deg(*t, p.youngs_modulus, p.poisson_ratio, measures);
    if (std::isfinite(psi))
      axial_psis.push_back(psi);
  }
  if (!axial_psis.empty())
    psis = axial_psis;
  if (!psis.empty()) {
    const double psi = std::clamp(mean(psis), 0.0, 60.0);
    scale_table(p.dilatancy_angle, psi);
    out.notes.push_back("psi = " + str(psi) + " deg from the plastic volumetric slope at the peak of " +
                        std::to_string(psis.size()) + " curves");
  }
  return out;
}

StartingValues starting_values(const ContinuumParameters &case_section, const std::vector<FitTarget> &targets,
                               const CalibrationParameters &options)
{
  const FreeParameters free(case_section, options);
  if (options.starting_values != "closed-form")
    return {case_section, {"starting values: the case's"}};
  const StartingValues estimates = closed_form_start(case_section, targets);
  StartingValues out{free.apply(case_section, free.values(estimates.parameters)), {}};
  // Mohr-Coulomb needs psi <= phi at every kappa: a free dilatancy knot starts at most at
  // the friction angle there (the fit keeps to that range, Calibration.cpp).
  for (const FreeParameter &f : free.list())
    if (f.family == FreeParameter::Family::Dilatancy) {
      auto &[kappa, psi] = out.parameters.dilatancy_angle.points[f.knot];
      if (psi > out.parameters.friction_angle(kappa)) {
        psi = out.parameters.friction_angle(kappa);
        out.notes.push_back("closed-form estimate: " + f.name + " lowered to the friction angle at its kappa (" +
                            str(psi) + " deg): Mohr-Coulomb needs psi <= phi");
      }
    }
  for (const auto &note : estimates.notes)
    out.notes.push_back("closed-form estimate (the start of the free parameters only): " + note);
  std::string fixed;
  const FreeParameters every = FreeParameters::all(case_section);
  for (const FreeParameter &p : every.list())
    if (!free.contains(p.name))
      fixed += (fixed.empty() ? "" : ", ") + p.name;
  if (!fixed.empty())
    out.notes.push_back("fixed at the case's values: " + fixed);
  return out;
}

} // namespace geocomp::calibration
