// @sect3{The free parameters of a calibration}
//
// Why it exists: a calibration varies a few numbers of the continuum section of a case -
// E, nu and the knot values of the piecewise-linear tables c(kappa), phi(kappa),
// psi(kappa) (the knots' kappa stay fixed) - and Ceres sees them as one vector. This class
// is the map between the two, with the bounds in case-file units (Pa, degrees).
// The model ladder (Ladder.h) also fits S1's Nikolaevsky model: on a section with
// model = nikolaevsky (material custom), E and nu are those of its nikolaevsky subsection,
// and four more families free its yield stress sigma_y, compressive strength sigma_c (the
// hardening, with eps_p* fixed), internal friction alpha and dilatancy Lambda. They are not
// names a case file's `free parameters` accepts (`calibrate` fits Mohr-Coulomb sections).
#pragma once

#include "compare/case/CaseDescription.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::calibration {

/// Bad or unidentifiable calibration input; names the parameter concerned.
struct CalibrationError : std::runtime_error {
  CalibrationError(std::string parameter, const std::string &message)
    : std::runtime_error(message), parameter(std::move(parameter)) {}
  std::string parameter;
};

struct FreeParameter {
  enum class Family { E, Nu, Cohesion, Friction, Dilatancy, YieldStress, CompressiveStrength, InternalFriction, Lambda };
  std::string name;     ///< "E", "nu", "friction[1]", "yield stress", ...
  Family family = Family::E;
  int knot = -1;        ///< table knot for Cohesion/Friction/Dilatancy
  double lower = 0.0, upper = 0.0;
};

class FreeParameters {
public:
  /// The free parameters `c` names, on the tables of `base` (throws CalibrationError for a
  /// knot that the table does not have, or for a Nikolaevsky parameter on another model).
  FreeParameters(const ContinuumParameters &base, const CalibrationParameters &c);

  /// Every parameter a calibration of `p` can free: E, nu and each knot of the tables.
  static FreeParameters all(const ContinuumParameters &p);
  /// Whether a parameter of that name is among these.
  bool contains(const std::string &name) const;

  const std::vector<FreeParameter> &list() const { return list_; }
  std::size_t size() const { return list_.size(); }
  /// The free values of a continuum section.
  std::vector<double> values(const ContinuumParameters &p) const;
  /// `p` with the free values replaced.
  ContinuumParameters apply(const ContinuumParameters &p, const std::vector<double> &values) const;

private:
  std::vector<FreeParameter> list_;
};

} // namespace geocomp::calibration
