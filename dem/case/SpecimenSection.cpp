// The `specimen` section: where the DEM specimen comes from and how it is prepared.
#include "dem/case/DemSections.h"

namespace geocomp::sections {

using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;
using dealii::Patterns::Anything;

void declare_specimen(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("specimen");
  prm.declare_entry("source", "generate", Selection("generate|store|text"),
                    "Where the DEM specimen comes from: 'generate' (radius growth, S0), 'store' "
                    "(a specimen from an HDF5 core store), 'text' (a packing file made elsewhere: see 'text file').");
  prm.declare_entry("store file", "", Anything(), "Core store (HDF5) for source = store.");
  prm.declare_entry("store name", "", Anything(), "Specimen name inside the store.");
  prm.declare_entry("text file", "", Anything(), "Packing file for source = text: a LAMMPS/LIGGGHTS data file (atom_style granular) when "
                    "the name ends in .data, else x y z r per line with the box in a '#' header line (the "
                    "format of bench/*.xyzr). Its spheres relax frictionless, then are consolidated.");
  prm.declare_entry("particles", "2000", Integer(8, 10000000), "Number of spheres N (S0 reference: 100000).");
  prm.declare_entry("packing fraction", "0.64", Double(0.30, 0.7405),
                    "Target packing fraction eta (S0: 0.6 <= eta < 0.7405; reference 0.69).");
  prm.declare_entry("radius", "0.0118", Double(1e-6, 10), "Mean sphere radius R [m] (S0: 11.8 mm).");
  prm.declare_entry("size distribution", "monodisperse", Selection("monodisperse|uniform|lognormal-mass"),
                    "Radii: equal, uniform in radius (see 'radius spread'), or lognormal by mass (S4).");
  prm.declare_entry("radius spread", "0", Double(0, 0.9),
                    "For 'uniform': half-width of the radius range relative to the mean radius.");
  prm.declare_entry("lognormal sigma", "0.432", Double(0, 3), "For 'lognormal-mass': sigma of ln m (S4: 0.432).");
  prm.declare_entry("box size", "0", Double(0, 1e3),
                    "Cube edge L0 [m]; 0 derives it from N, eta and R (S0 reference: 1.0 m).");
  prm.declare_entry("density", "2650", Double(1, 1e5), "Particle density [kg/m^3].");
  prm.declare_entry("isotropic pressure", "2e6", Double(0, 1e10),
                    "All-round pre-stress sigma_0 [Pa], compression positive (S0: 8.093 MPa; 2 MPa).");
  prm.declare_entry("aristotelian", "false", Bool(),
                    "Pack with first-order (overdamped, velocity proportional to force) dynamics.");
  prm.declare_entry("preparation", "consolidate", Selection("consolidate|as given"),
                    "What happens to the specimen before the program: 'consolidate' (rest, friction on, servo "
                    "consolidation to 'isotropic pressure'; for a text source a frictionless rest first), or "
                    "'as given' for an imported packing (source = text or store): the program starts on the "
                    "positions (and the velocities a LAMMPS data file lists) exactly as read, with no rest, no "
                    "consolidation and no isotropic pressure required.");
  prm.declare_entry("frictionless relaxation", "damped", Selection("damped|fire"),
                    "How the grown frictionless packing comes to rest at fixed walls (Newtonian growth): "
                    "Cundall local damping, or FIRE (Bitzek et al. 2006: velocities turned towards the "
                    "forces, adaptive time step). The friction-on rest and the consolidation stay damped "
                    "(docs/specimens.md).");
  prm.leave_subsection();
}

SpecimenParameters parse_specimen(dealii::ParameterHandler &prm, const Reader &r)
{
  SpecimenParameters p;
  read_section(prm, r, "specimen", p);
  if (p.aristotelian && p.frictionless_relaxation == "fire")
    r.fail("specimen/frictionless relaxation", "fire needs Newtonian dynamics: set aristotelian = false or frictionless relaxation = damped");
  if (p.source == "store" && (p.store_file.empty() || p.store_name.empty()))
    r.fail(p.store_file.empty() ? "specimen/store file" : "specimen/store name",
           "source = store needs both 'store file' and 'store name'");
  if (p.preparation == "as given" && p.source == "generate")
    r.fail("specimen/preparation", "'as given' needs an imported packing (source = text or store); a generated "
                                   "specimen is grown and consolidated");
  if (p.source == "text" && p.text_file.empty())
    r.fail("specimen/text file", "source = text needs a packing file");
  if (p.size_distribution == "uniform" && p.radius_spread <= 0.0)
    r.fail("specimen/radius spread", "a uniform size distribution needs a spread > 0");
  return p;
}

} // namespace geocomp::sections
