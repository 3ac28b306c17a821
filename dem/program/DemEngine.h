// @sect3{The DemEngine class: a DEM specimen in a six-wall box, driven by the loading program}
//
// Why it exists: the DEM side of every S0 test. The ProgramRunner owns the program
// (stages, stop conditions, unloading branches); this engine follows one StageControl at a
// time the way a true-triaxial apparatus does, measures itself like a laboratory would,
// and saves/restores its whole state for branches and checkpoints.
//
// Walls 0..5 of the system are the box faces x-, x+, y-, y+, z-, z+ (DemSystem::add_box).
// The box at construction is the reference: $L_{0,a}$, strain $\varepsilon_a = (L_a - L_{0,a})/L_{0,a}$
// (engineering, tension positive, DEM-NOTES section 6), program time 0.
//  - Kinematic axis a: before each step both walls get the speed that brings the edge to
//    $L_{0,a}(1+\varepsilon_a(t+\Delta t))$, symmetric about the box centre, and after the step the
//    walls are placed exactly there. The isochoric program (S0 eq. (3)) comes out of
//    StageControl::strain as $L_z = V_0/(L_x L_y)$, so the box volume is constant to round-off.
//  - Stress axis a: a servo moves both walls symmetrically (AxisServo, ServoControl.h):
//    a proportional part after Yade's TriaxialStressController (DEM-NOTES section 7), the
//    stiffness-based one-step correction $(\sigma^{goal}_{aa} - \sigma_{aa}) A_a / K$ times a gain,
//    with $K = \bar k_w (1 + c_n/(k_n\Delta t))$ from the walls' contact stiffnesses and the
//    dashpot time of a mean wall contact, plus an integral part that learns the speed the
//    walls must keep up, under a velocity cap.
// Measurements (measure()): the stress from the wall forces,
// $\sigma_{ba} = -(F^{hi}_b - F^{lo}_b)/(2A_a)$ (symmetrised; the diagonal is S0's wall stress),
// its time-weighted mean over every step since the previous measure() (the interval mean
// of the Response), and
// extras: the Love-Weber stress over all contacts, particle-wall ones included,
// $\sigma = -\frac1V\sum_c \ell_c\otimes f_c$ (DEM-NOTES section 6, V the box volume), the
// coordination number $Z = 2C/N$, the mechanical one $Z_m = (2C - N_1)/(N - N_0 - N_1)$ (Thornton
// 2000), the fabric $\Phi = \frac1C\sum n\otimes n$ and its anisotropy $\sqrt{\tfrac32\,\mathrm{dev}\Phi:\mathrm{dev}\Phi}$,
// the porosity, the kinetic energy, the inertial number $I = \dot\gamma\,\bar d\sqrt{\rho/p}$ with
// $\dot\gamma = \max_a\dot\varepsilon_a - \min_a\dot\varepsilon_a$ from the wall speeds' means over the
// interval, and the
// unbalanced-force ratio (mean |net force| / mean |contact force|, Yade).
//
// save()/restore() copy the whole DemSystem (contact histories, lists and counters), so a
// branch restored from a saved state continues bit for bit. write_checkpoint() and
// read_checkpoint() do the same through a file (DemSystem::write_state), atomically. Each
// step checks the interrupt flag (SIGINT/SIGTERM with install_interrupt_handlers()): on a
// request the engine writes its checkpoint and throws Interrupted.
#pragma once

#include "common/LoadingEngine.h"
#include "dem/case/DemParameters.h"
#include "dem/DemSystem.h"
#include "dem/program/ServoControl.h"
#include "dem/specimen/Packing.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace geocomp::dem {

/// The case file's contact law as the core's ContactModel: linear (S0 eq. (1)-(2): k_n given
/// or S0's secant Hertz stiffness at V_c; c_n given, per unit effective mass (LIGGGHTS
/// gamma_n) or from the restitution; k_t given or a ratio of k_n; c_t given, a ratio of c_n,
/// or by default c_n times k_t/k_n) or hertz-mindlin (S4, damping from the restitution).
ContactModel make_contact_model(const ContactParameters &c);
/// The case's law on a system: make_contact_model(c), wall bonding and the walls that bond.
void set_contact_law(DemSystem &system, const ContactParameters &c);

/// A DemSystem holding the packing in its box (six walls with mu_p, spheres with the
/// packing's density and its velocities when it has them), the contact law, mu_s, the skin
/// (DemParameters::skin times the
/// mean diameter), the threads, local damping and dt = time_step_safety x critical step.
DemSystem make_system(const Packing &packing, const ContactParameters &c, const DemParameters &d);

