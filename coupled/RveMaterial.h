#pragma once
// @sect3{The RveMaterial class: a periodic DEM cell as the constitutive law of a point}
//
// Why it exists: the hierarchical FEM x DEM method (Guo & Zhao 2014; Nitka, Combe, Desrues
// et al. 2011; issue 35) puts a small DEM assembly at every quadrature point and lets the
// grains' own law answer the finite-element strain. This class is that law, a
// continuum::PointStateModel whose point state is a dem::PeriodicCell: every point starts
// from a copy of one prepared RVE (dem/periodic/PeriodicPreparation.h, PeriodicProgram.h).
//
// Driving (small strain). From the committed state, a cell at total strain eps_n, to the
// total strain eps_{n+1} of the current Newton iterate, a copy of the cell is driven
// quasi-statically over n DEM steps of its own time step dt by the homogeneous velocity
// gradient
// $$ L = \frac{\Delta\varepsilon}{n\,\Delta t},\qquad \Delta\varepsilon = \varepsilon_{n+1} - \varepsilon_n, $$
// symmetric (no spin: the small-strain increment carries no rotation). The affine strain the
// cell sees over the increment is then $\int L\,dt = \Delta\varepsilon$ (its log strain, to
// $O(\Delta\varepsilon^2)$). n (`steps per increment`) sets the cell's strain rate, hence its
// inertial number: the choice that makes the response quasi-static. A zero increment
// returns the committed state itself (a quasi-static cell holds its state when nothing moves).
// The stress is the cell's Love-Weber stress at the end of the n steps (CellStress.h:
// contact part, plus the kinetic part when the cell was prepared with it), tension positive.
//
// Tangent: the normal-spring contact stiffness of the cell's current contact network. For
// spheres the branch vector is along the normal, l = |l| n, so the affine stiffness of the
// normal springs is the totally symmetric tensor
// $$ C_{ijkl} = \frac1V\sum_c k_{n,c}\,|l_c|^2\,n_i n_j n_k n_l, $$
// and the cell's servo stiffness (CellStress::stiffness) holds $K_{ab} = C_{abab} = C_{aabb}$.
// The tangent is its orthotropic part in the cell axes (the 3x3 normal block $C_{aabb}$ and
// the shear diagonal $C_{abab}$; the odd moments $C_{aaab}$, $C_{abac}$ left out), positive
// semi-definite as principal blocks of a PSD tensor. It omits the tangential springs and the
// non-affine relaxation of the packing, so it is not the consistent tangent: the FE Newton
// converges linearly with it (a quasi-Newton).
// Driving (finite strain). From the committed cell at F_n to the Newton iterate's F_{n+1},
// the copy is driven over the same n steps by the constant velocity gradient
// $$ L = \frac{\ln(F_{n+1}F_n^{-1})}{n\,\Delta t}, $$
// (the principal matrix logarithm, spin included), so its cell matrix ends at
// $H_{n+1} = e^{nL\Delta t}H_n = F_{n+1}F_n^{-1}H_n$ to round-off: the cell follows the
// point's deformation exactly, rotation included, whatever the size of the increment. The
// stress is the cell's Love-Weber (Cauchy) stress in the lab frame, tau = J sigma, and the
// spatial tangent is the rate form's (PointStateModel.h, jaumann_spatial_tangent) with the
// contact-stiffness tangent below as C: the grains turn with the cell's spin through their
// contacts (their spins are absolute), so a rotated cell's stress co-rotates - to within
// what the tangential springs lag (measured in docs/coupled.md).
//
// Tangent along the branch (`tangent = branch secant`, the default). A cell that slides
// answers an increment and its opposite with stiffnesses a tenth apart (docs/coupled.md, "The
// cells' answer near the floor"): its law is incrementally non-linear, and the contact
// stiffness above, the loading branch of no sliding contact, is several times too stiff along
// the branch the point is on. A rate-independent cell's answer is positively homogeneous of
// degree one in the increment, sigma(eps_n + lambda s) - sigma_n = lambda (sigma(eps_n + s) -
// sigma_n) for lambda > 0, so its derivative along the increment s is the secant (Euler):
// $$ \frac{\partial\sigma}{\partial\varepsilon}\,s = y,\qquad s = \Delta\varepsilon,\quad y = \sigma_{n+1} - \sigma_n , $$
// measured by the run the iterate needs anyway, at no extra cost. The tangent made from it is
// the contact stiffness C updated by the BFGS formula, a rank-two change that carries the
// secant along s and leaves C on every v with v.C.s = 0 and v.r = 0, with Powell's damping
// (Math. Programming 14, 1978) keeping it positive definite where the cell softens along s
// (y.s < 0.2 s.C.s):
// $$ \tilde C = C - \frac{C s\,(C s)^T}{s^T C s} + \frac{r\,r^T}{s^T r},\qquad r = \theta y + (1-\theta) C s,\quad
//    \theta = \begin{cases} 1 & s^T y \ge 0.2\, s^T C s \\ \frac{0.8\, s^T C s}{s^T C s - s^T y} & \text{else,} \end{cases} $$
// so $\tilde C s = r$ (= y unless damped). At finite strain s is the symmetric part of ln(F_{n+1}
// F_n^{-1}) and y the Jaumann increment of the Cauchy stress, sigma_{n+1} - sigma_n - (W sigma_n -
// sigma_n W), W its skew part, as C is the rate form's. The committed state keeps the tangent
// of the increment that made it: a zero increment (the predictor of the next load step) answers
// with it, the tangent of the branch the point was last on. `tangent = contact stiffness` is the
// contact stiffness alone at every state.
//
// `elasticity()` (the FE cube's reference stiffness: residual floor, prestrain, localization
// scan) is the isotropic projection of the prepared cell's tangent:
// $K = C_{iijj}/9$, $G = (C_{ijij} - C_{iijj}/3)/10$.
#include "continuum/models/IsotropicElasticity.h"
#include "continuum/models/PointStateModel.h"
#include "dem/periodic/PeriodicCell.h"

