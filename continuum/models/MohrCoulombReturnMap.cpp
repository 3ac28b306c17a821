#include "continuum/models/MohrCoulombReturnMap.h"

#include "continuum/models/ScalarRoot.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::continuum {

void MohrCoulombParameters::validate() const {
  IsotropicElasticity check(youngs_modulus, poisson_ratio);
  (void)check;
  const double half_pi = 2.0 * std::atan(1.0);
  if (cohesion.min_value() < 0.0)
    throw std::invalid_argument("Mohr-Coulomb: cohesion must be >= 0");
  if (!(friction_angle.min_value() > 0.0) || !(friction_angle.max_value() < half_pi))
    throw std::invalid_argument("Mohr-Coulomb: friction angle must lie in (0, pi/2)");
  if (dilatancy_angle.min_value() < 0.0 || !(dilatancy_angle.max_value() < half_pi))
    throw std::invalid_argument("Mohr-Coulomb: dilatancy angle must lie in [0, pi/2)");
  if (!(apex_min_dilatancy > 0.0))
    throw std::invalid_argument("Mohr-Coulomb: apex_min_dilatancy must be > 0");
  // psi <= phi at every kappa: both tables are piecewise linear, so at every knot of either.
  std::vector<double> knots = friction_angle.breakpoints();
  knots.insert(knots.end(), dilatancy_angle.breakpoints().begin(), dilatancy_angle.breakpoints().end());
  for (double kappa : knots)
    if (dilatancy_angle(kappa) > friction_angle(kappa) + 1e-12)
      throw std::invalid_argument("Mohr-Coulomb: the dilatancy angle exceeds the friction angle at kappa = " +
                                  std::to_string(kappa));
}

MohrCoulombReturnMap::MohrCoulombReturnMap(MohrCoulombParameters parameters)
    : p_(std::move(parameters)), elastic_(p_.youngs_modulus, p_.poisson_ratio) {
  p_.validate();
  D_hat_ = elastic_.principal_stiffness();
}

MohrCoulombStrength MohrCoulombReturnMap::strength(double kappa) const {
  return {p_.cohesion.value(kappa),        p_.cohesion.slope(kappa),
          p_.friction_angle.value(kappa),  p_.friction_angle.slope(kappa),
          p_.dilatancy_angle.value(kappa), p_.dilatancy_angle.slope(kappa)};
}

double MohrCoulombReturnMap::yield_principal(const Vector3 &s, double kappa) const {
  const MohrCoulombStrength st = strength(kappa);
  return (s(0) - s(2)) + (s(0) + s(2)) * std::sin(st.phi) - 2.0 * st.c * std::cos(st.phi);
}

Vector3 MohrCoulombReturnMap::flow_generator(int i, int j, double psi) {
  Vector3 g = Vector3::Zero();
  g(i) = 1.0 + std::sin(psi);
  g(j) = -(1.0 - std::sin(psi));
  return g;
}

namespace {
// Scale of a stress problem, for relative tolerances.
double stress_scale(const Vector3 &trial, double c) {
  return std::max(trial.cwiseAbs().maxCoeff(), std::max(c, 1e-300));
}
} // namespace

