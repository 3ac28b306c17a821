#include "compare/calibrate/Calibration.h"

#include "compare/calibrate/PlasticReach.h"
#include "continuum/driver/CaseMaterial.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>

namespace geocomp::calibration {

namespace {

/// All residuals of all targets for the scaled parameters x (p_i = s_i x_i).
struct Residuals {
  const ContinuumParameters *base;
  const FreeParameters *free;
  const std::vector<FitTarget> *targets;
  std::vector<double> scale;
  std::vector<ResidualQuantity> quantities;

  bool operator()(double const *const *x, double *r) const
  {
    std::vector<double> p(scale.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      p[i] = scale[i] * x[0][i];
    continuum::MaterialParameters m;
    try {
      m = continuum::material_from_case(free->apply(*base, p));
    } catch (const std::exception &) {
      return false; // outside the model's range: Ceres shrinks the step
    }
    // The targets are independent runs: one thread each, each writing its own rows.
    const std::vector<FitTarget> &ts = *targets;
    std::vector<std::size_t> offset(ts.size() + 1, 0);
    for (std::size_t k = 0; k < ts.size(); ++k)
      offset[k + 1] = offset[k] + residual_count(ts[k], quantities.size());
    int failed = 0;
#pragma omp parallel for schedule(dynamic) reduction(+ : failed)
    for (std::size_t k = 0; k < ts.size(); ++k) {
      try {
        residuals(ts[k], simulate(ts[k], m), quantities, r + offset[k]);
      } catch (const std::exception &) {
        ++failed; // the driver failed for these values
      }
    }
    return failed == 0;
  }
};

/// The residuals as Ceres sees them, with a Jacobian by finite differences that stay inside
/// the bounds and inside the model's range. Column j is the central difference
///     J_j = (r(x + h e_j) - r(x - h e_j)) / (2 h),   h = 1e-6 max(|x_j|, 1)
/// (x is scaled to order one), and, where one side leaves the bounds [l_j, u_j] or the
/// material point fails there, the one-sided difference on the other side,
///     J_j = (r(x + h e_j) - r(x)) / h   or   (r(x) - r(x - h e_j)) / h.
/// A parameter on its bound (a dilatancy of 0 at kappa = 0, where the fit starts or ends) or
/// next to a point the model refuses is then differentiated, where a central difference fails
/// the whole evaluation and Ceres gives up ("Residual and Jacobian evaluation failed"). Only
/// when both sides fail is the evaluation refused.
class BoundedDifferences : public ceres::CostFunction {
public:
  BoundedDifferences(const Residuals &r, std::vector<double> lower, std::vector<double> upper, std::size_t m)
      : residuals_(r), lower_(std::move(lower)), upper_(std::move(upper))
  {
    mutable_parameter_block_sizes()->push_back(int(lower_.size()));
    set_num_residuals(int(m));
  }

