// @sect3{The stress servo of a wall pair}
//
// Why it exists: a stress-controlled axis of the true-triaxial box (S0 program 2's lateral
// pressure, the isotropic consolidation, any `x = stress ...` of a program) has no wall
// force law of its own: each step the two walls of the axis are given the outward speed
// that brings the wall stress to its goal. A proportional law alone (Yade's
// TriaxialStressController, DEM-NOTES section 7) leaves an error that grows with the speed
// the walls must keep up (the specimen dilates under the axial load, so the lateral walls
// must follow it): S0's 2 MPa program ended 11 % above its lateral goal. This law adds an
// integral part that learns that speed, so the error is driven to zero on average.
//
// The law, per stress axis (both walls move symmetrically, outward speed v):
// $$ e = \sigma^{goal} - \sigma,\qquad
//    G = \frac{A}{K\,\Delta t},\qquad K = \bar k_w\Bigl(1 + \frac{c_n}{k_n\Delta t}\Bigr), $$
// $$ v_I \leftarrow v_I + g_I\,G\,e,\qquad v = \mathrm{clamp}\bigl(g_P\,G\,e + v_I,\ -v_{max},\ v_{max}\bigr). $$
// $\sigma$ is the axis' wall stress after the last step (tension positive, so e > 0 means
// the specimen is more compressed than the goal and the walls move out), A the current
// face area, $\bar k_w$ the mean of the two walls' contact stiffnesses (the sum of k_n over
// their touching contacts, as Yade's stiffness-based gain) and $c_n/k_n$ the dashpot time of
// a mean wall contact: within one step the contacts answer a wall speed with
// $k\delta + c v$, so the stiffness seen in one step is K. $G e$ is the speed that would
// cancel the error in one step if the specimen were the wall contacts alone; the
// proportional gain $g_P$ takes a fraction of it per step (0.5: the error halves per step
// on the contacts, and the slower response of the packing behind them keeps the loop far
// from its stability limit at 1). $v_I$ is the integral part in velocity units: the wall
// speed the axis has needed so far, kept by the state (saved, restored and checkpointed
// with the engine) and cleared when the drive changes (a new stage, an unloading branch).
// $g_I$ is its gain per step: the integral time is $T_I = (g_P/g_I)\,\Delta t$.
// While the speed is clamped the integral does not grow further (anti-windup). Without
// wall contacts (K = 0) the walls move at $v_{max}$ towards the goal and $v_I$ is cleared.
// The cap is $v_{max} = \max(v_{cap},\ r\,v_{kin})$: the case's cap, raised to r (4) times the
// speed of the fastest kinematic wall, since the walls of a stress axis must keep up with a
// specimen that widens as fast as it is shortened (S0's 2 MPa program needs 0.09 m/s where
// the axial walls move at 0.078 m/s; a 0.05 m/s cap held the lateral stress 11 % high).
// The gains are numerics of the control loop, not physics: they change how closely the
// walls follow the goal, never the specimen's law, rate or damping.
#pragma once

namespace geocomp::dem {

struct ServoParameters
{
  double proportional_gain = 0.5; ///< g_P: fraction of the one-step stiffness-based correction
  double integral_gain = 0.1;     ///< g_I: per-step gain of the integral part (0: proportional only)
  double max_velocity = 0.05;     ///< [m/s] cap on a wall's speed, at least
  /// The cap is at least this many times the fastest kinematic wall's speed: a specimen
  /// under axial load widens about as fast as it is shortened, dilating faster, and a cap
  /// below that speed leaves the walls behind their goal for good.
  double kinematic_speed_ratio = 4.0;
  /// Throws std::invalid_argument for a non-positive g_P or v_max, a negative g_I or ratio.
  void validate() const;
  /// The cap v_max = max(max_velocity, kinematic_speed_ratio x kinematic_speed).
  double cap(double kinematic_speed) const;
};

/// What one axis' servo reads each step.
struct ServoInput
{
  double goal = 0.0;      ///< [Pa] target stress, tension positive
  double stress = 0.0;    ///< [Pa] the axis' wall stress now
  double area = 0.0;      ///< [m^2] current face area
  double stiffness = 0.0; ///< [N/m] K: the walls' mean contact stiffness with the dashpot term
  double dt = 0.0;        ///< [s] the step about to be taken
  double kinematic_speed = 0.0; ///< [m/s] the fastest kinematic wall's speed (0: none)
};

/// The state and law of one stress-controlled axis.
class AxisServo
{
public:
  /// Outward speed of each wall of the axis for the coming step; updates the integral.
  double velocity(const ServoParameters &p, const ServoInput &in);
  /// Forgets the learned speed (a new drive).
  void reset() { integral_velocity_ = 0.0; }
  double integral_velocity() const { return integral_velocity_; }
  void set_integral_velocity(double v) { integral_velocity_ = v; }

private:
  double integral_velocity_ = 0.0; ///< [m/s] v_I
};

} // namespace geocomp::dem
