// Material-point targets with known parameters for the calibration tests: the truth,
// the programs, and a target made by the material point (optionally with noise).
#pragma once

#include "compare/calibrate/FitTarget.h"
#include "continuum/driver/CaseMaterial.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace geocomp::calibration::synthetic {

/// The truth: Mohr-Coulomb with friction hardening then softening, constant cohesion,
/// dilatancy rising to 8 deg.
inline ContinuumParameters truth()
{
  ContinuumParameters p;
  p.youngs_modulus = 80e6;
  p.poisson_ratio = 0.3;
  p.cohesion.points = {{0.0, 30e3}};
  p.friction_angle.points = {{0.0, 20.0}, {0.02, 32.0}, {0.08, 27.0}};
  p.dilatancy_angle.points = {{0.0, 0.0}, {0.02, 8.0}};
  return p;
}

/// Constant lateral pressure `p`, axial compression to 6 %.
inline LoadingProgram axial(double p)
{
  LoadingProgram program;
  program.sample_interval = 0.0015;
  Stage s;
  s.name = "axial";
  s.axes = {{AxisDrive::stress(-p), AxisDrive::stress(-p), AxisDrive::rate(-1.0)}};
  s.stop_any = {parse_condition("eps_zz <= -0.06", "test")};
  s.max_duration = 1.0;
  program.stages = {s};
  return program;
}

/// A target made by the material point with the `material` parameters (the truth unless
/// given); `noise` adds Gaussian noise of that fraction of the largest axial stress to
/// sigma_zz (seeded).
inline FitTarget made_target(const LoadingProgram &program, double p, double noise, unsigned seed,
                             const ContinuumParameters &material = truth())
{
  FitTarget probe;
  probe.program = program;
  probe.initial_stress = -p;
  probe.substeps = 10;
  Response r = simulate(probe, continuum::material_from_case(material));
  if (noise > 0.0) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    double smax = 0.0;
    for (const auto &s : r.samples)
      smax = std::max(smax, std::abs(s.stress(2, 2)));
    for (std::size_t k = 1; k < r.samples.size(); ++k)
      r.samples[k].stress(2, 2) += noise * smax * gauss(rng);
  }
  return make_target("p = " + std::to_string(p), r, program, -p, 10, 1.0);
}

} // namespace geocomp::calibration::synthetic
