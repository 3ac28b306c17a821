#pragma once
// The case file, as plain data: what a user writes, checked and converted to SI.
//
// A case file (.prm or .json, read by deal.II's ParameterHandler) has the sections
// `specimen`, `contact`, `dem`, `continuum`, `program` and `output`. Every parameter is
// declared once (CaseFile.cpp and the *Section.cpp files) with a default, a pattern
// and a help text; `geocomp print-parameters` prints them all. Engines take these
// structs, never the ParameterHandler, so the DEM core builds without deal.II.
//
// Conventions: SI units; stresses and strain rates in the program are tension
// positive; quantities named "pressure" are magnitudes, positive in compression.
#include "common/LoadingProgram.h"

#include <string>
#include <utility>
#include <vector>

namespace geocomp {

/// Bad input: which file, which parameter, what was expected. Exit code 2.
struct CaseError : std::runtime_error {
  CaseError(std::string file, std::string parameter, const std::string &message)
    : std::runtime_error(file + ": parameter '" + parameter + "': " + message),
      file(std::move(file)), parameter(std::move(parameter)) {}
  std::string file, parameter;
};

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
  std::string frictionless_relaxation = "damped"; ///< damped | fire: the frictionless rest after growth
  /// consolidate (rest, friction on, servo to the isotropic pressure) | as given (an imported
  /// packing starts the program exactly as read: text and store sources)
  std::string preparation = "consolidate";
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
  double tangential_damping = 0.0;      ///< [N s/m] c_t given directly; 0 = the ratio
  double tangential_damping_ratio = -1.0; ///< c_t / c_n; -1 = k_t / k_n (S0 eq. (2))
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
};

/// Rigid clumps of spheres (S3, S4), section `clumps`.
struct ClumpParameters {
  std::string shape = "spheres";        ///< spheres | s4-clumps
  double log_mass_mean = -0.117;        ///< S4: mu of ln(m / 1 g)
  double log_mass_sigma = 0.432;        ///< S4: sigma of ln(m / 1 g)
  double mass_min = 0.4e-3;             ///< [kg]
  double mass_max = 2.0e-3;             ///< [kg]
  double max_overlap = 0.5;             ///< overlaps in [0, max_overlap D_min]
  double voxel_fraction = 0.05;         ///< voxel side / D_min (S4: 1/20)
};

struct DemParameters {
  double time_step_safety = 0.2;        ///< dt = safety * critical step
  unsigned int threads = 0;             ///< 0 = OpenMP default
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
};

/// A piecewise-linear function of the equivalent plastic strain kappa.
struct HardeningTable {
  std::vector<std::pair<double, double>> points; ///< (kappa, value), kappa increasing from 0
  double operator()(double kappa) const;
};

/// S1's quasi-static Nikolaevsky model (continuum/model = nikolaevsky), subsection
/// continuum/nikolaevsky (NikolaevskySection.cpp): a row of S1's material table, or
/// custom values. SI; stresses are magnitudes of uniaxial compression.
struct NikolaevskyParameters {
  std::string material = "sandstone";   ///< sandstone | concrete (S1's table) | custom
  // material = custom only, where every one is required:
  double youngs_modulus = 0.0;          ///< E [Pa]
  double poisson_ratio = 0.0;           ///< nu
  double yield_stress = 0.0;            ///< sigma_y [Pa]
  double compressive_strength = 0.0;    ///< sigma_c [Pa], > sigma_y
  double internal_friction = 0.0;       ///< alpha = 3 omega (S1 eq. (1))
  double dilatancy = 0.0;               ///< Lambda (S1 eq. (2))
  double plastic_strain_at_strength = 0.0; ///< axial plastic strain at sigma_c (sets the hardening)
};

