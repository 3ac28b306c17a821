// The `dem` section: the DEM's numerics (time step, threads, skin, servo, guards,
// snapshots, checkpoints), and the three DEM sections declared and parsed together.
#include "dem/case/DemSections.h"
#include "dem/ThreadCount.h"

#include <string>

namespace geocomp::sections {

using dealii::Patterns::Double;
using dealii::Patterns::Integer;

void declare_dem(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("dem");
  prm.declare_entry("time step safety", "0.2", Double(1e-4, 1.0),
                    "Time step as a fraction of the critical step (sqrt(m/k) or S4's Rayleigh step).");
  prm.declare_entry("threads", "0", Integer(0, 1024),
                    "OpenMP threads of the DEM step; 0 = from the problem size: one thread per " +
                        std::to_string(dem::kMinParticlesPerThread) +
                        " particles (at least one), at most the OpenMP default (OMP_NUM_THREADS, else "
                        "the cores). The results are the same for any count.");
  prm.declare_entry("local damping", "0", Double(0, 0.99),
                    "Cundall local non-viscous damping while loading (0 = off; S0 loads without it).");
  prm.declare_entry("skin", "0.1", Double(0.001, 2.0), "Verlet skin as a fraction of the mean diameter.");
  prm.declare_entry("servo max velocity", "0.05", Double(1e-9, 100),
                    "Speed cap of a servo-controlled wall [m/s], raised to 'servo speed ratio' times the speed of "
                    "the fastest kinematic wall of the stage.");
  prm.declare_entry("servo speed ratio", "4", Double(0, 1e3),
                    "The servo walls' speed cap is at least this times the fastest kinematic wall's speed [1] "
                    "(a specimen widens about as fast as it is shortened; docs/dem.md).");
  prm.declare_entry("servo gain", "0.5", Double(1e-6, 1.0),
                    "g_P: fraction of the stiffness-based stress correction applied per step (proportional part "
                    "of the wall servo, docs/dem.md).");
  prm.declare_entry("servo integral gain", "0.1", Double(0, 1),
                    "g_I: per-step gain of the servo's integral part, which learns the wall speed an axis needs "
                    "(integral time g_P/g_I steps; 0 = proportional only, docs/dem.md).");
  prm.declare_entry("guard min edge", "3", Double(0, 1e3),
                    "A box edge shorter than this many largest particle diameters stops the run as failed "
                    "(exit 1, results so far, /meta/status) [1].");
  prm.declare_entry("guard stress ratio", "1e3", Double(1, 1e12),
                    "A wall stress above this times the reference (the largest |sigma_aa| at the start and of "
                    "every stress goal) stops the run as failed [1].");
  prm.declare_entry("snapshots", "4", Integer(0, 10000), "Particle snapshots kept for localization analysis.");
  prm.declare_entry("checkpoint interval", "600", Double(0, 1e9),
                    "Wall-clock seconds between checkpoints of a DEM program run (<output>/dem-program.ckpt, "
                    "at main-path samples; 0 = only on SIGINT/SIGTERM). Running the same command again "
                    "resumes from it, bit for bit.");
  prm.leave_subsection();
}

DemParameters parse_dem(dealii::ParameterHandler &prm, const Reader &r)
{
  DemParameters p;
  read_section(prm, r, "dem", p);
  return p;
}

void declare_dem_sections(dealii::ParameterHandler &prm)
{
  declare_specimen(prm);
  declare_contact(prm);
  declare_contact_parts(prm);
  declare_dem(prm);
}

void parse_dem_sections(dealii::ParameterHandler &prm, const Reader &r, dem::DemCase &c)
{
  c.specimen = parse_specimen(prm, r);
  c.contact = parse_contact(prm, r);
  c.dem = parse_dem(prm, r);
}

} // namespace geocomp::sections