/// Where a run stops being a test of the specimen (issue 30). Past them the engine throws
/// GuardError; the ProgramRunner turns that into ProgramFailed with the samples so far,
/// and `geocomp` writes them with /meta/status and exits 1.
///  - a box edge below `min_edge_diameters` times the largest particle diameter (a program
///    that squeezes the box shut or turns it inside out), checked every step;
///  - a wall stress that is not finite, or whose largest normal component exceeds
///    `max_stress_ratio` times the reference stress (the largest |sigma_aa| at the engine's
///    start and of every stress goal since; a stress-free start under kinematic drives
///    alone has none, and only the finiteness is checked), every step;
///  - a particle centre outside the box, at every sample.
struct GuardLimits
{
  double min_edge_diameters = 3.0;
  double max_stress_ratio = 1e3;
};

/// A guard of GuardLimits has stopped the run; the message says which and where.
struct GuardError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct DemEngineParameters
{
  ServoParameters servo;              ///< the stress servo of the walls (ServoControl.h)
  GuardLimits guards;                 ///< where a run is stopped as failed
  std::filesystem::path checkpoint_file; ///< where checkpoints go (empty: none, not even on interrupt)
  std::uint64_t checkpoint_every_steps = 0; ///< periodic checkpoint every so many DEM steps (0: off)
  double checkpoint_every_seconds = 0.0;    ///< periodic checkpoint every so much wall time (0: off)
  bool check_interrupts = true;       ///< honour SIGINT/SIGTERM (install_interrupt_handlers())

  /// Servo and checkpoint values of the case file (checkpoint file left empty).
  static DemEngineParameters from_case(const DemParameters &d);
};

/// Thrown by DemEngine::advance_to after SIGINT/SIGTERM, once the checkpoint is written.
struct Interrupted : std::runtime_error
{
  Interrupted(int signal, std::filesystem::path checkpoint, double time);
  int signal;                        ///< SIGINT or SIGTERM (or 0 for request_interrupt())
  std::filesystem::path checkpoint;  ///< empty if no checkpoint file was configured
  double time;                       ///< program time of the checkpoint
};

/// SIGINT and SIGTERM set a flag instead of killing the process (async-signal-safe).
void install_interrupt_handlers();
/// SIGINT and SIGTERM back to their default action (terminate): what follows a DEM run in the
/// same process (a fit, a continuum run) is stopped by them as usual.
void restore_default_interrupt_handlers();
/// The signal that requested the stop (0: none).
int interrupt_requested();
/// Raises the flag as a signal would (tests, GUIs).
void request_interrupt(int signal = 0);
void clear_interrupt();

/// Snapshot of the particles and contacts, particles in id order (ids 0..N-1).
/// `ids` + `positions` are what compare::ParticleSnapshot holds (local strain, D2min).
struct ParticleFields
{
  double time = 0.0;   ///< program time
  double label = 0.0;  ///< any monotone measure, e.g. gamma_max of the box
  Vector3 box_min = Vector3::Zero(), box_max = Vector3::Zero(); ///< wall planes
  Vector3 box_size0 = Vector3::Zero();                        ///< L0 of the program
  std::vector<std::int64_t> ids;
  std::vector<Vector3> positions;
  std::vector<Vector3> displacements; ///< since the start of the program
  std::vector<Vector3> velocities;
  std::vector<Vector3> angular_velocities;
  std::vector<double> radii;
  // Touching particle-particle contacts (i < j, ids) and particle-wall contacts.
  std::vector<std::array<std::int64_t, 2>> contact_pairs;
  std::vector<Vector3> contact_points, contact_forces; ///< force on j
  std::vector<double> contact_normal_forces, contact_overlaps;
  std::vector<std::array<std::int64_t, 2>> wall_contacts; ///< (wall 0..5, particle id)
  std::vector<Vector3> wall_contact_points, wall_contact_forces; ///< force on the particle
};

class DemEngine : public LoadingEngine
{
public:
  /// Column indices of the extras (extra_columns() order).
  enum Extra : int {
    kLoveWeberXX, kLoveWeberYY, kLoveWeberZZ, kLoveWeberXY, kLoveWeberYZ, kLoveWeberXZ, kLoveWeberMean,
    kCoordination, kMechanicalCoordination, kWallContacts, kFabricXX, kFabricYY, kFabricZZ,
    kFabricAnisotropy, kPorosity, kKineticEnergy, kInertialNumber, kUnbalancedForceRatio, kSteps,
    kServoDeviation, kServoReversals, kWallRateXX, kWallRateYY, kWallRateZZ,
    kIntactBonds, kBrokenBonds, kExtraCount
  };

  /// `system` must hold the six walls of add_box() as walls 0..5; its box, time and
  /// positions at construction are the program's reference state.
  DemEngine(DemSystem system, const DemEngineParameters &parameters);
  /// An engine continuing from a checkpoint file (the parameters must be the run's).
  static std::unique_ptr<DemEngine> from_checkpoint(const std::filesystem::path &path,
                                                    const DemEngineParameters &parameters);

