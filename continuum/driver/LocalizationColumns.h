#pragma once
// @sect3{The localization indicator's columns in a Response}
//
// Why a file of its own: the material point and the FE cube both record the acoustic-tensor
// indicator q = min_n det(n.C_ep.n)/det(n.C_e.n) (AcousticTensorScan.h) and its onset, and
// compare/ reads those columns by name (localization_q, localization_onset_time,
// localization_n*). One list keeps the names, units and order the same in both engines;
// the cube adds where the onset was (localization_x/y/z), a material point has no "where".
#include "common/Response.h"

#include <string>
#include <vector>

namespace geocomp::continuum {

struct LocalizationColumnsOptions {
  std::string q_description;   ///< what q is over (one point, or the minimum over points)
  bool onset_point = false;    ///< add the onset point's coordinates (a mesh has one)
};

/// localization_q, localization_onset_time, [localization_x/y/z,] localization_nx/ny/nz.
std::vector<ExtraColumn> localization_columns(const LocalizationColumnsOptions &options);

} // namespace geocomp::continuum
