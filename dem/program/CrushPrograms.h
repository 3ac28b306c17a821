// @sect3{S2's crushing programs: single-particle crushing and uniaxial compression}
//
// Why it exists: S2 (Zhao & Chi 2022) calibrates and demonstrates its cube replacement
// mode with two numerical tests, which this file runs on the DEM engine:
//  - single particle: spheres of random diameter in [d_min, d_max] (S2: 100 particles,
//    28-30 mm), one at a time between two platens closing at constant speed, until the
//    crushing criterion (S2 eq. (3)) breaks it; records the platen force against the
//    approach, the crushing force and every fragment (S2 Figs. 2-4);
//  - uniaxial: one-size spheres (S2: 40 mm) on a jittered lattice (or grown from random
//    positions to a random packing) in a rigid box, seated by the lid to a small stress
//    with breakage off, then compressed one-dimensionally by the lid at constant speed
//    with breakage on; records vertical stress against strain, the number broken, the
//    final gradation (S2 Fig. 7) and the polar distributions of contact number and mean
//    contact force after seating, at the most loaded recorded state and at the end
//    (S2 Figs. 8-11, ContactPolarDistribution.h).
// Contact: S2's linear law with rolling resistance (kn, ks, mu, mu_r) plus a small
// normal dashpot and Cundall local damping (quasi-static loading, as in PFC).
// Time step: safety * critical step of the current particles, recomputed after every
// breakage batch (fragments are lighter). An optional uniform density scaling (mass
// scaling, common for quasi-static DEM) lengthens the step; gravity is off (its stress,
// ~3 kPa, is negligible against the MPa of crushing).
#pragma once

#include "dem/BreakageMonitor.h"
#include "dem/program/ContactPolarOutput.h"

#include <functional>
#include <string>
#include <vector>

namespace geocomp::dem {

struct CrushContact
{
  double normal_stiffness = 7.0e7;   ///< kn [N/m] (S2)
  double shear_stiffness = 6.0e7;    ///< ks [N/m] (S2)
  double friction = 0.40;            ///< mu (S2)
  double rolling_friction = 0.70;    ///< mu_r (S2)
  double restitution = 0.3;          ///< normal dashpot (not in S2)
  double wall_friction = 0.0;        ///< platens and box walls
  double local_damping = 0.7;        ///< Cundall lambda (PFC default)
};

struct SingleParticleSetup
{
  int particles = 100;
  double d_min = 0.028, d_max = 0.030;  ///< [m]
  double platen_speed = 0.01;           ///< closing speed of the platens [m/s]
  std::uint64_t seed = 1;               ///< particle sizes
  /// Repetitions of the test (S2 Fig. 3: ten seeds); particle i of repetition r is crushed
  /// with the fragment seed breakage.seed + r particles + i, so repetition 0 is the
  /// single test and every particle of every repetition draws its own cut point.
  int runs = 1;
};

struct UniaxialSetup
{
  double diameter = 0.040;       ///< [m]
  int per_edge = 5;              ///< lattice sites per box edge (per_edge^3 spheres)
  /// "lattice": jittered simple cubic lattice (loose; seating makes load columns);
  /// "grown": random placement at 0.7 of the size in a cube box, frictionless radius
  /// growth (RadiusGrowth.h) to `packing_fraction`, then seating as for the lattice.
  std::string packing = "lattice";
  double packing_fraction = 0.45;  ///< grown: solid fraction after growth (below jamming)
  double lattice_gap = 0.1;      ///< lattice spacing 2R (1 + gap)
  double seating_stress = 50e3;  ///< [Pa] lid stress that ends seating
  double seating_speed = 0.5;    ///< [m/s]
  double lid_speed = 0.05;       ///< [m/s] during compression
  double final_strain = 0.10;
  std::uint64_t seed = 1;        ///< lattice jitter
};

struct CrushSetup
{
  std::string title;
  std::string mode = "single particle";  ///< "single particle" | "uniaxial"
  double density = 2650.0;               ///< [kg/m^3]
  double density_scaling = 1.0;
  CrushContact contact;
  BreakageMonitor::Settings breakage;
  double time_step_safety = 0.2;
  std::uint64_t record_interval = 200;   ///< steps between curve rows
  double gradation_bin = 0.002;          ///< [m] sieve spacing of the gradation (S2 Fig. 7: 2 mm)
  ContactPolarDistribution::Settings polar;  ///< roses of S2 Figs. 8-11 (uniaxial)
  SingleParticleSetup single;
  UniaxialSetup uniaxial;
};

/// A table with a header line, written as TSV.
struct Table
{
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

struct CrushResults
{
  Table curve;       ///< force-displacement (single) or stress-strain (uniaxial)
  Table crushing;    ///< single: one row per particle (d, crushing force, sigma, children, run)
  Table fragments;   ///< every child of a breakage event (single, with its run) / every breakage event (uniaxial)
  Table gradation;   ///< percent passing by mass vs size
  std::vector<std::string> summary;  ///< "key<TAB>value" lines
  /// uniaxial: contact roses (S2 Figs. 8-11) "seated" (after seating), "peak" (the curve row
  /// of largest lid stress) and "final"
  std::vector<PolarState> polar;
};

/// Runs the program of `s`; `progress` gets a line now and then.
CrushResults run_crush(const CrushSetup& s, const std::function<void(const std::string&)>& progress = {});

/// Writes a table as TSV with one header line.
void write_table(const std::string& path, const Table& t);

}  // namespace geocomp::dem
