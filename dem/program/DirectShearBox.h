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
// The floor is an unbounded plane moving with the lower box.
// Upper box (S4: fixed horizontally, free vertically): its four sides, its rim and three
// skirts form one rigid body moving only along z, released at the start of the rest
// under sigma_n (the gap screws backed off), with
//   $m_B \ddot z_B = F_{B,z} - W_B + R$,  $\dot x_B = \dot y_B = 0$,
//   $F_{B,z} = \sum_{box\ plates} F_z$ (the particles' force), W_B the box weight of S4 eq. (22),
//   R the reaction of the seat (R >= 0) or of the top stop (R <= 0),
// integrated each DEM step like the loaded lid (drive_box). The box rests on spacers at the
// set gap (it cannot sink below its seat: a lower stop) and a top stop limits its rise to
// box_max_rise (stop reactions recorded). Off the stops the box is carried by the specimen:
// on average $F_{B,z} = W_B$, so the side friction on the specimen is bounded by the box
// weight and the specimen carries $F_N = P + W_P + W_B$ (S4 eq. 22). A free box rises with
// a dilating specimen and opens the gap by the dilation (a grain or more); the plates are
// one-sided (a grain that passes the gap ends behind a plate and explodes), so the gap is
// closed by skirts, plates a quarter of the smallest radius behind the box plates (no
// double contact): the upper box's x-, y- and y+ skirts hang from the bottom of its sides to
// box_max_rise below the lower box's top (the y skirts also along the rim), and the lower
// box carries an x+ skirt up to the highest rim position. upper_box_free = false keeps the box
// fixed (the former model; its side friction then exceeds W_B and is recorded).
// The lid (friction mu_lid) is lowered by a velocity servo to the load and is a loaded rigid
// plate during rest and shear (drive_lid) under $P = \sigma_n L B$ plus its own weight (a
// parameter, 0 by default). $F_N = F_{lid} + W_P + W_B$ (S4 eq. 22): F_lid the particles' force
// on the lid, W_P the weight of the grains above the middle of the gap (S4: the weight of the
// granular medium of the upper box), W_B the box weight.
// Measurements (S4 eq. 22-24), compression positive in the reports:
//   $F_S = \sum_{upper\ walls} (N_x + S_x)$ over S4's N_wall = 5 walls (the lid and the
//   four upper sides; the x force on the upper rim and skirts is recorded apart), $A = B(L - U)$,
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
  double lid_weight = 0.0;         ///< [N] the lid's own weight, a dead load added to P
  double box_weight = 9.81;        ///< W_B [N], S4 eq. (22)
  bool upper_box_free = true;      ///< S4: free vertically (false: fixed, the former model)
  double box_mass = 1.0;           ///< m_B [kg] of the free upper box (sides, rim, skirts)
  double box_max_rise = 0.01;      ///< [m] top stop of the free box above its seat; skirt reach
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
  double frame_force = 0.0;   ///< [N] x force on the upper rim and skirts (not in F_S, S4 eq. 22)
  double box_vertical_force = 0.0;  ///< [N] F_{B,z}: particles' upward force on the upper box
                                    ///< (sides, rim, skirts) = the box's load on the specimen
  double box_rise = 0.0;      ///< [m] upper box above its seat
  double box_stop_force = 0.0;  ///< [N] stop reaction on the box (> 0 seat pushes up, < 0 top stop)
  double grain_weight = 0.0;  ///< [N] W_P of S4 eq. (22): weight of the clumps above mid-gap
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
  double frame_share_at_peak = 0.0;  ///< upper rim and skirts' x force / F_S at the peak of mu_b
  // The free upper box over the shear (time averages over every step).
  double box_force_mean = 0.0;     ///< [N] mean F_{B,z} (= W_B when carried by the specimen)
  double box_stop_mean = 0.0;      ///< [N] mean stop reaction (> 0 seat, < 0 top stop)
  double box_force_max = 0.0;      ///< [N] max F_{B,z} over the output rows
  double box_rise_max = 0.0;       ///< [m]
  double box_rise_final = 0.0;     ///< [m]
  double box_seated_share = 0.0;   ///< fraction of the shear steps on the seat
  double box_top_share = 0.0;      ///< fraction of the shear steps at the top stop
  std::size_t escaped = 0;         ///< spheres outside the two box halves at the end
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
  /// One update of the vertical speed of the free upper box (rigid body on z under the
  /// particles' force, its weight and the seat and top stops); no-op when it is fixed.
  void drive_box();
  /// The walls of the upper box body (sides, rim, skirts: upper_walls() without the lid).
  std::vector<std::size_t> box_walls() const { return {upper_.begin() + 1, upper_.end()}; }
  /// [m] rise of the upper box above its seat.
  double box_rise() const;
  /// W_P of S4 eq. (22) [N]: weight of the clumps whose centre is above the middle of the gap.
  double grain_weight() const;
  /// Spheres whose centre is outside the two box halves (x in [min(0, U), L + max(0, U)],
  /// y in [0, B], z >= 0): grains lost through the gap.
  std::size_t escaped_spheres() const;
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
  double box_seat_z_ = 0.0;     ///< [m] z of the upper x- side's centre at the seat
  bool box_released_ = false;   ///< the free box moves (after loading)
  double box_stop_ = 0.0;       ///< [N] the last step's stop reaction
  // Shear statistics of the box (sums over steps).
  double box_force_sum_ = 0.0, box_stop_sum_ = 0.0;
  std::uint64_t box_steps_ = 0, box_seated_steps_ = 0, box_top_steps_ = 0;
  double servo_target_ = 0.0;  ///< [N] the servo's current target
  double solid_volume_ = 0.0;  ///< [m^3] sum of clump masses / density
  ShearSummary info_;
};

}  // namespace geocomp::dem