// Newton on the multipliers of m active planes (m = 1 or 2). See the header for J and the
// tangent. If Newton does not converge (a kink of a piecewise-linear table), fall back to a
// bracketed scalar solve in kappa: for a fixed kappa the planes' conditions are linear in
// the multipliers, x(kappa) = (F D_hat G)^{-1} (F s_tr - 2 c cos(phi) 1), and the remaining
// equation is rho(kappa) = kappa - kappa_n - 2 sum x(kappa) = 0.
bool MohrCoulombReturnMap::return_to_planes(int m, const int (*planes)[2], const Vector3 &trial,
                                            double kappa_n, PrincipalReturn &out) const {
  using MatX = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
  using VecX = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
  const VecX ones = VecX::Ones(m);
  const double scale = stress_scale(trial, p_.cohesion.max_value());

  // Residual R, Jacobian J, M = D_hat [G + 2 w 1^T] and F at multipliers x.
  struct State {
    Vector3 s;
    VecX R;
    MatX J, M, F;
  };
  auto evaluate = [&](const VecX &x) {
    State e{Vector3::Zero(), VecX(m), MatX(m, m), MatX(3, m), MatX(m, 3)};
    const double kappa = kappa_n + 2.0 * x.sum();
    const MohrCoulombStrength st = strength(kappa);
    const double sphi = std::sin(st.phi), cphi = std::cos(st.phi);
    MatX G(3, m);
    VecX phi_kappa(m);
    Vector3 w = Vector3::Zero();
    for (int b = 0; b < m; ++b) {
      G.col(b) = flow_generator(planes[b][0], planes[b][1], st.psi);
      Vector3 dg = Vector3::Zero(); // dg_b/dkappa = cos(psi) psi' (e_i + e_j)
      dg(planes[b][0]) = dg(planes[b][1]) = std::cos(st.psi) * st.dpsi;
      w += x(b) * dg;
    }
    e.s = trial - D_hat_ * (G * x);
    for (int a = 0; a < m; ++a) {
      const int i = planes[a][0], j = planes[a][1];
      e.F.row(a) = flow_generator(i, j, st.phi).transpose();
      e.R(a) = (e.s(i) - e.s(j)) + (e.s(i) + e.s(j)) * sphi - 2.0 * st.c * cphi;
      phi_kappa(a) = (e.s(i) + e.s(j)) * cphi * st.dphi - 2.0 * st.dc * cphi +
                     2.0 * st.c * sphi * st.dphi;
    }
    e.M = D_hat_ * (G + 2.0 * w * ones.transpose());
    e.J = -e.F * e.M + 2.0 * phi_kappa * ones.transpose();
    return e;
  };
  // Multipliers that satisfy the plane conditions exactly at a fixed kappa.
  auto multipliers_at = [&](double kappa) {
    const MohrCoulombStrength st = strength(kappa);
    MatX F(m, 3), G(3, m);
    for (int a = 0; a < m; ++a) {
      F.row(a) = flow_generator(planes[a][0], planes[a][1], st.phi).transpose();
      G.col(a) = flow_generator(planes[a][0], planes[a][1], st.psi);
    }
    const MatX A = F * D_hat_ * G;
    const VecX rhs = F * trial - 2.0 * st.c * std::cos(st.phi) * ones;
    return VecX(A.fullPivLu().solve(rhs));
  };

  VecX x = VecX::Zero(m);
  State e = evaluate(x);
  bool converged = false;
  for (int it = 0; it < 25; ++it) {
    if (e.R.cwiseAbs().maxCoeff() <= 1e-14 * scale) {
      converged = true;
      break;
    }
    const VecX dx = e.J.fullPivLu().solve(-e.R);
    if (!dx.allFinite())
      break;
    x += dx;
    e = evaluate(x);
    ++out.iterations;
    if (dx.cwiseAbs().maxCoeff() <= 1e-15 * x.cwiseAbs().maxCoeff() &&
        e.R.cwiseAbs().maxCoeff() <= 1e-11 * scale) {
      converged = true; // step below round-off
      break;
    }
  }
  if (!converged) {
    const double sum0 = multipliers_at(kappa_n).sum();
    if (!(sum0 > 0.0))
      return false;
    auto rho = [&](double kappa) { return kappa - kappa_n - 2.0 * multipliers_at(kappa).sum(); };
    const ScalarRootResult root = bracketed_root(rho, kappa_n, -2.0 * sum0, 2.0 * sum0,
                                                 1e-16 * (std::abs(kappa_n) + 2.0 * sum0), 0.0);
    out.iterations += root.evaluations;
    if (!root.converged)
      return false;
    x = multipliers_at(root.x);
    e = evaluate(x);
    if (e.R.cwiseAbs().maxCoeff() > 1e-11 * scale)
      return false;
  }

  const double tol = 1e-12 * scale;
  if ((x.array() < -1e-14 * std::max(1.0, x.cwiseAbs().maxCoeff())).any())
    return false;
  if (e.s(0) < e.s(1) - tol || e.s(1) < e.s(2) - tol)
    return false;

  out.stress = e.s;
  out.delta_kappa = 2.0 * x.sum();
  out.multipliers.setZero();
  out.multipliers.head(m) = x;
  out.dstress_dtrial = Matrix3::Identity() + e.M * e.J.fullPivLu().solve(e.F);
  return true;
}

