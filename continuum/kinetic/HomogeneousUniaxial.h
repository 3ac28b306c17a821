#pragma once
// @sect3{Homogeneous uniaxial test of one kinetic point (no inertia)}
//
// Why: the specimen engine adds waves and inertia to the material response; this driver
// isolates the material. It loads one point in uniaxial stress along y at a constant
// strain rate (sigma_xx = sigma_zz = 0; by isotropy d eps_xx = d eps_zz, solved by a
// monotone root) until it fractures, and reports the peak stress. The rate-sweep tests
// and the docs compare it with S1 eqs. (14)-(15) and with the FE specimen.
#include "continuum/kinetic/KineticNikolaevsky.h"

#include <vector>

namespace geocomp::kinetic {

enum class LoadingMode { compression, tension };
const char *to_string(LoadingMode mode);

struct UniaxialPointResult {
  double peak_stress = 0.0;      ///< largest |sigma_yy| [Pa]
  double strain_at_peak = 0.0;   ///< |eps_yy| at the peak
  double fracture_time = -1.0;   ///< [s]; -1 if the point never fractured
  double yield_stress = -1.0;    ///< |sigma_yy| at the first plastic step [Pa]; -1 if none
  std::vector<std::pair<double, double>> curve; ///< (|eps_yy|, |sigma_yy|), every `sample_every` steps
};

/// @param steps_to_static_strength the time step is sigma_st / (E epsdot) / this number.
UniaxialPointResult run_uniaxial_point(const KineticNikolaevsky &model, LoadingMode mode, double strain_rate,
                                       int steps_to_static_strength = 2000, int sample_every = 0);

} // namespace geocomp::kinetic