  std::string name() const override { return "dem"; }
  std::vector<ExtraColumn> extra_columns() const override;
  void begin_control(const StageControl &control) override;
  void advance_to(double t_end) override;
  /// The sample now; its stress_mean is the mean wall stress over the steps since the
  /// previous measure() (the instantaneous one if none), which starts the next interval.
  ResponseSample measure() override;
  bool gives_interval_means() const override { return true; }
  std::unique_ptr<EngineState> save() const override;
  void restore(const EngineState &state) override;
  bool can_write_states() const override { return true; }
  void write_state(std::ostream &out, const EngineState &state) const override;
  std::unique_ptr<EngineState> read_state(std::istream &in) const override;

  /// Full state (system, reference box, positions at the start, current drive) to a
  /// file, written under a temporary name and renamed.
  void write_checkpoint(const std::filesystem::path &path) const;
  /// Replaces the whole state by the checkpoint's.
  void read_checkpoint(const std::filesystem::path &path);

  const DemSystem &system() const { return system_; }
  /// OpenMP threads of the step (0: the OpenMP default); the results do not depend on it.
  void set_num_threads(int n) { system_.set_num_threads(n); }
  const DemEngineParameters &parameters() const { return prm_; }
  /// Program time: DEM time less the time at construction.
  double time() const { return system_.time() - s_.t_origin; }
  Vector3 box_lengths() const;
  const Vector3 &reference_lengths() const { return s_.L0; }
  /// Stress from the wall forces (tension positive, current face areas).
  Tensor3 wall_stress() const;
  /// Love-Weber stress over all touching contacts incl. particle-wall (tension positive).
  Tensor3 love_weber_stress() const;
  /// Particles and contacts now (label: e.g. gamma_max).
  ParticleFields snapshot(double label = 0.0) const;

private:
  struct Saved;
  /// Everything of the engine's state except the system and the parameters.
  struct State
  {
    Vector3 L0 = Vector3::Ones();
    double t_origin = 0.0;
    std::vector<Vec3> x_start;          ///< by id, at construction
    double density = 0.0, mean_diameter = 0.0, solid_volume = 0.0;
    double dashpot_time = 0.0;          ///< c_n/k_n of a mean wall contact (servo)
    double max_diameter = 0.0;          ///< [m] of the largest particle (guards)
    double reference_stress = 0.0;      ///< [Pa] the stress guard's reference (GuardLimits)
    bool has_control = false;
    Stage stage;                        ///< the drive of the control (copied)
    double control_t0 = 0.0, control_direction = 1.0;
    Vector3 control_eps0 = Vector3::Zero();
    Vector3 rate = Vector3::Zero();     ///< engineering strain rates of the last step
    std::array<AxisServo, 3> servo{};   ///< the stress servo of each axis
    // The sampling interval under way (since the last measure()):
    Tensor3 stress_sum = Tensor3::Zero(); ///< sum of wall stress x dt over its steps
    Vector3 rate_sum = Vector3::Zero();   ///< sum of the axes' strain rates x dt (inertial number)
    double window_time = 0.0;           ///< [s] their time
    double max_servo_deviation = 0.0;   ///< largest |sigma_aa - goal| / |goal| of a stress axis at a step
    std::uint64_t servo_reversals = 0;  ///< steps at which a servo wall's speed changed sign
  };

  DemEngine() = default;
  static void write_state(std::ostream &out, const State &s, const DemSystem &system);
  static void read_state(std::istream &in, State &s, DemSystem &system);
  void step();
  /// Outward speed of each wall of stress axis a for a step of dt (the servo), the
  /// kinematic walls moving at up to `kinematic_speed`.
  double servo_velocity(int a, const StageControl &c, double dt, double kinematic_speed);
  /// Adds the wall stress after a step of dt to the interval's sums; checks the stress guards.
  void accumulate(const StageControl &c, double dt);
  /// The box-edge guard (every step) and the particles-in-the-box guard (at samples).
  void check_box() const;
  void check_particles_inside() const;
  StageControl control() const;
  void maybe_checkpoint();

  DemSystem system_;
  DemEngineParameters prm_;
  State s_;
  double last_checkpoint_wall_ = 0.0;
};

/// Holds all three axes at -pressure with the servo until every wall stress is within
/// `tolerance` (relative) of it and the unbalanced-force ratio is below `unbalanced`,
/// checked every `check_interval` of program time, or until `max_time` has passed.
/// Returns whether it converged.
struct HoldResult
{
  bool converged = false;
  double stress_error = 0.0;
  double unbalanced = 0.0;
  double time = 0.0; ///< program time spent
};
HoldResult hold_isotropic(DemEngine &engine, double pressure, double tolerance, double unbalanced, double max_time,
                          double check_interval);

} // namespace geocomp::dem