  bool Evaluate(double const *const *x, double *r, double **jacobians) const override
  {
    if (!residuals_(x, r))
      return false;
    if (jacobians == nullptr || jacobians[0] == nullptr)
      return true;
    const std::size_t n = lower_.size(), m = std::size_t(num_residuals());
    std::vector<double> shifted(x[0], x[0] + n), plus(m), minus(m);
    const double *at[] = {shifted.data()};
    for (std::size_t j = 0; j < n; ++j) {
      const double h = 1e-6 * std::max(std::abs(x[0][j]), 1.0);
      shifted[j] = x[0][j] + h;
      const bool up = shifted[j] <= upper_[j] && residuals_(at, plus.data());
      shifted[j] = x[0][j] - h;
      const bool down = shifted[j] >= lower_[j] && residuals_(at, minus.data());
      shifted[j] = x[0][j];
      if (!up && !down)
        return false;
      const double *hi = up ? plus.data() : r, *lo = down ? minus.data() : r;
      const double width = (up ? h : 0.0) + (down ? h : 0.0);
      for (std::size_t i = 0; i < m; ++i)
        jacobians[0][i * n + j] = (hi[i] - lo[i]) / width;
    }
    return true;
  }

private:
  Residuals residuals_;
  std::vector<double> lower_, upper_;
};

using CostFunction = BoundedDifferences;

/// Jacobian (m x n) of the residuals at x; false if the model fails there.
bool jacobian(const CostFunction &f, const std::vector<double> &x, std::size_t m, Eigen::MatrixXd &J)
{
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Jr(m, x.size());
  std::vector<double> r(m);
  const double *params[] = {x.data()};
  double *jacs[] = {Jr.data()};
  if (!f.Evaluate(params, r.data(), jacs))
    return false;
  J = Jr;
  return true;
}

void throw_if_unidentifiable(const Identifiability &id, const char *when)
{
  if (id.ok())
    return;
  std::string names;
  for (const auto &p : id.parameters)
    names += (names.empty() ? "" : ", ") + p;
  throw CalibrationError(id.parameters.front(),
                         "the targets cannot identify " +
                           std::string(id.parameters.size() > 1 ? "the parameters " : "the parameter ") + names + " (" +
                           when + ": the residuals change with " +
                           (id.parameters.size() > 1 ? "only a combination of them" : "it by nothing measurable") +
                           "); fix " + (id.parameters.size() > 1 ? "one of them" : "it") +
                           " or add a target that sees it (e.g. an axial test for nu, a curve past the peak "
                           "for the softening knots)");
}
} // namespace

Identifiability check_identifiability(const Eigen::MatrixXd &J, const std::vector<FreeParameter> &parameters,
                                      double threshold)
{
  Identifiability id;
  Eigen::MatrixXd Jn = J;
  std::vector<bool> dead(J.cols(), false);
  for (Eigen::Index j = 0; j < J.cols(); ++j) {
    const double norm = J.col(j).norm();
    if (!(norm > 0.0)) {
      dead[j] = true;
      id.parameters.push_back(parameters[j].name);
      continue;
    }
    Jn.col(j) /= norm;
  }
  if (!id.parameters.empty()) {
    id.ratio = 0.0;
    return id;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd &s = svd.singularValues();
  id.ratio = s(s.size() - 1) / s(0);
  if (id.ratio < threshold) {
    const Eigen::VectorXd v = svd.matrixV().col(s.size() - 1);
    for (Eigen::Index j = 0; j < v.size(); ++j)
      if (std::abs(v(j)) > 0.3)
        id.parameters.push_back(parameters[j].name);
  }
  return id;
}

std::vector<ResidualSummary> summarize_residuals(const FitTarget &t, const Response &model,
                                                const std::vector<ResidualQuantity> &fitted)
{
  const std::vector<ResidualQuantity> all = all_quantities();
  std::vector<double> r(residual_count(t, all.size()));
  residuals(t, model, all, r.data());
  std::vector<ResidualSummary> rows;
  for (std::size_t j = 0; j < all.size(); ++j) {
    ResidualSummary row;
    row.quantity = all[j].name;
    row.fitted = std::any_of(fitted.begin(), fitted.end(), [&](const ResidualQuantity &q) { return q.kind == all[j].kind; });
    double sum = 0.0;
    for (std::size_t k = j; k < r.size(); k += all.size()) {
      const double v = r[k] / std::max(t.weight, 1e-300);
      row.values.push_back(v);
      sum += v * v;
      row.max_abs = std::max(row.max_abs, std::abs(v));
    }
    row.rms = std::sqrt(sum / double(row.values.size()));
    rows.push_back(std::move(row));
  }
  return rows;
}

CalibrationResult calibrate(const ContinuumParameters &start, const std::vector<FitTarget> &targets,
                            const CalibrationParameters &options)
{
  const auto t0 = std::chrono::steady_clock::now();
  if (targets.empty())
    throw CalibrationError("calibration/targets", "no target curve to fit");
  const FreeParameters free(start, options);
  CalibrationResult out;
  out.parameters = free.list();
  out.start = free.values(start);
  out.quantities = fitted_quantities(options);
  const std::size_t n = free.size();
  std::size_t m = 0;
  for (const auto &t : targets)
    m += residual_count(t, out.quantities.size());
  out.residuals = m;
  if (m <= n)
    throw CalibrationError("calibration/targets", "fewer residuals than free parameters");

  Residuals functor{&start, &free, &targets, std::vector<double>(n), out.quantities};
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const FreeParameter &p = out.parameters[i];
    double s = std::abs(out.start[i]);
    if (!(s > 0.0))
      s = std::max(std::abs(p.upper), std::abs(p.lower)) > 0 ? 0.1 * (p.upper - p.lower) : 1.0;
    if (p.family == FreeParameter::Family::Friction || p.family == FreeParameter::Family::Dilatancy)
      s = std::max(s, 1.0); // degrees: a unit step is a fair scale near zero
    functor.scale[i] = s;
    x[i] = std::clamp(out.start[i], p.lower, p.upper) / s;
  }

  std::vector<double> lower(n), upper(n);
  for (std::size_t i = 0; i < n; ++i) {
    lower[i] = out.parameters[i].lower / functor.scale[i];
    upper[i] = out.parameters[i].upper / functor.scale[i];
  }
  auto *cost = new CostFunction(functor, lower, upper, m);
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, x.data());
  for (std::size_t i = 0; i < n; ++i) {
    problem.SetParameterLowerBound(x.data(), int(i), lower[i]);
    problem.SetParameterUpperBound(x.data(), int(i), upper[i]);
  }

