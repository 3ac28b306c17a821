// @sect3{The DirectShearBox class: S4's direct shear test of clumped rubble}
//
// Why it exists: S4 (Yan & Ji 2009) shears limestone rubble, modelled as clumps of
// overlapping spheres, in a split box and reads the effective friction from the wall
// forces. This class builds that box from bounded walls (PlaneWall rectangles), fills it
// with S4 clumps, prepares the specimen and shears it, recording S4's measurements.
//
// Geometry (z up): lower box $x \in [U, L+U]$, $z \in [0, H]$; upper box $x \in [0, L]$,
// $z \ge H + g$, $y \in [0, B]$, gap $g$ = gap_fraction x mean sphere diameter. Each box
// is a set of thin one-sided plates: four sides, and a rim plate that closes the box
// frame outside its footprint (lower: $z = H$, $x \in [U - F, U]$; upper: $z = H + g$,
// $x \in [L, L + F]$, F = max shear + L/10), standing for the thick frame of a real box.
// The floor is an unbounded plane moving with the lower box. Choice: the upper box is
// fixed (horizontally and vertically; S4's is free vertically, but a free massless box
// rises with the dilating specimen, opens the gap wider than the grains and lets them
// leak). The side-wall friction of a dilating specimen then presses it down beyond F_N;
// that force is recorded (box_vertical_force), and so is the rim's x force. The lid
// (friction mu_lid) is lowered by a velocity servo to the load and is a loaded rigid plate
// during rest and shear (drive_lid): $P = \sigma_n L B$, $F_N = P + W_P + W_B$ (S4 eq. 22)
// with the lid and box weights W_P, W_B given as parameters (0 by default).
// Measurements (S4 eq. 22-24), compression positive in the reports:
//   $F_S = \sum_{upper\ walls} (N_x + S_x)$ over S4's N_wall = 5 walls (the lid and the
//   four upper sides; the x force on the upper rim is recorded apart), $A = B(L - U)$,
//   $\sigma_z = F_N/A$, $\tau_x = F_S/A$, $\mu_b = F_S/F_N$; lid displacement from the
//   start of shearing (up = dilation); inertial number $I = \dot\gamma \bar d \sqrt{\rho/\sigma_n}$
//   with $\dot\gamma = v/(10\bar d)$ (a shear band ten mean diameters thick).
// Preparation (S4): clumps placed at random at `growth_start` of their size, grown in
// `growth_stages` uniform stages to full size (each stage rebuilds the system with the
// members scaled about each clump's centroid, velocities zeroed, then settles under
// gravity with local damping). Growth and a first compaction under the lid to the
// seating stress `seat_stress` run with the friction `prep_friction` on every contact and
// wall: S4's specimens are densified by vibration before loading, and S4's DEM aims at
// their void ratio (0.46); grown with the full friction 0.7 the clumps jam at e ~ 1.0,
// a loose specimen that only contracts. The seating state is the same for every normal
// stress. Then the friction is restored, the servo loads the lid to sigma_n, and the
// specimen is left under the loaded lid without local damping (as in shear) until it is
// at rest: kinetic energy < rest_ratio x elastic energy and the load within the
// tolerance, for 5 x 200 steps. Then the lower box moves at constant speed.
// Rate: S4's 3 mm/min is unaffordable; the speed is chosen so that I < 1e-3 (quasi-static)
// and the modulus may be scaled (modulus_scale) to lengthen the Rayleigh time step.
#pragma once

#include "dem/ClumpGenerator.h"
#include "dem/DemSystem.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace geocomp::dem {

struct DirectShearParameters
{
  // Box (S4: L = B = 10 cm, halves 3.71 cm, gap half a mean diameter).
  double length = 0.10;            ///< L [m]
  double width = 0.10;             ///< B [m]
  double half_height = 0.0371;     ///< H [m]
  double gap_fraction = 0.5;       ///< g / mean sphere diameter
  double void_ratio = 0.46;        ///< sets the number of clumps: V_box = (1 + e) V_solid
  std::size_t n_clumps = 0;        ///< 0: from void_ratio
  ClumpGenerationParameters clumps;
  // Material (S4: E = 58.54 GPa, nu = 0.221).
  double youngs_modulus = 58.54e9;
  double modulus_scale = 1.0;      ///< E used = youngs_modulus * modulus_scale
  double poisson_ratio = 0.221;
  double restitution = 0.5;        ///< sets S4's damping constant A (restitution form)
  double mu_contact = 0.7;
  double mu_side = 0.2;
  double mu_lid = 1.0;
  double time_step_fraction = 0.2; ///< dt = alpha T_Rayleigh (S4: 0.2 dense)
  double gravity = 9.81;
  // Loading.
  double normal_stress = 100e3;    ///< sigma_n [Pa], compression positive
  double lid_weight = 0.0;         ///< W_P [N]
  double box_weight = 0.0;         ///< W_B [N]
  double lid_mass = 1.0;           ///< [kg] inertia of the loaded lid during rest and shear
  double shear_speed = 0.05;       ///< [m/s] of the lower box
  double max_shear = 0.015;        ///< [m]
  std::size_t output_points = 100;
  double servo_factor = 0.01;      ///< lid moves factor*(P_target-P)/K per step (small: the
                                   ///< contact dashpots answer the lid speed at once)
  double servo_max_speed = 0.2;    ///< [m/s]
  double load_tolerance = 0.02;    ///< |P/P_target - 1| to end loading
  double load_max_time = 0.3;      ///< [s] of DEM time for loading
  // Preparation.
  double growth_start = 0.5;       ///< S4: placement at half size
  int growth_stages = 16;
  std::size_t settle_steps = 1500; ///< steps after each growth stage
  double local_damping = 0.5;      ///< during preparation only
  double prep_friction = 0.0;      ///< contact and wall mu during growth and seating (vibration)
  double seat_stress = 10e3;       ///< [Pa] lid stress of the seating compaction (same for all sigma_n)
  double rest_ratio = 1e-4;        ///< at rest before shear: E_kin < rest_ratio * E_elastic
  double rest_max_time = 0.05;     ///< [s] of DEM time for coming to rest under sigma_n
  std::uint64_t seed = 1;
};

