#pragma once
// @sect3{Strength versus strain rate: S1's Fig. 5 and Fig. 6 experiment}
//
// Why: S1's verification is a sweep of constant-rate uniaxial tests; the normalized
// strength sigma_peak / sigma_st is compared with the data fits (14) (compression) and
// (15) (tension), with the kinetic model on (Fig. 5) and off (Fig. 6, where only inertia
// can raise the strength). Each row also carries the homogeneous point result (same
// material, no inertia), so the inertial part of the rise is visible on its own.
#include "continuum/dynamics/ExplicitSpecimen.h"

#include <functional>
#include <string>
#include <vector>

namespace geocomp::dynamics {

using kinetic::S1Material;

struct RateSweepSetup {
  std::string title;
  S1Material material;
  LoadingMode mode = LoadingMode::compression;
  std::vector<double> strain_rates;      ///< [1/s]
  std::vector<bool> kinetic_modes{true, false};
  SpecimenGeometry geometry;
  DynamicsControls controls;
};

struct RateSweepRow {
  bool kinetic = true;
  double strain_rate = 0.0;
  double normalized_strength = 0.0;       ///< specimen peak / static strength
  double s1_fit = 0.0;                    ///< S1 eq. (14) or (15)
  double point_normalized_strength = 0.0; ///< homogeneous point (no inertia) peak / static strength
  SpecimenRunResult run;
  /// normalized_strength / s1_fit - 1
  double relative_error() const { return normalized_strength / s1_fit - 1.0; }
};

/// S1 eq. (14) for compression, eq. (15) for tension.
double s1_strength_factor(LoadingMode mode, double strain_rate);

/// Runs every (kinetic mode, rate) pair; `progress` is called after each.
std::vector<RateSweepRow> run_rate_sweep(const RateSweepSetup &setup,
                                         const std::function<void(const RateSweepRow &)> &progress = {});

} // namespace geocomp::dynamics
