// The consolidated specimens shared by the dem_program tests: n^3 spheres (n = 7: 343,
// n = 14: 2744; R = 5 mm +- 10 %) on a loose jittered lattice (packing fraction ~0.24,
// jitter up to 0.3 R per axis), compacted frictionless by the servo to
// sigma_0 = 100 kPa with preparation damping, then mu_s = 0.4 switched on and held again
// until quasi-static (unbalanced-force ratio < 1e-3) with the damping off. The loose
// specimen is compacted with mu_s = 0.4 on from the start (friction stops the grains short
// of the dense arrangement). Built once per process.
#pragma once

#include "dem/program/DemEngine.h"
#include "dem/program/LatticePacking.h"

#include <chrono>
#include <cstdio>
#include <string>

namespace geocomp::dem::test {

constexpr double kPressure = 1.0e5;

inline ContactParameters contact_parameters()
{
  ContactParameters c;
  c.model = "linear";
  c.normal_stiffness = 2.0e5; // kappa = k_n / (p d) = 200: overlaps ~0.5 % of d
  c.restitution = 0.5;
  c.tangential_stiffness_ratio = 2.0 / 7.0;
  c.particle_friction = 0.4;
  c.wall_friction = 0.0;
  return c;
}

inline DemParameters dem_parameters()
{
  DemParameters d;
  d.threads = 1;
  d.time_step_safety = 0.2;
  d.skin = 0.1;
  return d;
}

inline DemEngineParameters engine_parameters()
{
  DemEngineParameters p;
  p.servo.proportional_gain = 0.5;
  p.servo.max_velocity = 0.05;
  return p;
}

struct Consolidated
{
  DemSystem system;
  HoldResult frictionless, frictional;
  double seconds = 0.0;
};

inline Consolidated consolidate(int n_per_edge, std::uint64_t seed, double compaction_friction = 0.0)
{
  {
    const auto start = std::chrono::steady_clock::now();
    Consolidated r;
    ContactParameters cp = contact_parameters();
    cp.particle_friction = compaction_friction; // S0: frictionless preparation
    DemSystem sys = make_system(jittered_lattice(n_per_edge, 0.005, 0.1, 0.3, 2650.0, seed), cp, dem_parameters());
    sys.set_local_damping(0.5); // preparation only
    DemEngine prep(std::move(sys), engine_parameters());
    r.frictionless = hold_isotropic(prep, kPressure, 0.005, 1e-2, 2.0, 0.002);
    DemSystem dense = prep.system();
    dense.set_friction(contact_parameters().particle_friction);
    dense.set_local_damping(0.0);
    DemEngine hold(std::move(dense), engine_parameters());
    r.frictional = hold_isotropic(hold, kPressure, 0.005, 1e-3, 2.0, 0.002);
    r.system = hold.system();
    for (int w = 0; w < 6; ++w)
      r.system.set_wall_velocity(w, Vec3::Zero());
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[specimen %zu spheres] frictionless: converged %d after %.4f s (error %.2e, UFR %.2e); "
                "frictional: converged %d after %.4f s (error %.2e, UFR %.2e); %llu steps, %.2f s wall\n",
                r.system.n_particles(), int(r.frictionless.converged), r.frictionless.time, r.frictionless.stress_error,
                r.frictionless.unbalanced, int(r.frictional.converged), r.frictional.time,
                r.frictional.stress_error, r.frictional.unbalanced, (unsigned long long)r.system.n_steps(),
                r.seconds);
    return r;
  }
}

/// Lateral stress -pressure on x and y, z shortened at `rate` to eps_zz = -strain (max
/// duration twice the time that takes).
inline Stage triaxial_stage(double pressure, double rate, double strain)
{
  Stage s;
  s.name = "triaxial";
  s.axes = {{AxisDrive::stress(-pressure), AxisDrive::stress(-pressure), AxisDrive::rate(-rate)}};
  s.stop_any = {parse_condition("eps_zz <= " + std::to_string(-strain), "test")};
  s.max_duration = 2.0 * strain / rate;
  return s;
}

inline const Consolidated &consolidated()
{
  static const Consolidated c = consolidate(7, 11);
  return c;
}

inline const Consolidated &consolidated_large()
{
  static const Consolidated c = consolidate(14, 11);
  return c;
}

inline const Consolidated &consolidated_large_loose()
{
  static const Consolidated c = consolidate(14, 11, contact_parameters().particle_friction);
  return c;
}

} // namespace geocomp::dem::test
