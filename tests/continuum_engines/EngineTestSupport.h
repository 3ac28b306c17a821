#pragma once
// Loading programs and materials shared by the continuum-engine tests. Every number a
// test checks is computed from the closed forms written next to it.
#include "common/LoadingProgram.h"
#include "continuum/models/MohrCoulombReturnMap.h"

#include <cmath>
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

} // namespace geocomp::continuum::testing
