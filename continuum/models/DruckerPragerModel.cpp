#include "continuum/models/DruckerPragerModel.h"

#include "continuum/models/PrincipalUpdate.h"
#include "continuum/models/ScalarRoot.h"
#include "continuum/models/SpectralDecomposition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::continuum {

void DruckerPragerParameters::validate() const {
  IsotropicElasticity check(youngs_modulus, poisson_ratio);
  (void)check;
  if (strength.min_value() < 0.0)
    throw std::invalid_argument("Drucker-Prager: strength Y must be >= 0");
  if (!(friction.min_value() > 0.0))
    throw std::invalid_argument("Drucker-Prager: friction omega must be > 0");
  if (dilatancy.min_value() < 0.0)
    throw std::invalid_argument("Drucker-Prager: dilatancy Lambda must be >= 0");
  if (!(apex_min_dilatancy > 0.0))
    throw std::invalid_argument("Drucker-Prager: apex_min_dilatancy must be > 0");
}

DruckerPragerMatch match_mohr_coulomb(double phi, double psi, DruckerPragerMatching matching) {
  const double sphi = std::sin(phi), cphi = std::cos(phi), spsi = std::sin(psi);
  const double sqrt3 = std::sqrt(3.0);
  switch (matching) {
  case DruckerPragerMatching::outer_cone: // CONTINUUM-THEORY.md Sec. 5, compression meridian
    return {2.0 * sphi / (sqrt3 * (3.0 - sphi)), 6.0 * cphi / (sqrt3 * (3.0 - sphi)),
            2.0 * sqrt3 * spsi / (3.0 - spsi)};
  case DruckerPragerMatching::inner_cone: // extension meridian
    return {2.0 * sphi / (sqrt3 * (3.0 + sphi)), 6.0 * cphi / (sqrt3 * (3.0 + sphi)),
            2.0 * sqrt3 * spsi / (3.0 + spsi)};
  case DruckerPragerMatching::plane_strain: {
    // Plane strain with zero out-of-plane plastic rate: s_2 = -(2/3) Lambda tau, so
    // (s1 - s3)/2 = tau sqrt(1 - Lambda^2/3) and (s1 + s3)/2 = p + Lambda tau / 3. Matching
    // the dilatancy ratio sin psi = d eps_v / (d eps_1 - d eps_3) and the MC line gives
    // (derived in docs/continuum-models.md; for psi = phi it is the classical
    // omega = tan phi / sqrt(9 + 12 tan^2 phi), Y = 3c / sqrt(9 + 12 tan^2 phi)):
    const double lambda = sqrt3 * spsi / std::sqrt(3.0 + spsi * spsi);
    const double root = std::sqrt(1.0 - lambda * lambda / 3.0);
    const double omega = sphi / (3.0 * root + lambda * sphi);
    return {omega, cphi * (1.0 - omega * lambda) / root, lambda};
  }
  }
  throw std::invalid_argument("unknown Drucker-Prager matching");
}

DruckerPragerParameters
DruckerPragerParameters::from_mohr_coulomb(const MohrCoulombParameters &mc,
                                           DruckerPragerMatching matching) {
  std::vector<double> x;
  for (const auto *f : {&mc.cohesion, &mc.friction_angle, &mc.dilatancy_angle})
    x.insert(x.end(), f->breakpoints().begin(), f->breakpoints().end());
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  std::vector<double> Y, omega, lambda;
  for (double k : x) {
    const DruckerPragerMatch m =
        match_mohr_coulomb(mc.friction_angle(k), mc.dilatancy_angle(k), matching);
    omega.push_back(m.omega);
    Y.push_back(m.y_over_c * mc.cohesion(k));
    lambda.push_back(m.lambda);
  }
  DruckerPragerParameters dp;
  dp.youngs_modulus = mc.youngs_modulus;
  dp.poisson_ratio = mc.poisson_ratio;
  dp.strength = PiecewiseLinear(x, Y);
  dp.friction = PiecewiseLinear(x, omega);
  dp.dilatancy = PiecewiseLinear(x, lambda);
  return dp;
}

DruckerPragerModel::DruckerPragerModel(DruckerPragerParameters parameters)
    : p_(std::move(parameters)), elastic_(p_.youngs_modulus, p_.poisson_ratio) {
  p_.validate();
}

double DruckerPragerModel::yield_function(const Vector6 &stress, double kappa) const {
  const double tr = stress.head<3>().sum();
  const Vector6 s = stress - tr / 3.0 * mandel_identity();
  return p_.friction(kappa) * tr + std::sqrt(0.5 * s.squaredNorm()) - p_.strength(kappa);
}

