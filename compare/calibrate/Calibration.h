// @sect3{Least-squares calibration of the continuum parameters}
//
// Why it exists: DEM as a virtual laboratory - which Mohr-Coulomb parameters reproduce
// the DEM curves? The free parameters p (FreeParameters) minimise
//   F(p) = 1/2 sum_targets sum_k r_k(p)^2      (residuals of FitTarget.h)
// over the bounds, by Ceres' Levenberg-Marquardt with central-difference Jacobians; each
// residual evaluation replays every target's program on the material point. Ceres works
// on x_i = p_i / s_i (s_i the starting magnitude) so that E in Pa and angles in degrees
// are equally conditioned.
// Uncertainty: with J the Jacobian at the solution and s^2 = 2 F/(m - n) the residual
// variance, Cov(p) = s^2 (J^T J)^{-1} (ceres::Covariance), standard errors sqrt(diag) and
// correlations C_ij / sqrt(C_ii C_jj).
// Identifiability: a parameter the targets cannot determine makes J rank deficient. The
// singular values of J with unit columns are checked before and after the fit; below
// 1e-6 of the largest, the right singular vector names the parameters involved and a
// CalibrationError says so (for example E and nu from isochoric shear alone, which sees
// only G = E/(2(1+nu))).
#pragma once

#include "compare/calibrate/FitTarget.h"
#include "compare/calibrate/FreeParameters.h"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace geocomp::calibration {

/// How far one fitted curve stays from its target in one quantity, relative to the
/// quantity's scale (FitTarget.h) and without weights.
struct ResidualSummary {
  std::string quantity;    ///< "q", "p", "eps_v"
  bool fitted = false;     ///< among the calibration's quantities
  double rms = 0.0, max_abs = 0.0;
  std::vector<double> values; ///< per fitted sample of the target
};

/// A parameter of the continuum section the calibration leaves as the case has it.
struct FixedParameter {
  std::string name;
  double value = 0.0;
};

struct CalibrationResult {
  std::vector<FreeParameter> parameters;
  std::vector<double> start, value, standard_error;
  std::vector<FixedParameter> fixed;  ///< every other parameter (E, nu, table knots), with its value
  Eigen::MatrixXd correlation;
  ContinuumParameters calibrated;
  std::vector<Response> fitted;      ///< the material point with the calibrated values, per target
  std::vector<ResidualQuantity> quantities;  ///< the fitted ones, with their weights
  std::vector<std::vector<ResidualSummary>> residual_summary; ///< per target: q, p, eps_v
  double initial_cost = 0.0, final_cost = 0.0;
  std::size_t residuals = 0;
  int iterations = 0;
  double seconds = 0.0;
  std::string summary;               ///< Ceres' brief report
  std::vector<std::string> notes;    ///< starting values and the like
  /// Free parameters the fitted curves cannot constrain (unconstrained_parameters()).
  std::vector<std::string> warnings;
};

/// How far `model` (the target's program on the material point) stays from the target in q, p
/// and eps_v, each relative to the target's scales and without weights; `fitted` marks which
/// quantities a fit used.
std::vector<ResidualSummary> summarize_residuals(const FitTarget &target, const Response &model,
                                                const std::vector<ResidualQuantity> &fitted);

/// Fits the free parameters of `start` (already the starting values) to the targets.
CalibrationResult calibrate(const ContinuumParameters &start, const std::vector<FitTarget> &targets,
                            const CalibrationParameters &options);

/// The smallest singular value of the column-normalised Jacobian relative to the largest,
/// and, when it is below `threshold`, a message naming the parameters of its singular
/// vector (components above 0.3). Used before and after the fit.
struct Identifiability {
  double ratio = 1.0;
  std::vector<std::string> parameters;
  bool ok() const { return parameters.empty(); }
};
Identifiability check_identifiability(const Eigen::MatrixXd &jacobian, const std::vector<FreeParameter> &parameters,
                                      double threshold = 1e-6);

} // namespace geocomp::calibration