  Eigen::MatrixXd J;
  if (!jacobian(*cost, x, m, J))
    throw CalibrationError("calibration", "the material point fails at the starting values; check the continuum section");
  throw_if_unidentifiable(check_identifiability(J, out.parameters), "at the starting values");

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = int(options.max_iterations);
  // Stop when a step changes the cost by less than 1e-9 of itself: on curves the model
  // cannot follow exactly (DEM) the cost then sits at its floor and further steps only
  // chase the finite-difference noise; on exact curves the cost keeps falling by orders of
  // magnitude per step, so this never stops a round trip early.
  so.function_tolerance = 1e-9;
  so.gradient_tolerance = 1e-15;
  so.parameter_tolerance = 1e-10;
  so.logging_type = std::getenv("GEOCOMP_CERES_LOG") ? ceres::PER_MINIMIZER_ITERATION : ceres::SILENT;
  so.minimizer_progress_to_stdout = std::getenv("GEOCOMP_CERES_LOG") != nullptr;
  so.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.iterations = int(summary.iterations.size()) - 1;
  out.summary = summary.BriefReport();
  if (!summary.IsSolutionUsable())
    throw std::runtime_error("calibration: Ceres found no usable solution: " + summary.message);

  out.value.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.value[i] = functor.scale[i] * x[i];
  out.calibrated = free.apply(start, out.value);
  const FreeParameters every = FreeParameters::all(start);
  const std::vector<double> every_value = every.values(start);
  for (std::size_t i = 0; i < every.size(); ++i)
    if (!free.contains(every.list()[i].name))
      out.fixed.push_back({every.list()[i].name, every_value[i]});

  if (!jacobian(*cost, x, m, J))
    throw std::runtime_error("calibration: the material point fails at the solution");
  throw_if_unidentifiable(check_identifiability(J, out.parameters), "at the solution");

  // Covariance of x from Ceres, scaled by the residual variance, then to p.
  out.standard_error.assign(n, std::nan(""));
  out.correlation = Eigen::MatrixXd::Constant(n, n, std::nan(""));
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = 0;
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double *, const double *>> blocks = {{x.data(), x.data()}};
  if (covariance.Compute(blocks, &problem)) {
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> C(n, n);
    covariance.GetCovarianceBlock(x.data(), x.data(), C.data());
    const double s2 = 2.0 * out.final_cost / double(m - n);
    for (std::size_t i = 0; i < n; ++i)
      out.standard_error[i] = functor.scale[i] * std::sqrt(std::max(0.0, s2 * C(i, i)));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        out.correlation(i, j) = C(i, j) / std::sqrt(C(i, i) * C(j, j));
  } else {
    out.notes.push_back("covariance not computed (Ceres: rank-deficient Jacobian)");
  }

  const continuum::MaterialParameters material = continuum::material_from_case(out.calibrated);
  for (const auto &t : targets) {
    out.fitted.push_back(simulate(t, material));
    out.residual_summary.push_back(summarize_residuals(t, out.fitted.back(), out.quantities));
  }
  out.warnings = unconstrained_strength(out.parameters, out.calibrated, out.fitted);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

} // namespace geocomp::calibration
