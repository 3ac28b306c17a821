#pragma once
// The Rudnicki-Rice verdict: does bifurcation theory predict where the engines localize?
//
// Rudnicki & Rice (1975) give, for the state along the loading path, a critical hardening
// modulus h_crit and a band angle theta_0 (CONTINUUM-THEORY.md section 3); localization is
// predicted where the tangent hardening modulus h first falls to h_crit. The continuum run
// gives its own onset from the acoustic tensor (min over n of det(n.C_ep.n)/det(n.C_e.n)
// <= 0), DEM from its particle fields (Localization.h). This layer takes the three onsets as
// inputs (the theory and the FE scan live in continuum/), finds zero crossings along a path
// when asked, and tabulates differences against the theory. Angles: the band normal from
// the most compressive principal axis, degrees (the convention of theta_0).
#include <string>
#include <vector>

namespace geocomp::compare {

/// One onset: at which strain (the curve's x measure) and band angle.
struct OnsetEstimate {
  std::string source;       ///< "Rudnicki-Rice", "FE acoustic tensor", "DEM"
  bool found = false;
  double strain = 0.0;      ///< onset strain (fraction), in the same measure for every source
  double angle_deg = 0.0;   ///< band normal from the most compressive axis [deg]
  bool has_angle = true;
  std::string note;
};

/// First crossing of `indicator` from > 0 to <= 0 along a path (e.g. h - h_crit, or the
/// acoustic-tensor ratio min q), linearly interpolated in strain; the angle is
/// interpolated the same way. Arrays must have equal lengths (throws otherwise).
OnsetEstimate first_crossing(const std::string &source, const std::vector<double> &strain,
                             const std::vector<double> &indicator, const std::vector<double> &angle_deg);

struct VerdictTolerances {
  double strain_relative = 0.25; ///< |onset - predicted| <= this * predicted ...
  double strain_absolute = 0.002; ///< ... or <= this (whichever is larger)
  double angle_deg = 5.0;        ///< |angle - predicted| <= this
};

struct VerdictRow {
  OnsetEstimate onset;
  double strain_difference = 0.0;  ///< onset - predicted (fraction)
  double strain_relative = 0.0;    ///< (onset - predicted)/predicted
  double angle_difference_deg = 0.0;
  bool comparable = false;         ///< both this and the prediction were found
  bool strain_agrees = false, angle_agrees = false;
  std::string verdict;             ///< "agrees", "onset differs", "angle differs", "differs", "n/a"
};

struct RrVerdict {
  OnsetEstimate predicted;
  std::vector<VerdictRow> rows; ///< one per engine (FE, DEM), in input order
  VerdictTolerances tolerances;
  std::string summary;          ///< one sentence
};

/// Compares each engine's onset with the prediction.
RrVerdict rudnicki_rice_verdict(const OnsetEstimate &predicted, const std::vector<OnsetEstimate> &engines,
                                const VerdictTolerances &tolerances = {});

} // namespace geocomp::compare
