// @sect3{How closely the servo held its goals: a DEM Response, read back}
//
// Why it exists: issue 30's measure of a servo that holds. For every stress-controlled axis
// of every stage, on the main path, from the end of the first `allowance` (0.5 %) of axial
// strain of the stage to its end:
//  - the interval mean: the largest $|\bar\sigma_{aa} - \sigma^{goal}_{aa}| / |\sigma^{goal}_{aa}|$
//    of the samples' interval-mean stresses (ResponseSample::stress_mean);
//  - the instantaneous: the same for the stress at the sample instants;
//  - the step: the largest deviation at any step of those intervals (the engine's
//    `servo_deviation` extra, all stress axes together);
//  - the wall-speed reversals: steps at which a servo wall's speed changed sign (the
//    `servo_reversals` extra) against the steps taken; an oscillating loop reverses every
//    step or every few, a loop that follows the specimen only where the specimen turns.
// The axial strain is that of the stage's fastest kinematic axis, from the stage's first
// sample. A stage without a kinematic axis (every axis on a stress goal: a consolidation,
// an approach from rest) is not counted: its convergence is its own stop condition.
#pragma once

#include "common/LoadingProgram.h"
#include "common/Response.h"

#include <string>
#include <vector>

namespace geocomp::dem {

struct AxisDeviation
{
  int stage = 0;
  int axis = 0;
  double goal = 0.0;              ///< [Pa]
  double mean = 0.0;              ///< largest relative deviation of the interval means
  double mean_signed = 0.0;       ///< that deviation with its sign (> 0: less compressed than the goal)
  double instantaneous = 0.0;     ///< largest relative deviation at the sample instants
  double step = 0.0;              ///< largest at any step (all stress axes of the stage)
  std::size_t samples = 0;        ///< samples counted
};

struct ServoReport
{
  std::vector<AxisDeviation> axes;
  double reversals = 0.0; ///< servo wall-speed reversals in the counted intervals
  double steps = 0.0;     ///< DEM steps of those intervals
  /// The worst of each over all axes.
  double worst_mean() const;
  double worst_instantaneous() const;
  double worst_step() const;
  /// One line per axis, for logs and docs.
  std::string describe() const;
};

/// Reads a DEM Response (the extras `servo_deviation`, `servo_reversals`, `steps`) of
/// `program`; std::invalid_argument if the extras are missing.
ServoReport servo_report(const Response &response, const LoadingProgram &program, double allowance = 0.005);

} // namespace geocomp::dem
