#pragma once
// Loading programs and materials shared by the continuum-engine tests. Every number a
// test checks is computed from the closed forms written next to it.
#include "common/LoadingProgram.h"
#include "common/Response.h"

#include <gtest/gtest.h>
#include "continuum/models/MohrCoulombReturnMap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace geocomp::continuum::testing {

inline double deg(double d) { return d * M_PI / 180.0; }
/// N_phi = (1 + sin phi) / (1 - sin phi).
inline double N_of(double phi) { return (1.0 + std::sin(phi)) / (1.0 - std::sin(phi)); }

/// Stage 1: all three axes to the isotropic stress -p (compression), held for `duration`.
inline Stage isotropic_stage(double p, double duration)
{
  Stage s;
  s.name = "consolidation";
  for (auto &a : s.axes)
    a = AxisDrive::stress(-p);
  s.stop_any = {parse_condition("stage_time >= " + std::to_string(duration), "test")};
  s.max_duration = 2.0 * duration;
  return s;
}

/// Conventional triaxial compression: x and y held at -p, z shortened at `rate` (1/s)
/// until eps_zz <= -strain.
inline Stage triaxial_stage(double p, double rate, double strain)
{
  Stage s;
  s.name = "shear";
  s.axes[0] = AxisDrive::stress(-p);
  s.axes[1] = AxisDrive::stress(-p);
  s.axes[2] = AxisDrive::rate(-rate);
  s.stop_any = {parse_condition("eps_zz <= " + std::to_string(-strain), "test")};
  s.max_duration = 2.0 * strain / rate;
  return s;
}

/// Perfectly plastic Mohr-Coulomb (constant c, phi, psi).
inline MohrCoulombParameters perfect_mohr_coulomb(double E, double nu, double c, double phi, double psi)
{
  MohrCoulombParameters m;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.cohesion = PiecewiseLinear(c);
  m.friction_angle = PiecewiseLinear(phi);
  m.dilatancy_angle = PiecewiseLinear(psi);
  return m;
}

/// S0's isochoric shear (eq. 3, lambda = 0) from the start of the program, sampled every
/// `interval` until gamma_max >= `gamma`.
inline LoadingProgram s0_isochoric(double gamma, double interval)
{
  LoadingProgram program;
  program.sample_interval = interval;
  Stage shear;
  shear.name = "isochoric";
  shear.isochoric = true;
  shear.isochoric_rate = 0.05;
  shear.stop_any = {parse_condition("gamma_max >= " + std::to_string(gamma), "test")};
  shear.max_duration = 100.0;
  program.stages = {shear};
  program.validate();
  return program;
}

/// Perfect Mohr-Coulomb with psi = 0 from the initial stress -p under s0_isochoric: at
/// finite strain det F = 1 and the flow is isochoric, so every sample keeps the mean stress
/// -p, and once plastic tau_max = c cos(phi) + p sin(phi) (to `tolerance`, relative).
/// Returns the number of plastic samples (state flag or plastic fraction > 0).
inline int expect_isochoric_plateau(const Response &r, double p, double c, double phi, double tolerance)
{
  const int flag = r.extra_index("state_flag") >= 0 ? r.extra_index("state_flag") : r.extra_index("plastic_fraction");
  const double tau_yield = c * std::cos(phi) + p * std::sin(phi);
  int plastic = 0;
  double drift = 0.0, plateau = 0.0; // largest relative deviations, printed as measured
  for (const auto &s : r.samples) {
    drift = std::max(drift, std::abs(mean_stress(s.stress) / -p - 1.0));
    if (!(std::abs(mean_stress(s.stress) / -p - 1.0) <= tolerance))
      ADD_FAILURE() << r.engine << ": mean stress " << mean_stress(s.stress) << " at t = " << s.time;
    if (s.extras[flag] == 0.0) {
      if (!(tau_max(s.stress) <= tau_yield * (1.0 + tolerance)))
        ADD_FAILURE() << r.engine << ": elastic sample above yield at t = " << s.time;
      continue;
    }
    ++plastic;
    plateau = std::max(plateau, std::abs(tau_max(s.stress) / tau_yield - 1.0));
    if (!(std::abs(tau_max(s.stress) / tau_yield - 1.0) <= tolerance))
      ADD_FAILURE() << r.engine << ": tau_max / (c cos phi + p sin phi) = " << tau_max(s.stress) / tau_yield
                    << " at t = " << s.time;
  }
  std::printf("[ measured ] %s: largest mean-stress drift %.2e, plateau deviation %.2e (tolerance %.0e)\n",
              r.engine.c_str(), drift, plateau, tolerance);
  return plastic;
}

} // namespace geocomp::continuum::testing
