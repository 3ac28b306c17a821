#pragma once
// The DEM's sections of a case file, as plain data: `specimen`, `contact`, `dem`. (Clumped
// grains are built by the shear-box case, dem/program/ShearBoxCase.h, whose `grains` section
// describes them; the wall-box engine packs spheres.)
//
// Why here: each engine owns its parameters (deal.II step-42's rule, one home per
// parameter). These structs, their declarations and parsers (dem/case/*Section.cpp) and
// their `visit` lists live in the DEM's folder; adding an entry touches only this folder.
// `visit(struct, v)` calls v("entry", field) for every declared entry in declaration
// order: CanonicalText writes the structs with it (the specimen record, SpecimenRecord.h,
// and `/meta/parameters` of every result), and a test checks that it names exactly the
// declared entries. Conventions: SI; "pressure" is a magnitude, positive in compression.
#include "common/case/CaseParameters.h"

#include <string>

namespace geocomp::dem {

struct SpecimenParameters {
  std::string source = "generate";      ///< generate | store | text
  std::string store_file, store_name;   ///< for source = store
  std::string text_file;                ///< for source = text (x y z r per line)
  unsigned int particles = 2000;
  double packing_fraction = 0.64;
  double radius = 0.0118;               ///< [m] mean radius
  std::string size_distribution = "monodisperse"; ///< monodisperse | uniform | lognormal-mass
  double radius_spread = 0.0;           ///< uniform: half-width relative to the mean radius
  double lognormal_sigma = 0.432;       ///< lognormal-mass: sigma of ln m (S4)
  double box_size = 0.0;                ///< [m] L0; 0 = from N, eta and R
  double density = 2650.0;              ///< [kg/m^3]
  double isotropic_pressure = 2.0e6;    ///< [Pa] sigma_0, compression positive
  bool aristotelian = false;            ///< first-order (overdamped) packing dynamics
  /// consolidate (rest, friction on, servo to the isotropic pressure) | as given (an imported
  /// packing starts the program exactly as read: text and store sources)
  std::string preparation = "consolidate";
  std::string frictionless_relaxation = "damped"; ///< damped | fire: the frictionless rest after growth

  template <class Self, class V>
  static void visit(Self &p, V &&v)
  {
    v("source", p.source);
    v("store file", p.store_file);
    v("store name", p.store_name);
    v("text file", p.text_file);
    v("particles", p.particles);
    v("packing fraction", p.packing_fraction);
    v("radius", p.radius);
    v("size distribution", p.size_distribution);
    v("radius spread", p.radius_spread);
    v("lognormal sigma", p.lognormal_sigma);
    v("box size", p.box_size);
    v("density", p.density);
    v("isotropic pressure", p.isotropic_pressure);
    v("aristotelian", p.aristotelian);
    v("preparation", p.preparation);
    v("frictionless relaxation", p.frictionless_relaxation);
  }
};

struct ContactParameters {
  std::string model = "linear";         ///< linear (S0) | hertz-mindlin (S4)
  double youngs_modulus = 7.0e9;        ///< [Pa] particle E
  double poisson_ratio = 0.25;
  double impact_velocity = 1.0;         ///< [m/s] V_c in S0's k_n
  double restitution = 0.5;             ///< c_r
  double normal_stiffness = 0.0;        ///< [N/m] given directly; 0 = from E*, R*, m*, V_c
  double normal_damping = 0.0;          ///< [N s/m] given directly; 0 = from c_r
  double normal_damping_per_mass = 0.0; ///< [1/s] LIGGGHTS gamma_n: c_n = gamma_n m*; 0 = not used
  double tangential_stiffness_ratio = 2.0 / 7.0; ///< k_t / k_n
  double tangential_stiffness = 0.0;    ///< [N/m] k_t given directly; 0 = the ratio
  double tangential_damping_ratio = -1.0; ///< c_t / c_n; -1 = k_t / k_n (S0 eq. (2))
  double tangential_damping = 0.0;      ///< [N s/m] c_t given directly; 0 = the ratio
  double particle_friction = 0.4;       ///< mu_s
  double wall_friction = 0.0;           ///< mu_p
  // Optional contact parts (ContactPartsSection.cpp).
  std::string tangential_model = "coulomb"; ///< coulomb | s3-stick-slip (S3 eq. (9))
  double slip_displacement = 1e-4;      ///< [m] S3 delta*_tau
  double slip_retention = 1.0;          ///< S3 k_phi
  double rolling_friction = 0.0;        ///< mu_r (S2); 0 = none
  double rolling_stiffness_ratio = 1.0; ///< k_r / (k_t R*^2)
  double cohesion = 0.0;                ///< [Pa] S3 C_c; 0 = no bonds
  double cohesion_modulus = 1e6;        ///< [Pa] S3 E_c
  double adhesion = 0.0;                ///< [Pa] S3 C_a; 0 = none
  double adhesion_modulus = 1e6;        ///< [Pa] S3 E_a
  bool wall_bonding = false;            ///< bonds and adhesion with walls too
  std::string bonding_walls = "all";    ///< all | z: the walls that bond (z: the platens of direct tension)

