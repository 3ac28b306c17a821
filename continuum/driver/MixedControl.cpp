#include "continuum/driver/MixedControl.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace geocomp::continuum {

namespace {
/// The system of one increment at a strain: residuals, their convergence measure, Jacobian.
class IncrementSystem {
public:
  IncrementSystem(const IncrementEquations &eq, const PointEvaluator &evaluate, const IncrementSettings &settings)
    : eq_(eq), evaluate_(evaluate), settings_(settings), n_(eq.n_stress + (eq.control_kappa ? 1 : 0))
  {}

  int size() const { return n_; }

  /// Residuals at `p` (row scaling fixed by the first call); returns the worst relative
  /// residual measured against its tolerance (<= 1: converged).
  double residual(const PointEvaluation &p, Eigen::VectorXd &r)
  {
    const MaterialPointUpdate &u = p.state;
    double stress_scale = 1.0; // Mandel slots 0..2 are the normal components, unweighted
    for (int i = 0; i < 3; ++i)
      stress_scale = std::max(stress_scale, std::abs(u.stress[i]));
    if (row_scale_ <= 0.0) {
      row_scale_ = stress_scale;
      for (int k = 0; k < eq_.n_stress; ++k)
        row_scale_ = std::max(row_scale_, std::abs(eq_.target[k]));
    }
    r.resize(n_);
    double worst = 0.0;
    for (int k = 0; k < eq_.n_stress; ++k) {
      const double res = u.stress[eq_.stress_axis[k]] - eq_.target[k];
      r[k] = res / row_scale_;
      worst = std::max(worst, std::abs(res) / std::max(stress_scale, std::abs(eq_.target[k])) /
                                settings_.stress_tolerance);
    }
    if (eq_.control_kappa) {
      r[eq_.n_stress] = (u.history.kappa - eq_.kappa_target) / eq_.kappa_scale;
      worst = std::max(worst, std::abs(r[eq_.n_stress]) / settings_.kappa_tolerance);
    }
    return worst;
  }

  /// J = dr/de_u at `eps` (state `p`); false when an evaluation of the kappa row fails.
  bool jacobian(const Tensor3 &eps, const PointEvaluation &p, Eigen::MatrixXd &J) const
  {
    J.resize(n_, eq_.n_unknown);
    for (int k = 0; k < eq_.n_stress; ++k)
      for (int m = 0; m < eq_.n_unknown; ++m)
        J(k, m) = p.axial_tangent(eq_.stress_axis[k], eq_.unknown[m]) / row_scale_;
    if (!eq_.control_kappa)
      return true;
    // d kappa / d eps_u by central differences of the update.
    const double h = 1e-8;
    for (int m = 0; m < eq_.n_unknown; ++m) {
      const int a = eq_.unknown[m];
      Tensor3 ep = eps, em = eps;
      ep(a, a) += h;
      em(a, a) -= h;
      PointEvaluation plus, minus;
      if (!evaluate_(ep, plus) || !evaluate_(em, minus))
        return false;
      J(eq_.n_stress, m) = (plus.state.history.kappa - minus.state.history.kappa) / (2.0 * h) / eq_.kappa_scale;
    }
    return true;
  }

  /// P: unknowns -> reduced unknowns, tying stress axes with equal targets and strains.
  Eigen::MatrixXd ties(const Tensor3 &eps) const
  {
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(eq_.n_unknown, eq_.n_unknown);
    std::array<int, 3> group{-1, -1, -1};
    int n_u = 0;
    for (int m = 0; m < eq_.n_unknown; ++m) {
      const int a = eq_.unknown[m];
      const int ka = stress_index(a);
      for (int l = 0; l < m && group[m] < 0 && ka >= 0; ++l) {
        const int b = eq_.unknown[l], kb = stress_index(b);
        const double de = std::abs(eps(a, a) - eps(b, b));
        if (kb >= 0 && eq_.target[ka] == eq_.target[kb] && de <= 1e-13 * std::max(std::abs(eps(a, a)), 1e-6))
          group[m] = group[l];
      }
      if (group[m] < 0)
        group[m] = n_u++;
      P(m, group[m]) = 1.0;
    }
    P.conservativeResize(eq_.n_unknown, n_u);
    return P;
  }

private:
  int stress_index(int axis) const
  {
    for (int k = 0; k < eq_.n_stress; ++k)
      if (eq_.stress_axis[k] == axis)
        return k;
    return -1;
  }

  const IncrementEquations &eq_;
  const PointEvaluator &evaluate_;
  const IncrementSettings &settings_;
  int n_;
  double row_scale_ = 0.0;
};
} // namespace

bool solve_increment(const IncrementEquations &equations, const PointEvaluator &evaluate,
                     const IncrementSettings &settings, Tensor3 &eps, PointEvaluation &out, unsigned &iterations)
{
  iterations = 0;
  if (!evaluate(eps, out))
    return false;
  IncrementSystem system(equations, evaluate, settings);
  if (system.size() == 0)
    return true;
  Eigen::VectorXd r;
  double worst = system.residual(out, r);
  while (worst > 1.0) {
    if (++iterations > settings.max_iterations)
      return false;
    Eigen::MatrixXd J;
    if (!system.jacobian(eps, out, J))
      return false;
    const Eigen::MatrixXd P = system.ties(eps);
    // Minimum-norm step: on a corner the remaining block can still be singular.
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(J * P);
    cod.setThreshold(1e-10);
    if (cod.rank() == 0)
      return false;
    const Eigen::VectorXd de = -P * cod.solve(r);
    // Damped update: halve while the residual norm grows.
    double alpha = 1.0;
    Eigen::VectorXd r_new;
    PointEvaluation trial;
    Tensor3 eps_trial;
    bool ok = false;
    double worst_new = 0.0;
    for (int ls = 0; ls < 8; ++ls, alpha *= 0.5) {
      eps_trial = eps;
      for (int m = 0; m < equations.n_unknown; ++m)
        eps_trial(equations.unknown[m], equations.unknown[m]) += alpha * de[m];
      if (!evaluate(eps_trial, trial))
        continue;
      ok = true;
      worst_new = system.residual(trial, r_new);
      if (r_new.norm() < r.norm())
        break;
    }
    if (!ok)
      return false;
    eps = eps_trial;
    out = trial;
    r = r_new;
    worst = worst_new;
  }
  return true;
}

} // namespace geocomp::continuum
