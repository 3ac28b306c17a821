// @sect3{Closed-form starting values}
//
// Why it exists: Levenberg-Marquardt needs a start in the right basin, and the classic
// hand calibration gives one. From the targets' metrics (compare::compute_metrics):
//  - E and nu from the unloading branches when the targets have them (elastic in S0's
//    reading): Hooke's law in increments, d eps = (d sigma + nu (d sigma - tr(d sigma) I))/E,
//    fitted by least squares in (1/E, nu/E) (only G when the branches are deviatoric).
//  - otherwise E from the initial slope: axial curves at constant lateral stress give E directly
//    (sigma_z = E eps_z); isochoric shear gives G = d tau/d gamma, E = 2 G (1 + nu).
//  - nu from the initial lateral-to-axial strain ratio of axial curves, nu = -d eps_x/d eps_z.
//  - phi and c from the peak Mohr envelope: with peaks at two or more confinements, the
//    least-squares line sigma_1 = N_phi sigma_3 + 2 c sqrt(N_phi) (compression positive;
//    CONTINUUM-THEORY section 6, the Coulomb line tau = sigma tan phi + c of S3 eq. (1) in
//    principal stresses) gives sin phi = (N_phi - 1)/(N_phi + 1) and c; with one, phi from c = 0.
//  - psi from the volumetric slope at the peak: on axial curves the plastic flow on the
//    compression corner, d eps_v^p / d(-eps_zz^p) = N_psi - 1 (CONTINUUM-THEORY section 6);
//    on isochoric curves the metrics' sin psi = d eps_v^p / d gamma^p (docs/metrics.md).
// The tables keep their shape: each is scaled so that its largest knot takes the estimate.
// Estimates that the targets cannot give (no axial curve for nu, no finite dilatancy)
// leave the case's values. starting_values() takes from these estimates the free
// parameters only: what the calibration does not free keeps the case's value, in the
// start and so in the calibrated section.
#pragma once

#include "compare/case/CaseDescription.h"
#include "compare/calibrate/FitTarget.h"
#include "compare/calibrate/FreeParameters.h"

#include <string>
#include <vector>

namespace geocomp::calibration {

struct StartingValues {
  ContinuumParameters parameters;
  std::vector<std::string> notes; ///< what was estimated from what
};

StartingValues closed_form_start(const ContinuumParameters &base, const std::vector<FitTarget> &targets);

/// Where the fit starts: the case's continuum section with each free parameter (`options`)
/// set to its closed-form estimate (`starting values = closed-form`) or left as the case
/// has it (`case`); every other parameter keeps the case's value.
StartingValues starting_values(const ContinuumParameters &case_section, const std::vector<FitTarget> &targets,
                               const CalibrationParameters &options);

} // namespace geocomp::calibration
