#include "compare/LocalizationOnsets.h"

#include "continuum/models/RudnickiRice.h"

#include <cmath>

namespace geocomp::compare {

double onset_strain(const Tensor3 &strain, const Tensor3 &reference, CurveKind kind, const AxialAxis &axial)
{
  const Tensor3 e = relative_log_strain(strain, reference);
  return kind == CurveKind::AxialLateral ? axial.sense * e(axial.axis, axial.axis) : gamma_max(e);
}

std::vector<double> onset_strain_measure(const Response &r, CurveKind kind, int stage,
                                         std::vector<std::size_t> &samples, std::optional<AxialAxis> axial)
{
  samples.clear();
  int s = stage;
  if (s < 0)
    for (const auto &x : r.samples)
      s = std::max(s, x.stage);
  const AxialAxis axis = kind == CurveKind::AxialLateral && !axial ? guess_axial_axis(r, s) : axial.value_or(AxialAxis{});
  std::vector<double> out;
  Tensor3 ref = Tensor3::Zero();
  bool have_ref = false;
  std::size_t previous_main = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const ResponseSample &x = r.samples[i];
    if (x.branch != 0)
      continue;
    if (x.stage == s) {
      if (!have_ref) {
        ref = r.samples[previous_main].strain;
        have_ref = true;
      }
      out.push_back(onset_strain(x.strain, ref, kind, axis));
      samples.push_back(i);
    }
    previous_main = i;
  }
  return out;
}

namespace {
/// RR's gamma^p per Mohr-Coulomb kappa on the main plane (kappa = eps1^p - eps3^p):
/// principal plastic increments (1 + sin psi, 0, -(1 - sin psi)) dgamma, kappa = 2 dgamma.
double shear_measure_ratio(double psi)
{
  const double s = std::sin(psi);
  const Vector3 ep(1 + s, 0, -(1 - s));
  const Vector3 dev = ep - Vector3::Constant(ep.sum() / 3);
  return std::sqrt(2 * dev.squaredNorm()) / 2.0;
}

double kappa_derivative(const continuum::PiecewiseLinear &f, double kappa)
{
  const double h = 1e-7;
  return (f(kappa + h) - f(std::max(0.0, kappa - h))) / (kappa + h - std::max(0.0, kappa - h));
}
} // namespace

OnsetEstimate rudnicki_rice_onset(const Response &r, const continuum::MohrCoulombParameters &mc,
                                  continuum::DruckerPragerMatching matching, KappaMeasure measure, CurveKind kind,
                                  int stage, std::optional<AxialAxis> axial)
{
  const int k_kappa = r.extra_index("kappa");
  if (k_kappa < 0) {
    OnsetEstimate e;
    e.source = "Rudnicki-Rice";
    e.note = "the response has no 'kappa' column";
    return e;
  }
  std::vector<std::size_t> idx;
  const std::vector<double> strain = onset_strain_measure(r, kind, stage, idx, axial);
  const double G = mc.youngs_modulus / (2 * (1 + mc.poisson_ratio));
  const int k_flag = r.extra_index("state_flag");
  std::vector<double> indicator, angle;
  for (std::size_t i : idx) {
    const ResponseSample &s = r.samples[i];
    const double kappa = s.extras[k_kappa];
    if (k_flag >= 0 && s.extras[k_flag] == 0.0) { // elastic: theory applies on the yield surface only
      indicator.push_back(1.0);
      angle.push_back(0.0);
      continue;
    }
    const double phi = mc.friction_angle(kappa), psi = mc.dilatancy_angle(kappa), c = mc.cohesion(kappa);
    const auto m = continuum::match_mohr_coulomb(phi, psi, matching);
    // Slopes of the matched cone's strength Y = y_over_c c and friction omega in kappa.
    const double h_k = 1e-7;
    const auto m2 = continuum::match_mohr_coulomb(mc.friction_angle(kappa + h_k), mc.dilatancy_angle(kappa + h_k),
                                                  matching);
    const double dY = m.y_over_c * kappa_derivative(mc.cohesion, kappa) + c * (m2.y_over_c - m.y_over_c) / h_k;
    const double domega = (m2.omega - m.omega) / h_k;
    const double p = mean_stress(s.stress);
    // d tau_bar / d gamma^p: kappa is gamma^p for Drucker-Prager, f(psi) gamma^p for Mohr-Coulomb.
    const double f = measure == KappaMeasure::mohr_coulomb ? shear_measure_ratio(psi) : 1.0;
    const double h = (dY - 3 * p * domega) / f;
    const continuum::RudnickiRiceMaterial mat{3 * m.omega, m.lambda, mc.poisson_ratio};
    const double N = continuum::deviatoric_state(s.stress);
    const auto pred = continuum::rudnicki_rice_prediction(mat, N);
    indicator.push_back(h / G - pred.critical_hardening_over_G);
    angle.push_back(pred.band_normal_angle * 180.0 / M_PI);
  }
  OnsetEstimate e = first_crossing("Rudnicki-Rice", strain, indicator, angle);
  if (!e.found)
    e.note = "h stays above h_cr along the path";
  return e;
}

OnsetEstimate acoustic_tensor_onset(const Response &r, const std::string &source, CurveKind kind, int stage,
                                    std::optional<AxialAxis> axial)
{
  const int kq = r.extra_index("localization_q"), kx = r.extra_index("localization_nx"),
            ky = r.extra_index("localization_ny"), kz = r.extra_index("localization_nz");
  if (kq < 0) {
    OnsetEstimate e;
    e.source = source;
    e.note = "no acoustic-tensor indicator in this response";
    return e;
  }
  std::vector<std::size_t> idx;
  const std::vector<double> strain = onset_strain_measure(r, kind, stage, idx, axial);
  std::vector<double> q, angle;
  for (std::size_t i : idx) {
    const ResponseSample &s = r.samples[i];
    q.push_back(s.extras[kq]);
    double a = 0.0;
    if (kx >= 0 && ky >= 0 && kz >= 0) {
      const Vector3 n(s.extras[kx], s.extras[ky], s.extras[kz]);
      Eigen::SelfAdjointEigenSolver<Tensor3> eig(s.stress);
      const Vector3 compressive = eig.eigenvectors().col(0); // most compressive (tension positive)
      if (n.norm() > 0)
        a = std::acos(std::min(1.0, std::abs(n.normalized().dot(compressive)))) * 180.0 / M_PI;
    }
    angle.push_back(a);
  }
  OnsetEstimate e = first_crossing(source, strain, q, angle);
  e.has_angle = kx >= 0;
  // The engines record the band normal from the onset on: take it there, not interpolated.
  for (std::size_t i = 0; i < q.size(); ++i)
    if (q[i] <= 0.0) {
      e.angle_deg = angle[i];
      break;
    }
  if (!e.found)
    e.note = "the acoustic tensor stays positive definite";
  return e;
}

} // namespace geocomp::compare