  template <class Self, class V>
  static void visit(Self &p, V &&v)
  {
    v("model", p.model);
    v("youngs modulus", p.youngs_modulus);
    v("poisson ratio", p.poisson_ratio);
    v("impact velocity", p.impact_velocity);
    v("restitution", p.restitution);
    v("normal stiffness", p.normal_stiffness);
    v("normal damping", p.normal_damping);
    v("normal damping per mass", p.normal_damping_per_mass);
    v("tangential stiffness ratio", p.tangential_stiffness_ratio);
    v("tangential stiffness", p.tangential_stiffness);
    v("tangential damping ratio", p.tangential_damping_ratio);
    v("tangential damping", p.tangential_damping);
    v("particle friction", p.particle_friction);
    v("wall friction", p.wall_friction);
    v("tangential model", p.tangential_model);
    v("slip displacement", p.slip_displacement);
    v("slip retention", p.slip_retention);
    v("rolling friction", p.rolling_friction);
    v("rolling stiffness ratio", p.rolling_stiffness_ratio);
    v("cohesion", p.cohesion);
    v("cohesion modulus", p.cohesion_modulus);
    v("adhesion", p.adhesion);
    v("adhesion modulus", p.adhesion_modulus);
    v("wall bonding", p.wall_bonding);
    v("bonding walls", p.bonding_walls);
  }
};

struct DemParameters {
  double time_step_safety = 0.2;        ///< dt = safety * critical step
  unsigned int threads = 0;             ///< 0 = from the problem size (DemSystem::set_num_threads)
  double local_damping = 0.0;           ///< Cundall non-viscous damping while loading
  double skin = 0.1;                    ///< Verlet skin / mean diameter
  double servo_max_velocity = 0.05;     ///< [m/s] cap on a servo wall's speed (at least)
  double servo_speed_ratio = 4.0;       ///< the cap is at least this times the fastest kinematic wall's speed
  double servo_gain = 0.5;              ///< g_P: fraction of the stiffness-based correction per step
  double servo_integral_gain = 0.1;     ///< g_I: per-step gain of the servo's integral part
  double guard_min_edge = 3.0;          ///< a box edge below this many largest diameters fails the run
  double guard_stress_ratio = 1e3;      ///< a wall stress above this times the reference fails the run
  unsigned int snapshots = 4;           ///< particle snapshots for localization analysis
  double checkpoint_interval = 600.0;   ///< [s] wall time between program checkpoints (0: none)

  template <class Self, class V>
  static void visit(Self &p, V &&v)
  {
    v("time step safety", p.time_step_safety);
    v("threads", p.threads);
    v("local damping", p.local_damping);
    v("skin", p.skin);
    v("servo max velocity", p.servo_max_velocity);
    v("servo speed ratio", p.servo_speed_ratio);
    v("servo gain", p.servo_gain);
    v("servo integral gain", p.servo_integral_gain);
    v("guard min edge", p.guard_min_edge);
    v("guard stress ratio", p.guard_stress_ratio);
    v("snapshots", p.snapshots);
    v("checkpoint interval", p.checkpoint_interval);
  }
};

/// A case as the DEM sees it: the shared head (file, seed, ...) and the DEM's sections.
/// The whole case (compare/case/CaseDescription.h) derives from it, so the DEM's functions
/// take either.
struct DemCase : CaseHead {
  SpecimenParameters specimen;
  ContactParameters contact;
  DemParameters dem;

  /// Calls visit(section name, struct) for the three sections, in case-file order.
  template <class Self, class V>
  static void visit_sections(Self &c, V &&v)
  {
    v("specimen", c.specimen);
    v("contact", c.contact);
    v("dem", c.dem);
  }
};

} // namespace geocomp::dem

namespace geocomp {
// The DEM's structs by their old names, for code that spoke of them before they had a home.
using dem::ContactParameters;
using dem::DemParameters;
using dem::SpecimenParameters;
} // namespace geocomp
