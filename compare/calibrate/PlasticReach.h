// @sect3{What the targets can say about a strength parameter}
//
// Why it exists: cohesion, friction and dilatancy act only where the material point flows
// plastically. A knot k of a piecewise-linear table c(kappa), phi(kappa), psi(kappa) at
// kappa_k shapes the response only while the point flows with kappa between the
// neighbouring knots, kappa_{k-1} < kappa < kappa_{k+1} (the reach of its hat function;
// the first knot from the onset of yield, the last one without end). Fitted to a target
// that stays elastic, or that never strains as far as the knot, the knot can take any
// value that keeps the point off the yield surface there: the fit returns a number and a
// standard error (phi = 54 +- 1.4 deg from a purely elastic curve) that measure nothing.
// The Jacobian check of Calibration.h catches a knot that changes no residual at all; this
// one catches the knot that changes a handful - the fitted point yields in fewer than
// `min_intervals` sample intervals within its reach - and says so in a warning.
#pragma once

#include "common/Response.h"
#include "compare/calibrate/FreeParameters.h"

#include <string>
#include <vector>

namespace geocomp::calibration {

/// One warning per free cohesion, friction or dilatancy knot of `calibrated` that the
/// `fitted` material-point responses (one per target, with the "kappa" extra) reach in
/// fewer than `min_intervals` plastic sample intervals.
std::vector<std::string> unconstrained_strength(const std::vector<FreeParameter> &free,
                                                const ContinuumParameters &calibrated,
                                                const std::vector<Response> &fitted, std::size_t min_intervals = 3);

} // namespace geocomp::calibration