// Apex: s = p 1 with p = c cot(phi) at the new kappa; unknown d kappa, with
// d eps_v^p = sin(psi) d kappa and p = p_tr - K d eps_v^p.
bool MohrCoulombReturnMap::return_to_apex(const Vector3 &trial, double kappa_n,
                                          PrincipalReturn &out) const {
  const double K = elastic_.bulk_modulus();
  const double p_tr = trial.sum() / 3.0;
  const double scale = stress_scale(trial, p_.cohesion.max_value());
  const double spsi_min = std::sin(p_.apex_min_dilatancy);
  // r(dk) = p_tr - K sin(psi) dk - c cot(phi), all at kappa_n + dk; r' and d(sin psi)/dk.
  struct Apex {
    double r, dr, spsi, dspsi;
  };
  auto evaluate = [&](double dk) {
    const MohrCoulombStrength st = strength(kappa_n + dk);
    double spsi = std::sin(st.psi), dspsi = std::cos(st.psi) * st.dpsi;
    if (spsi < spsi_min) {
      spsi = spsi_min;
      dspsi = 0.0;
    }
    const double cot = std::cos(st.phi) / std::sin(st.phi);
    const double dcot = -st.dphi / (std::sin(st.phi) * std::sin(st.phi));
    return Apex{p_tr - K * spsi * dk - st.c * cot,
                -K * (spsi + dk * dspsi) - (st.dc * cot + st.c * dcot), spsi, dspsi};
  };
  double dk = 0.0;
  Apex a = evaluate(dk);
  const double r0 = a.r;
  if (!(r0 > 0.0))
    return false; // the trial pressure is below the apex: not an apex return
  const bool converged = newton_root(evaluate, dk, a, scale, out.iterations);
  if (!converged || dk < 0.0) {
    const ScalarRootResult root =
        bracketed_root([&](double d) { return -evaluate(d).r; }, 0.0, -r0,
                       r0 / (K * spsi_min), 1e-16 * r0 / (K * spsi_min), 1e-15 * scale);
    out.iterations += root.evaluations;
    if (!root.converged)
      return false;
    dk = root.x;
    a = evaluate(dk);
  }
  if (dk < 0.0)
    return false;
  const double p = p_tr - K * a.spsi * dk;
  out.stress = Vector3::Constant(p);
  out.delta_kappa = dk;
  out.multipliers.setZero();
  // dp/dp_tr = 1 + K (sin psi + dk dsin psi) / r'; d p_tr / d s_tr_j = 1/3.
  const double dp_dptr = 1.0 + K * (a.spsi + dk * a.dspsi) / a.dr;
  out.dstress_dtrial = Matrix3::Constant(dp_dptr / 3.0);
  return true;
}

PrincipalReturn MohrCoulombReturnMap::return_principal(const Vector3 &trial,
                                                       double kappa_n) const {
  PrincipalReturn out;
  out.stress = trial;
  out.trial_yield = yield_principal(trial, kappa_n);
  if (!(out.trial_yield > 0.0)) {
    out.region = ReturnRegion::elastic;
    return out;
  }

  static const int plane[1][2] = {{0, 2}};
  static const int left[2][2] = {{0, 2}, {1, 2}};
  static const int right[2][2] = {{0, 2}, {0, 1}};

  if (return_to_planes(1, plane, trial, kappa_n, out)) {
    out.region = ReturnRegion::plane;
    return out;
  }
  const double spsi = std::sin(p_.dilatancy_angle.value(kappa_n));
  const bool right_first =
      (1.0 - spsi) * trial(0) - 2.0 * trial(1) + (1.0 + spsi) * trial(2) > 0.0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const bool try_right = (attempt == 0) == right_first;
    if (return_to_planes(2, try_right ? right : left, trial, kappa_n, out)) {
      out.region = try_right ? ReturnRegion::right_edge : ReturnRegion::left_edge;
      return out;
    }
  }
  if (return_to_apex(trial, kappa_n, out)) {
    out.region = ReturnRegion::apex;
    return out;
  }
  throw ReturnMapFailure("Mohr-Coulomb return: no admissible region (plane, edges, apex)");
}

} // namespace geocomp::continuum