PrincipalReturn DruckerPragerModel::return_principal(const Vector3 &trial,
                                                     double kappa_n) const {
  const double G = elastic_.shear_modulus(), K = elastic_.bulk_modulus();
  const double p_tr = trial.sum() / 3.0;
  const Vector3 s_tr = trial - Vector3::Constant(p_tr);
  const double tau_tr = std::sqrt(0.5 * s_tr.squaredNorm());
  const double scale = std::max(trial.cwiseAbs().maxCoeff(), std::max(p_.strength.max_value(), 1e-300));

  PrincipalReturn out;
  out.stress = trial;
  out.trial_yield = 3.0 * p_.friction(kappa_n) * p_tr + tau_tr - p_.strength(kappa_n);
  if (!(out.trial_yield > 0.0)) {
    out.region = ReturnRegion::elastic;
    return out;
  }

  // Cone: r(dg) = tau_tr - G dg + 3 omega (p_tr - K Lambda dg) - Y, all at kappa_n + dg.
  // Newton first; a bracketed solve if Newton stalls at a kink of the tables.
  struct Cone {
    double r, dr, lam, dlam, om;
  };
  auto cone = [&](double dg) {
    const double k = kappa_n + dg;
    const double om = p_.friction(k), dom = p_.friction.slope(k);
    const double lam = p_.dilatancy(k), dlam = p_.dilatancy.slope(k);
    const double Y = p_.strength(k), dY = p_.strength.slope(k);
    const double p = p_tr - K * lam * dg;
    return Cone{tau_tr - G * dg + 3.0 * om * p - Y,
                -G + 3.0 * dom * p - 3.0 * om * K * (lam + dlam * dg) - dY, lam, dlam, om};
  };
  if (tau_tr > 0.0) {
    double dg = 0.0;
    Cone c = cone(dg);
    bool converged = newton_root(cone, dg, c, scale, out.iterations);
    if (!converged || dg < 0.0) {
      const double guess = out.trial_yield / (G + 3.0 * K * p_.friction(kappa_n) * p_.dilatancy(kappa_n));
      const ScalarRootResult root = bracketed_root([&](double x) { return -cone(x).r; }, 0.0,
                                                   -out.trial_yield, guess, 1e-16 * guess,
                                                   1e-15 * scale);
      out.iterations += root.evaluations;
      converged = root.converged;
      dg = root.x;
      c = cone(dg);
    }
    const double tau = tau_tr - G * dg;
    if (converged && dg >= 0.0 && tau >= 0.0) {
      const double p = p_tr - K * c.lam * dg;
      const double a = G * dg / tau_tr;
      out.stress = (1.0 - a) * s_tr + Vector3::Constant(p);
      out.delta_kappa = dg;
      out.multipliers = Eigen::Vector2d(dg, 0.0);
      out.region = ReturnRegion::plane;
      // d dg / d s_tr_j = -(1/R') (s_tr_j / (2 tau_tr) + omega)
      const Vector3 ddg = -(s_tr / (2.0 * tau_tr) + Vector3::Constant(c.om)) / c.dr;
      const Matrix3 Pdev = Matrix3::Identity() - Matrix3::Constant(1.0 / 3.0);
      out.dstress_dtrial = (1.0 - a) * Pdev - (G / tau_tr) * s_tr * ddg.transpose() +
                           (G * dg / (2.0 * tau_tr * tau_tr * tau_tr)) * s_tr * s_tr.transpose() +
                           Matrix3::Constant(1.0 / 3.0) -
                           K * (c.lam + c.dlam * dg) * Vector3::Ones() * ddg.transpose();
      return out;
    }
  }

  // Apex: r(dk) = p_tr - K Lambda dk - Y / (3 omega) = 0, Lambda floored.
  struct Apex {
    double r, dr, lam, dlam;
  };
  auto apex = [&](double dk) {
    const double k = kappa_n + dk;
    const double om = p_.friction(k), dom = p_.friction.slope(k);
    const double Y = p_.strength(k), dY = p_.strength.slope(k);
    double lam = p_.dilatancy(k), dlam = p_.dilatancy.slope(k);
    if (lam < p_.apex_min_dilatancy) {
      lam = p_.apex_min_dilatancy;
      dlam = 0.0;
    }
    return Apex{p_tr - K * lam * dk - Y / (3.0 * om),
                -K * (lam + dlam * dk) - (dY * om - Y * dom) / (3.0 * om * om), lam, dlam};
  };
  double dk = 0.0;
  Apex a = apex(dk);
  const double r0 = a.r;
  if (!(r0 > 0.0))
    throw ReturnMapFailure("Drucker-Prager return: neither cone nor apex admissible");
  const bool converged = newton_root(apex, dk, a, scale, out.iterations);
  if (!converged || dk < 0.0) {
    const double guess = r0 / (K * std::max(a.lam, p_.apex_min_dilatancy));
    const ScalarRootResult root = bracketed_root([&](double x) { return -apex(x).r; }, 0.0, -r0,
                                                 guess, 1e-16 * guess, 1e-15 * scale);
    out.iterations += root.evaluations;
    if (!root.converged)
      throw ReturnMapFailure("Drucker-Prager return: apex solve did not converge");
    dk = root.x;
    a = apex(dk);
  }
  out.stress = Vector3::Constant(p_tr - K * a.lam * dk);
  out.delta_kappa = dk;
  out.region = ReturnRegion::apex;
  out.dstress_dtrial = Matrix3::Constant((1.0 + K * (a.lam + a.dlam * dk) / a.dr) / 3.0);
  return out;
}

MaterialPointUpdate DruckerPragerModel::update(const Vector6 &total_strain,
                                               const PlasticHistory &old) const {
  return principal_space_update(elastic_, total_strain, old, [this](const Vector3 &trial, double kappa_n) {
    return return_principal(trial, kappa_n);
  });
}

Matrix6 DruckerPragerModel::continuum_tangent(const Vector6 &stress, double kappa) const {
  const Vector6 one = mandel_identity();
  const double tr = stress.head<3>().sum();
  const Vector6 s = stress - tr / 3.0 * one;
  const double tau = std::sqrt(0.5 * s.squaredNorm());
  if (!(tau > 0.0))
    throw std::invalid_argument("Drucker-Prager continuum tangent: undefined at the apex");
  const Vector6 Q = p_.friction(kappa) * one + s / (2.0 * tau);    // dPhi/dsigma
  const Vector6 P = s / (2.0 * tau) + p_.dilatancy(kappa) / 3.0 * one; // dg/dsigma
  const double H = p_.strength.slope(kappa) - p_.friction.slope(kappa) * tr;
  const Matrix6 &D = elastic_.stiffness();
  const Vector6 DP = D * P, DQ = D.transpose() * Q;
  return D - DP * DQ.transpose() / (H + Q.dot(DP));
}

} // namespace geocomp::continuum