struct ContinuumParameters {
  std::string model = "mohr-coulomb";   ///< mohr-coulomb | drucker-prager | nikolaevsky
  std::string dp_matching = "outer";    ///< outer | inner | plane-strain
  double youngs_modulus = 200.0e6;      ///< [Pa]
  double poisson_ratio = 0.25;
  HardeningTable cohesion;              ///< [Pa]
  HardeningTable friction_angle;        ///< [deg]
  HardeningTable dilatancy_angle;       ///< [deg]
  unsigned int cells_per_edge = 4;
  unsigned int degree = 1;
  std::string volumetric_integration = "full"; ///< full | b-bar
  std::string kinematics = "finite strain";    ///< finite strain | small strain
  double imperfection_radius = 0.0;     ///< [m]; 0 = none
  double imperfection_factor = 0.9;     ///< cohesion multiplier inside it
  std::vector<double> imperfection_centre{0.5, 0.5, 0.5}; ///< relative to L0
  std::string regularization = "none"; ///< crack-band | none
  std::string linear_solver = "gmres";  ///< gmres | cg | direct
  std::string preconditioner = "amg";  ///< amg | jacobi
  std::string near_null_space = "rigid-body"; ///< ML's near-null space: rigid-body | translations
  double newton_tolerance = 1e-9;
  unsigned int load_steps_per_sample = 2;
  unsigned int point_substeps = 20;     ///< material-point increments per sample
  double reference_element_size = 0.0;  ///< [m] crack-band reference width; 0 = the cube edge L0
  NikolaevskyParameters nikolaevsky;    ///< for model = nikolaevsky
};

struct OutputParameters {
  std::string directory = "results";
  bool report = true;
  bool fields = true;                   ///< VTU / XDMF field output
};

/// Bounds of one calibrated parameter family ("E", "nu", "cohesion", "friction",
/// "dilatancy"), in case-file units (Pa, degrees).
struct ParameterBounds {
  std::string name;
  double lower = 0.0, upper = 0.0;
};

/// One response quantity fitted by `geocomp calibrate` and its weight: "q" (deviator
/// sqrt(3 J2)), "p" (mean stress) or "eps_v" (volumetric strain).
struct FittedQuantity {
  std::string name;
  double weight = 1.0;
};

/// What `geocomp calibrate` fits (docs/calibration.md).
struct CalibrationParameters {
  std::vector<std::string> targets;     ///< results files (.h5) of the curves to fit, e.g. DEM runs
  std::vector<double> weights;          ///< one per target; empty: all 1
  /// E, nu, cohesion, friction, dilatancy; a table name frees all its knots, name[k] one knot.
  std::vector<std::string> free_parameters{"E", "nu", "cohesion", "friction", "dilatancy"};
  std::vector<ParameterBounds> bounds;  ///< overrides of the default bounds
  std::string starting_values = "closed-form"; ///< closed-form | case
  std::vector<FittedQuantity> quantities{{"q", 1.0}, {"eps_v", 1.0}}; ///< residuals at each sample
  unsigned int max_iterations = 100;
  std::string output_file = "calibrated.prm"; ///< inside the output directory's calibration/ folder
};

struct CaseDescription {
  std::string file;                     ///< as given on the command line
  std::string text;                     ///< whole file, stored in every results file
  std::string title;
  std::vector<std::string> engines;     ///< dem, continuum, material-point
  unsigned long long seed = 1;
  SpecimenParameters specimen;
  ContactParameters contact;
  ClumpParameters clumps;
  DemParameters dem;
  ContinuumParameters continuum;
  LoadingProgram program;
  OutputParameters output;
  CalibrationParameters calibration;
};

/// Reads and validates a case file; throws CaseError (never leaves anything behind).
CaseDescription read_case(const std::string &path);
/// The same for a case file's text; `path` names it in messages and picks .prm/.json.
CaseDescription parse_case(const std::string &text, const std::string &path);
/// Every parameter with default, pattern and help text, as a .prm with comments.
std::string describe_parameters();

} // namespace geocomp