#include <cstdint>
#include <memory>
#include <string>

namespace geocomp::coupled {

/// The tangent a cell answers with (the file comment).
enum class RveTangent { contact_stiffness, branch_secant };

struct RveParameters {
  std::uint64_t steps_per_increment = 200;         ///< n >= 1: DEM steps over one strain increment
  RveTangent tangent = RveTangent::branch_secant; ///< of every update
};

/// The point state: the cell, the total strain (small strain) or deformation gradient
/// (finite strain) it was driven to, and the tangent it answers with.
struct RveState : continuum::PointState {
  RveState(dem::PeriodicCell c, const continuum::Vector6 &e, const continuum::Matrix6 &t)
    : cell(std::move(c)), strain(e), tangent(t)
  {
  }
  dem::PeriodicCell cell;
  continuum::Vector6 strain;                                                       ///< eps_n (Mandel) of the caller
  continuum::Matrix3 deformation_gradient = continuum::Matrix3::Identity();        ///< F_n of the caller
  continuum::Matrix6 tangent; ///< of the increment that made this state (the file comment)
};

class RveMaterial : public continuum::PointStateModel {
public:
  /// @param[in] prepared the RVE every point starts from (its stress made current here; it
  /// must carry contacts); @param[in] parameters n >= 1. Throws std::invalid_argument.
  RveMaterial(dem::PeriodicCell prepared, const RveParameters &parameters);

  std::shared_ptr<const continuum::PointState> initial_state(const continuum::Vector6 &initial_strain) const override;
  continuum::PointStateUpdate advance(const continuum::Vector6 &total_strain,
                                      const std::shared_ptr<const continuum::PointState> &old) const override;
  continuum::FiniteStrainUpdate advance_finite(const continuum::Matrix3 &deformation_gradient,
                                               const continuum::FiniteStrainHistory &old) const override;

  const continuum::IsotropicElasticity &elasticity() const override { return elastic_; }
  std::string name() const override { return "dem_rve"; }

  const RveParameters &parameters() const { return p_; }
  const dem::PeriodicCell &prepared() const { return prepared_; }

  /// The velocity gradient that drives a cell by the strain increment (Mandel) over n steps.
  static dem::Mat3 velocity_gradient(const continuum::Vector6 &increment, std::uint64_t n, double time_step);
  /// The velocity gradient ln(F_inc) / (n dt) that takes a cell through the deformation
  /// increment F_inc = F_{n+1} F_n^{-1} over n steps; throws continuum::ReturnMapFailure
  /// when F_inc has no real logarithm (det <= 0 or a rotation by pi).
  static dem::Mat3 finite_velocity_gradient(const continuum::Matrix3 &increment, std::uint64_t n, double time_step);
  /// Stress (Mandel, tension positive) and tangent of a cell as this model reports them.
  static continuum::Vector6 stress(const dem::PeriodicCell &cell);
  static continuum::Matrix6 tangent(const dem::PeriodicCell &cell);
  /// The damped BFGS update of `contact` that carries the secant y along s (the file
  /// comment); `contact` itself where s.C.s is not positive.
  static continuum::Matrix6 branch_tangent(const continuum::Matrix6 &contact, const continuum::Vector6 &s,
                                           const continuum::Vector6 &y);

private:
  dem::PeriodicCell prepared_;
  RveParameters p_;
  continuum::IsotropicElasticity elastic_;
};

} // namespace geocomp::coupled
