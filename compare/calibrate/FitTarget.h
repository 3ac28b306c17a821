// @sect3{A curve to fit and its replay on the material point}
//
// Why it exists: a target is a results file (typically a DEM run). The file carries the
// case it was run from, so the same loading program and initial stress are replayed on
// the material point with trial continuum parameters (unloading branches left out: the
// fit uses the main path). The residuals compare, at the target's main-path sample
// times, the deviator q = sqrt(3 J2) (scaled by the target's largest q) and the
// volumetric strain (scaled by its range, at least 1e-3, times the volumetric weight):
//   r_q,k = w (q_model(t_k) - q_target(t_k)) / max|q_target|
//   r_v,k = w w_v (eps_v,model(t_k) - eps_v,target(t_k)) / max(range eps_v,target, 1e-3)
// Model values between its samples are interpolated linearly in time; a model run that
// ends early (a stop condition met sooner) is held at its last sample.
#pragma once

#include "common/LoadingProgram.h"
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

/// Number of residuals of a target (2 per fitted sample).
std::size_t residual_count(const FitTarget &target);
/// Writes residual_count(target) residuals of `model` against the target.
void residuals(const FitTarget &target, const Response &model, double volumetric_weight, double *out);

/// Deviator q = sqrt(3 J2) of a stress.
double deviator(const Tensor3 &stress);

} // namespace geocomp::calibration
