// @sect3{The PeriodicCell class: a DEM representative volume element driven by L}
//
// Why it exists: a DEM assembly without walls, repeated through space, whose deformation
// is imposed homogeneously by a velocity gradient L (or, component by component, by a
// target stress: MixedControl.h). It is the representative volume element the FEM x DEM
// coupling will put at each quadrature point (issue 35); Yade's periodic Cell and
// PeriTriaxController are the behavioural reference.
//
// Kinematics (Yade's periodic cell; the standard RVE split). The lab velocity of a sphere
// is $v = u + Lx$: the affine field of the cell plus a fluctuation u, which is what the
// particles store and what the contact forces change. One velocity-Verlet step
// (dem/Integrator.h, with its Cundall local damping acting on u):
// $$ u \mathrel{+}= \tfrac{\Delta t}{2}F/m,\quad \omega \mathrel{+}= \tfrac{\Delta t}{2}T/I \qquad\text{(kick)} $$
// $$ A = e^{L\Delta t},\quad x \leftarrow A x + \Delta t\,u,\quad H \leftarrow A H \qquad\text{(affine drift)} $$
// then the contact forces (PeriodicContactPass.h) and the closing half kick. The affine
// part uses the same A as the cell, so without contacts $u$ stays zero and every sphere
// keeps its reduced coordinates $H^{-1}x$ exactly as H follows $e^{Lt}H_0$. The affine field
// carries no inertia (the quasi-static RVE: $\dot u = F/m$, the $\dot L x$ and $L\dot x$ terms
// of the lab acceleration are dropped; they are $O(\dot\varepsilon^2 x)$ against
// contact accelerations). Spins split the same way: the lab spin is $\omega + w$, w the
// axial vector of skw L (the affine field's rotation; PeriodicContactPass.h), and the
// particles store the fluctuation $\omega$. The positions are wrapped into the cell at
// each neighbour build (u does not jump; the lab velocity's jump $LHn$ is the shift term
// the contact kinematics carry).
//
// After each step the cell holds the Love-Weber stress (CellStress.h) and, at the start
// of the next, L is taken from the MixedControl (every component prescribed unless some
// follow a stress). Particles keep their storage order (ids = indices), one thread: the
// same bits on every run; an FE mesh's RVEs are the parallel grain.
#pragma once

#include "dem/ContactLaw.h"
#include "dem/Integrator.h"
#include "dem/ParticleStore.h"
#include "dem/periodic/CellMatrix.h"
#include "dem/periodic/CellStress.h"
#include "dem/periodic/MixedControl.h"
#include "dem/periodic/PeriodicNeighbours.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace geocomp::dem {

class PeriodicCell
{
public:
  struct Parameters
  {
    double time_step = 0.0;       ///< [s] (must be set before stepping)
    double friction = 0.5;        ///< Coulomb coefficient mu between spheres
    double local_damping = 0.0;   ///< Cundall lambda on the fluctuations (0: off)
    double skin_ratio = 0.3;      ///< Verlet skin / largest radius
    bool kinetic_stress = false;  ///< add the fluctuations' kinetic stress to the total
  };

  PeriodicCell(const CellMatrix& cell, const ContactModel& law, const Parameters& p);

  /// Adds a sphere at x (any image; wrapped at the next build) with fluctuating velocity u
  /// and spin omega; returns its index (= its id).
  Index add_sphere(const Vec3& x, double radius, double density, const Vec3& u = Vec3::Zero(),
                   const Vec3& omega = Vec3::Zero());
  /// Sets sphere p's fluctuating velocity u and spin omega.
  void set_velocity(Index p, const Vec3& u, const Vec3& omega);
  /// Multiplies every radius by `factor` at constant density (radius growth).
  void scale_radii(double factor);

  void set_parameters(const Parameters& p);
  const Parameters& parameters() const { return p_; }
  const ContactModel& contact_model() const { return law_; }

  /// The control of L (every component prescribed by default, L = 0).
  MixedControl& control() { return control_; }
  const MixedControl& control() const { return control_; }
  /// Shorthand: every component of L prescribed.
  void set_velocity_gradient(const Mat3& l) { control_.set_velocity_gradient(l); }

  void step();
  void run(std::uint64_t steps);
  /// Evaluates the contact forces and the stress at the current state without moving
  /// (history not advanced): the state a freshly built cell reports.
  void evaluate();
  /// evaluate() unless the loads and the stress already belong to the current state (after
  /// a step, nothing changed since): a program that starts on a running cell then leaves
  /// its trajectory exactly as continued stepping would.
  void refresh();

  // State.
  std::size_t n_particles() const { return store_.size(); }
  const CellMatrix& cell() const { return cell_; }
  const ParticleStore& particles() const { return store_; }
  const Vec3& position(Index p) const { return store_.x[p]; }
  const Vec3& fluctuation(Index p) const { return store_.v[p]; }
  /// Lab velocity u + L x.
  Vec3 velocity(Index p) const { return store_.v[p] + l_ * store_.x[p]; }
  const Vec3& force(Index p) const { return store_.force[p]; }
  const Vec3& torque(Index p) const { return store_.torque[p]; }
  /// The velocity gradient of the last step.
  const Mat3& velocity_gradient() const { return l_; }
  const CellStress& stress() const { return stress_; }
  const PeriodicNeighbours& neighbours() const { return lists_; }
  double time() const { return time_; }
  std::uint64_t steps() const { return steps_; }

  // Measures.
  /// Sum of the spheres' volumes over the cell volume (overlaps counted twice).
  double packing_fraction() const;
  /// Mean |net force| over mean |contact force| (1 when there is no contact).
  double unbalanced_force_ratio() const;
  /// Kinetic energy of the fluctuations and spins [J].
  double kinetic_energy() const;
  /// Coordination number Z = 2 C / N of the force-carrying contacts.
  double coordination() const;

private:
  void build_lists();
  void forces(double history_dt);
  void kick(double dt);
  /// Affine drift by A = exp(L dt) of the spheres and the cell; rebuilds the list when
  /// the criterion of PeriodicNeighbours asks for it.
  void drift(double dt);

  Parameters p_{};
  ContactModel law_;
  CellMatrix cell_;
  ParticleStore store_;
  Integrator integrator_;
  PeriodicNeighbours lists_;
  MixedControl control_;
  CellStress stress_;
  Mat3 l_ = Mat3::Zero();
  Mat3 l_step_ = Mat3::Constant(std::numeric_limits<double>::quiet_NaN());  ///< L dt of the cached A
  Mat3 a_ = Mat3::Identity();
  Mat3 h_ref_inv_ = Mat3::Identity();     ///< H^{-1} at the last build
  std::vector<Vec3> x_ref_;               ///< positions at the last build
  double grown_ = 0.0;                    ///< [m] largest radius growth since the last build
  bool lists_valid_ = false;
  bool loads_current_ = false;            ///< force, torque and stress belong to the state
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
};

}  // namespace geocomp::dem
