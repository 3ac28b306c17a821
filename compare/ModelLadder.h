#pragma once
// @sect3{The model ladder: what each extra parameter buys}
//
// Why it exists: a continuum model with more parameters fits the DEM curves at least as well
// as a simpler one nested in it, so the residual alone always prefers the richest rung. The
// ladder fits each rung (Mohr-Coulomb with constant parameters, with hardening/softening
// tables, Drucker-Prager, S1's Nikolaevsky model; compare/calibrate/Ladder.h) to the same
// curves and weighs its residual against its number of parameters. For least squares with
// independent Gaussian errors of one unknown variance, the maximised log-likelihood is
// -n/2 ln(RSS/n) + const, which gives (Akaike 1974; Schwarz 1978)
//   AIC = n ln(RSS/n) + 2 k,      BIC = n ln(RSS/n) + k ln n,
// with n the number of residuals, k the number of free parameters and RSS the (weighted,
// dimensionless: FitTarget.h) residual sum of squares at the fit. Only differences between
// rungs fitted to the same residuals mean anything: delta = value - the smallest value over
// the rungs; a rung is preferred by ~2 or more, clearly by 10 or more.
// This file holds the rows as the reports show them (the fit report, the comparison report's
// "Model ladder" table and metrics.json), so that the report library needs no calibration.
#include "compare/Metrics.h"

#include <cstddef>
#include <string>
#include <vector>

namespace geocomp::compare {

/// One rung of the ladder, fitted (or with the reason it was not).
struct LadderRung {
  std::string name;       ///< "mohr-coulomb constant", ... (ladder_rung_names())
  std::string failure;    ///< empty when fitted; otherwise why the fit failed
  std::vector<std::string> parameters; ///< "name = value" of the fitted parameters
  std::size_t k = 0, n = 0; ///< free parameters, residuals
  double rss = nan;       ///< sum of the squared (weighted) residuals at the fit
  /// rms of each quantity over all fitted curves' samples, unweighted (fit report's scales).
  double rms_q = nan, rms_p = nan, rms_eps_v = nan;
  double aic = nan, bic = nan, delta_aic = nan, delta_bic = nan;
  /// The held-out curve predicted by the rung (a pair with pair dem = held out), rms.
  double held_out_q = nan, held_out_p = nan, held_out_eps_v = nan;
  double seconds = 0.0;   ///< of the rung's fit
};

/// n ln(RSS/n) + 2 k.
double akaike(double rss, std::size_t n, std::size_t k);
/// n ln(RSS/n) + k ln n.
double bayesian(double rss, std::size_t n, std::size_t k);
/// Sets aic, bic of every fitted rung and their differences to the smallest over the rungs.
void rank_rungs(std::vector<LadderRung> &rungs);

/// The "Model ladder" table (HTML) with a paragraph on its formulas; empty for no rung.
std::string ladder_html(const std::vector<LadderRung> &rungs);
/// The rungs as a JSON array (one object per rung; null for what is not defined).
std::string ladder_json(const std::vector<LadderRung> &rungs, const std::string &indent);
/// The "ladder" array of a fit.json document (empty when it has none); throws
/// std::runtime_error for text that is not JSON.
std::vector<LadderRung> ladder_from_fit_json(const std::string &fit_json);

} // namespace geocomp::compare
