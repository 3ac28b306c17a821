#pragma once
// The loading program: the one description of a test that both engines run.
//
// A program is an ordered list of stages. In each stage every box axis (x, y, z) is
// driven either kinematically (an engineering strain rate, 1/s) or by a target stress
// (Pa) that the engine holds (servo walls in DEM, tractions in the continuum), or the
// whole box follows S0's isochoric program, eq. (3):
//     v_x = v0,  v_y = lambda v0,  L_z = V0 / (L_x L_y)
// which keeps the box volume constant to round-off (the digest explains why the
// position, not the printed mean speed, is imposed). Conventions: SI, tension positive,
// strain engineering and relative to the box at the start of the program.
//
// A stage ends when any of its stop conditions holds (checked at every sample). Unloading
// branches (S0 Fig. 2: A-F ... E-L) are requested per stage: at each trigger the engine
// state is saved, every kinematic rate is reversed until tau_max returns to the level at
// the start of the stage (or a given level), the branch is recorded, and the main path
// resumes from the saved state. A stage may also locate the elastic limit (S0: the strain
// at which the residual strain after unloading reaches 1 %): after its main path, extra
// branches bisect the bracket of neighbouring branches whose residuals straddle 1 %
// (ProgramRunner, docs/metrics.md).
#include "common/Tensor.h"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp {

/// Error in a loading program; `where` names the parameter (e.g. "program/stage 2/x").
struct ProgramError : std::runtime_error {
  ProgramError(std::string where, const std::string &what)
    : std::runtime_error(what), where(std::move(where)) {}
  std::string where;
};

/// How one axis is driven in a stage.
struct AxisDrive {
  enum class Kind { StrainRate, Stress };
  Kind kind = Kind::StrainRate;
  double value = 0.0; ///< strain rate [1/s] or stress [Pa], tension positive
  bool is_stress() const { return kind == Kind::Stress; }
  static AxisDrive rate(double r) { return {Kind::StrainRate, r}; }
  static AxisDrive stress(double s) { return {Kind::Stress, s}; }
};

/// S0's elastic limit: the residual strain after unloading (gamma_max) stays below 1 %.
inline constexpr double s0_residual_threshold = 0.01;

/// Quantities a stop condition or a branch trigger can test.
enum class Quantity {
  Time,        ///< program time [s]
  StageTime,   ///< time since the stage began [s]
  EpsXX, EpsYY, EpsZZ,  ///< engineering strains
  SigXX, SigYY, SigZZ,  ///< stresses [Pa]
  GammaMax,    ///< eps_max - eps_min
  TauMax,      ///< (s_max - s_min)/2 [Pa]
  VolumetricStrain, ///< det(I+eps)-1
  MeanStress,  ///< tr(sigma)/3 [Pa]
  StressRatio, ///< s_min/s_max of the principal stresses (compressive ratio sigma_1/sigma_3 >= 1)
  PeakDrop,    ///< (tau_peak - tau)/tau_peak since the stage began, 0 before any drop
  ServoError   ///< largest |sigma - target|/|target| over the stress-driven axes
};

/// `quantity >= value` or `quantity <= value`.
struct Condition {
  Quantity quantity = Quantity::Time;
  bool at_least = true;
  double value = 0.0;
  std::string text; ///< as written in the case file
};

/// Parses "gamma_max >= 0.15", "eps_zz <= -0.1", "time >= 2"...; throws ProgramError.
Condition parse_condition(const std::string &text, const std::string &where);
/// Names accepted by parse_condition, for help texts.
std::string condition_quantity_names();

/// Where an unloading branch starts.
struct BranchTrigger {
  enum class Kind { WhenCondition, AtPeak };
  Kind kind = Kind::WhenCondition;
  Condition condition; ///< for WhenCondition (e.g. "gamma_max >= 0.02", "peak_drop >= 0.1")
  std::string text;
};
/// Parses "peak" or a condition.
BranchTrigger parse_trigger(const std::string &text, const std::string &where);

struct Stage {
  std::string name;
  std::array<AxisDrive, 3> axes{};      ///< used unless isochoric
  bool isochoric = false;               ///< S0 eq. (3)
  double lambda = 0.0;                  ///< S0 eq. (3), in [-1, 1]
  double isochoric_rate = 0.0;          ///< 2 v0 / L0 [1/s] > 0: x shortens at this rate
  std::vector<Condition> stop_any;      ///< the stage ends when any holds
  double max_duration = 0.0;            ///< safety limit [s] > 0: ends the stage, flagged
  std::vector<BranchTrigger> unload_at; ///< unloading branches from this stage
  bool unload_to_start = true;          ///< unload until tau_max <= value at stage start
  double unload_to_tau = 0.0;           ///< otherwise until tau_max <= this [Pa]
  double peak_tolerance = 0.01;         ///< relative drop that confirms a peak
  /// After the main path: bisect with unloading branches between the neighbouring branches
  /// whose residuals straddle s0_residual_threshold, until the bracket of their start
  /// strains (gamma_max, logarithmic, since the stage start) is narrower than the tolerance.
  bool locate_elastic_limit = false;
  double elastic_limit_tolerance = 0.001; ///< bracket width [strain] > 0

  bool kinematic(int axis) const { return isochoric || !axes[axis].is_stress(); }
  bool has_stress_axis() const;
};

struct LoadingProgram {
  std::vector<Stage> stages;
  double sample_interval = 0.0; ///< [s] between recorded samples
  /// Throws ProgramError naming "program/..." for anything inconsistent.
  void validate() const;
};

/// The drive of one stage, anchored in time and strain: what an engine follows.
/// Kinematic axes get a target strain at any time; stress axes a target stress.
struct StageControl {
  const Stage *stage = nullptr;
  double t0 = 0.0;          ///< program time at which this control starts
  Vector3 eps0 = Vector3::Zero(); ///< diagonal strain at t0
  double direction = 1.0;   ///< +1 loading, -1 unloading (every rate reversed)

  bool kinematic(int axis) const { return stage->kinematic(axis); }
  double target_stress(int axis) const { return stage->axes[axis].value; }
  /// Target engineering strain of a kinematic axis at program time t.
  double strain(int axis, double t) const;
  /// Its time derivative.
  double strain_rate(int axis, double t) const;
};

} // namespace geocomp
