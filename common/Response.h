#pragma once
// The Response record: what every engine emits for a loading program.
//
// One sample per sampling instant: time, the full engineering strain tensor of the box
// (relative to the start of the program), the full stress tensor at that instant and its
// mean over the sampling interval that ends there, the stage and the branch it belongs to
// (0 = main path, k = k-th unloading branch), and named engine extras (DEM: coordination
// number, inertial number...; FE: Newton iterations...). A dynamic engine (DEM) averages
// its stress over every step of the interval, as Yade and LIGGGHTS users compare it; a
// quasi-static engine's sample is its state, so its mean is the instantaneous stress
// (Response::interval_means says which).
// Metrics in compare/ read only this record, so they never depend on the engine.
#include "common/Tensor.h"

#include <string>
#include <vector>

namespace geocomp {

struct ResponseSample {
  double time = 0.0;
  Tensor3 strain = Tensor3::Zero(); ///< engineering, tension positive
  Tensor3 stress = Tensor3::Zero(); ///< Cauchy [Pa], tension positive, at `time`
  /// Mean of the stress over the sampling interval ending at `time` (time-weighted over
  /// the engine's steps); the instantaneous stress where the engine gives no mean.
  Tensor3 stress_mean = Tensor3::Zero();
  int stage = 0;                    ///< 0-based stage index
  int branch = 0;                   ///< 0 main path, k >= 1 unloading branch k
  std::vector<double> extras;       ///< aligned with Response::extras
};

struct ExtraColumn {
  std::string name;
  std::string units;
  std::string description;
};

/// One unloading branch: where it left the main path and where it ended.
struct BranchRecord {
  /// The trigger of a branch placed by the runner to locate the elastic limit (a case's
  /// triggers are "peak" or conditions, never this word).
  static constexpr const char *bisection_trigger = "bisection";
  int id = 0;
  int stage = 0;
  std::string trigger;
  /// Index of the main-path sample it starts from; a bisection branch that leaves the main
  /// path between two samples starts from its own first sample (the main-path state there).
  std::size_t first_sample = 0;
  std::size_t last_sample = 0;  ///< index of its final sample
  double tau_start = 0.0;       ///< tau_max where the branch left the main path
  double tau_target = 0.0;      ///< level it unloaded to
  double gamma_start = 0.0;     ///< gamma_max there
  double residual_gamma = 0.0;  ///< gamma_max at the end of the branch
  bool reached_target = false;
  bool bisection() const { return trigger == bisection_trigger; }
};

struct Response {
  std::string engine; ///< "dem", "continuum-fe", "material-point", ...
  bool interval_means = false; ///< stress_mean is a mean over each interval (else a copy of stress)
  std::vector<ExtraColumn> extras;
  std::vector<ResponseSample> samples;
  std::vector<BranchRecord> branches;
  std::vector<std::string> stage_names;
  std::vector<std::string> stage_end_reasons; ///< condition text, or "max duration"

  int extra_index(const std::string &name) const; ///< -1 if absent
  /// Samples of one branch (0 = main path) in order.
  std::vector<const ResponseSample *> path(int branch) const;
};

/// The response as metrics and reports read it: each sample's stress replaced by its
/// interval mean when the engine gives means (the DEM: a sample instant catches the wall
/// force mid-fluctuation, the mean is what Yade and LIGGGHTS users compare); unchanged
/// otherwise. The instantaneous stresses stay in the results file.
Response with_interval_means(Response response);

} // namespace geocomp
