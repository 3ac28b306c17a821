// @sect3{The model ladder, each rung calibrated}
//
// Why it exists: issue 38 asks what each extra parameter of the continuum buys. Every rung
// of calibration/ladder is calibrated (Calibration.h: the same targets, quantities, weights,
// bounds and Levenberg-Marquardt over the material point) with the free parameters natural
// to its model, and reported with its residual and information criteria
// (compare/ModelLadder.h: AIC = n ln(RSS/n) + 2k, BIC = n ln(RSS/n) + k ln n):
//  - mohr-coulomb constant: E, nu, c, phi, psi each one number (each freed table of the
//    case replaced by a single knot); the families the case's `free parameters` fixes stay
//    fixed (so do their tables);
//  - mohr-coulomb tables: the case's own free parameters on its tables c(kappa), phi(kappa),
//    psi(kappa) (the calibration `geocomp calibrate` runs);
//  - drucker-prager: the same parameters, behind the case's Drucker-Prager matching of the
//    cone to the Mohr-Coulomb tables (continuum/models/DruckerPragerModel.h);
//  - nikolaevsky: S1's quasi-static model, Phi = omega J1 + tau <= Y0 + H kappa (S1 eq. (5)),
//    free E, nu (as the case frees them), sigma_y (for c), alpha = 3 omega (for phi),
//    Lambda (for psi) and sigma_c, which sets the hardening H with eps_p* held at 1 % (H
//    depends on (sigma_c - sigma_y)/eps_p* only: freeing both would be unidentifiable). It
//    starts from the constant rung's fit (its start when that rung is not in the ladder or
//    fails) mapped onto the compression (outer) cone,
//      omega = 2 sin phi / (sqrt3 (3 - sin phi)),  Y0 = 6 c cos phi / (sqrt3 (3 - sin phi)),
//      sigma_y = Y0 / (1/sqrt3 - omega),  Lambda = 6 sin psi / (sqrt3 (3 - sin psi)),
//    sigma_y at least 1e-3 of the targets' largest q (the model needs sigma_y > 0) and
//    sigma_c = 1.1 sigma_y.
// A rung whose fit fails (a parameter its model cannot identify on these curves, the
// material point failing) is reported with the reason instead of numbers.
#pragma once

#include "compare/ModelLadder.h"
#include "compare/calibrate/Calibration.h"

#include <string>
#include <vector>

namespace geocomp::calibration {

struct LadderInput {
  const ContinuumParameters *section = nullptr;  ///< the case's continuum section
  const std::vector<FitTarget> *targets = nullptr;
  const CalibrationParameters *options = nullptr; ///< free parameters, quantities, bounds, ladder
  const FitTarget *held_out = nullptr;           ///< a curve predicted, not fitted (or none)
};

/// Where one rung's fit starts and what it frees.
struct RungProblem {
  ContinuumParameters start;
  CalibrationParameters options;
};

/// The problem of `rung` (a name of ladder_rung_names()); `constant` is the constant rung's
/// fit (the start of nikolaevsky), or none. Throws CalibrationError for an unknown rung.
RungProblem rung_problem(const std::string &rung, const LadderInput &in, const CalibrationResult *constant);

/// Each rung of in.options->ladder fitted, in that order, ranked (compare::rank_rungs).
std::vector<compare::LadderRung> run_ladder(const LadderInput &in);

/// One line per rung for the command line: k, n, RSS, AIC, BIC and their deltas.
std::string ladder_summary(const std::vector<compare::LadderRung> &rungs);

} // namespace geocomp::calibration
