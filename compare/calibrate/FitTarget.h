// @sect3{A curve to fit and its replay on the material point}
//
// Why it exists: a target is a results file (typically a DEM run). The file carries the
// case it was run from, so the same loading program and initial stress are replayed on
// the material point with trial continuum parameters (unloading branches left out: the
// fit uses the main path). The residuals compare, at the target's main-path sample
// times t_k, the quantities the case file names (calibration/quantities), each with its
// weight w_j, the target's weight w and a scale that makes them dimensionless:
//   r_q,k = w w_q (q_model(t_k) - q_target(t_k)) / max q_target     q = sqrt(3 J2)
//   r_p,k = w w_p (p_model(t_k) - p_target(t_k)) / max q_target     p = tr(sigma)/3
//   r_v,k = w w_v (eps_v,model(t_k) - eps_v,target(t_k)) / max(range eps_v,target, 1e-3)
// q carries E (initial slope), c and phi (peak) and the softening; eps_v carries nu and
// psi at constant lateral stress; p carries psi in isochoric shear, where eps_v = 0 and
// dilatancy shows as the rise of the mean stress instead (S0 program 1, eq. (3)).
// Model values between its samples are interpolated linearly in time; a model run that
// ends early (a stop condition met sooner) is held at its last sample.
#pragma once

#include "common/LoadingProgram.h"
#include "compare/case/CaseDescription.h"
#include "common/Response.h"
#include "continuum/driver/Materials.h"

#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::calibration {

struct FitTarget {
  std::string name;           ///< file name as given
  Response response;          ///< the target
  LoadingProgram program;     ///< its program, without unloading branches
  double initial_stress = 0.0; ///< isotropic, tension positive [Pa]
  unsigned substeps = 20;     ///< material-point increments per sample
  double weight = 1.0;
  std::vector<std::size_t> samples; ///< main-path samples fitted (after the first)
  double q_scale = 1.0, volume_scale = 1e-3;
};

/// Reads a results file and the case inside it (throws CalibrationError naming the file).
FitTarget load_target(const std::filesystem::path &file, double weight);
/// A target from a response and the program and initial stress it was run with.
FitTarget make_target(std::string name, Response response, LoadingProgram program, double initial_stress,
                      unsigned substeps, double weight);

/// The target's program on the material point with `material` (main path only).
Response simulate(const FitTarget &target, const continuum::MaterialParameters &material);

/// A response quantity compared at the samples, with its weight.
struct ResidualQuantity {
  enum class Kind { Deviator, MeanStress, Volumetric };
  Kind kind = Kind::Deviator;
  double weight = 1.0;
  std::string name; ///< "q", "p", "eps_v"
};
/// The quantities of a calibration section (throws CalibrationError for an unknown name).
std::vector<ResidualQuantity> fitted_quantities(const CalibrationParameters &c);
/// q, p and eps_v with weight 1: what the report shows, fitted or not.
std::vector<ResidualQuantity> all_quantities();

/// Number of residuals of a target: one per fitted sample and quantity.
std::size_t residual_count(const FitTarget &target, std::size_t quantities);
/// Writes residual_count() residuals of `model` against the target, sample by sample,
/// quantity by quantity within a sample: out[k * quantities.size() + j].
void residuals(const FitTarget &target, const Response &model, const std::vector<ResidualQuantity> &quantities,
               double *out);

/// Deviator q = sqrt(3 J2) of a stress.
double deviator(const Tensor3 &stress);

} // namespace geocomp::calibration