/// One output row (compression positive).
struct ShearRecord
{
  double shear = 0.0;         ///< U [m]
  double lid_rise = 0.0;      ///< [m] lid displacement since the start of shear (+ dilation)
  double normal_force = 0.0;  ///< F_N [N]
  double shear_force = 0.0;   ///< F_S [N]
  double area = 0.0;          ///< B (L - U) [m^2]
  double sigma_z = 0.0;       ///< [Pa]
  double tau_x = 0.0;         ///< [Pa]
  double mu_b = 0.0;
  double inertial_number = 0.0;
  double time = 0.0;          ///< [s] DEM time
  double rim_force = 0.0;     ///< [N] x force on the upper rim plate (not in F_S, S4 eq. 22)
  double box_vertical_force = 0.0;  ///< [N] particles' upward (friction) force on the four upper
                                    ///< sides: the fixed box presses the upper specimen down by it
};

struct ShearSummary
{
  double peak_mu_b = 0.0;
  double shear_at_peak = 0.0;
  double max_contraction = 0.0;  ///< [m] max downward lid displacement (>= 0)
  double final_dilation = 0.0;   ///< [m] final lid rise (< 0: net contraction)
  double inertial_number = 0.0;
  std::size_t n_clumps = 0, n_spheres = 0;
  double time_step = 0.0;
  double gap = 0.0;
  double load_error = 0.0;       ///< |P/P_target - 1| at the end of loading
  double void_ratio_seated = 0.0;  ///< e after the seating compaction (column floor..lid)
  double void_ratio = 0.0;         ///< e at the start of shear
  double rest_kinetic_ratio = 0.0; ///< E_kin / E_elastic at the start of shear
  double rest_lid_speed = 0.0;     ///< [m/s] |lid speed| at the start of shear
  double rim_share_at_peak = 0.0;  ///< upper-rim x force / F_S at the peak of mu_b
  double prepare_seconds = 0.0, shear_seconds = 0.0;
  std::uint64_t steps = 0;
};

/// S4 eq. (23): corrected area B (L - U).
inline double corrected_area(double length, double width, double shear) { return width * (length - shear); }

class DirectShearBox
{
public:
  using Progress = std::function<void(const std::string& phase, double fraction)>;

  explicit DirectShearBox(const DirectShearParameters& p);

  /// Generation, placement, growth and normal loading (S4's preparation).
  void prepare(const Progress& progress = {});
  /// Shears to max_shear; returns the curve (output_points + 1 rows).
  std::vector<ShearRecord> shear(const Progress& progress = {});
  /// The measurements now (S4 eq. 22-24) at shear displacement U.
  ShearRecord measure(double U) const;
  ShearSummary summary(const std::vector<ShearRecord>& curve) const;

  const DemSystem& system() const { return *sys_; }
  DemSystem& system() { return *sys_; }
  /// Wall indices: the walls of the upper box (lid first) and of the lower box.
  const std::vector<std::size_t>& upper_walls() const { return upper_; }
  const std::vector<std::size_t>& lower_walls() const { return lower_; }
  std::size_t lid() const { return upper_.front(); }
  double gap() const { return gap_; }
  double target_load() const { return p_.normal_stress * p_.length * p_.width; }
  /// One servo update of the lid velocity towards the target load.
  void servo_lid();
  /// Void ratio of the column floor..lid: e = L B z_lid / V_solid - 1 (gap included).
  double void_ratio() const;
  /// One update of the vertical speed of the loaded lid (rigid plate under the particles'
  /// force and the load P; used for rest and shear).
  void drive_lid();
  /// Runs `steps` steps with the lid servo on.
  void run_servo(std::size_t steps);

private:
  void build(const std::vector<std::vector<ClumpMember>>& clumps, double lid_height);
  std::vector<std::vector<ClumpMember>> clump_members() const;
  void set_friction(bool preparation);
  /// Servo to `load` [N] until it holds within load_tolerance for 5 chunks (or max_time).
  void load_lid(double load, double max_time, const Progress& progress);

  DirectShearParameters p_;
  std::unique_ptr<DemSystem> sys_;
  std::vector<std::size_t> upper_, lower_;
  double gap_ = 0.0, d_mean_ = 0.0, dt_ = 0.0, r_min_ = 0.0;
  double lid_start_ = 0.0;
  double servo_target_ = 0.0;  ///< [N] the servo's current target
  double solid_volume_ = 0.0;  ///< [m^3] sum of clump masses / density
  ShearSummary info_;
};

}  // namespace geocomp::dem
