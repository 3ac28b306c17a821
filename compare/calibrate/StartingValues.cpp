#include "compare/calibrate/StartingValues.h"

#include "common/Tensor.h"
#include "compare/Metrics.h"

#include <Eigen/Dense>

#include <algorithm>
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
  std::vector<double> E_axial, G_shear, nus, psis;
  std::vector<std::pair<double, double>> peaks; // (sigma_3, sigma_1), compression positive
  double phi_single = std::nan("");
  for (const auto &t : targets) {
    compare::MetricOptions o;
    o.kind = compare::curve_kind_for(t.program);
    const compare::MetricSet m = compare::compute_metrics(t.response, o);
    if (o.kind == compare::CurveKind::AxialLateral) {
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
    if (std::isfinite(m.dilatancy_angle_deg))
      psis.push_back(m.dilatancy_angle_deg);
  }
  auto mean = [](const std::vector<double> &v) {
    double s = 0.0;
    for (double x : v)
      s += x;
    return s / double(v.size());
  };
  if (!nus.empty()) {
    p.poisson_ratio = mean(nus);
    out.notes.push_back("nu = " + str(p.poisson_ratio) + " from the initial lateral/axial strain ratio");
  }
  if (!E_axial.empty()) {
    p.youngs_modulus = mean(E_axial);
    out.notes.push_back("E = " + str(p.youngs_modulus) + " Pa from the initial axial slope");
  } else if (!G_shear.empty()) {
    p.youngs_modulus = 2.0 * mean(G_shear) * (1.0 + p.poisson_ratio);
    out.notes.push_back("E = " + str(p.youngs_modulus) + " Pa from G = d tau/d gamma and nu");
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
  if (!psis.empty()) {
    const double psi = std::clamp(mean(psis), 0.0, 60.0);
    scale_table(p.dilatancy_angle, psi);
    out.notes.push_back("psi = " + str(psi) + " deg from the volumetric slope at the peak");
  }
  return out;
}

} // namespace geocomp::calibration
