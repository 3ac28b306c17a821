#pragma once
// @sect3{The kinetic Nikolaevsky point: S1's dynamic model of a brittle material point}
//
// Why: this is the whole of S1's model at one integration point of an explicit code:
// elastic predictor in increments, Wilkins correction of the Nikolaevsky plasticity
// (S1 eqs. (1)-(5)), relaxation towards the surface over the finite time T_r instead of in
// one step (eq. (13)), and Drucker-Prager fracture after an incubation period (eqs. (6),
// (8)-(11)), followed by the loss of strength at the point. Unlike ConstitutiveModel, it
// needs the time step, and its history holds times, so it has its own state.
//
// One step, tension positive (sigma_tr = sigma_n + D : d eps):
//   Phi = omega J1 + sqrt(J2),  Y*(kappa) = Y0 + H kappa (static surface, hardening)
//   kinetic off: DeltaPhi = full return to the hardened surface (quasi-static Wilkins).
//   kinetic on (S1 Sec. 2): when Phi exceeds the highest value of the current overstress
//     episode, Phi is the new dynamic elastic limit Y_dyn; y = Y_dyn / Y* gives the
//     equivalent rate and T_r(y) (eqs. (19)-(21)) and with them omega, Lambda and the
//     plastic-strain share (eqs. (23), (28), (29)); the relaxation rate is
//       R = (Y_dyn - Y*) / T_r,  DeltaPhi = R dt (capped by the full return)    (S1 eq. (13))
//     so a held overstress falls linearly and reaches the surface after exactly T_r.
//   Hardening: d kappa = d gamma / share - the plastic strain share of eq. (29) shrinks
//   the plastic strain needed to harden, i.e. steepens the hardening at high rates.
//   Fracture: static eq. (6), or kinetic eqs. (10)-(11) measured from the onset time t0,
//   interpolated inside the step. After fracture the point keeps no deviator and no
//   tension: sigma = min(0, p) 1 (zero in plane stress).
#include "continuum/kinetic/FractureCriterion.h"
#include "continuum/kinetic/RateCalibration.h"
#include "continuum/kinetic/S1Material.h"
#include "continuum/kinetic/WilkinsCorrection.h"
#include "continuum/models/IsotropicElasticity.h"

namespace geocomp::kinetic {

struct KineticState {
  Vector6 stress = Vector6::Zero();          ///< [Pa], Mandel
  Vector6 plastic_strain = Vector6::Zero();  ///< Mandel
  double plastic_shear = 0.0;                ///< accumulated gamma^p
  double hardening_strain = 0.0;             ///< kappa (gamma^p divided by the plastic share)
  double time = 0.0;                         ///< [s]
  // relaxation episode, S1 eq. (13)
  bool relaxing = false;
  double dynamic_yield = 0.0;                ///< Y_dyn: highest Phi of the episode [Pa]
  double relaxation_time = 0.0;              ///< T_r of the episode [s]
  double relaxation_rate = 0.0;              ///< R [Pa/s]
  double omega = 0.0, dilatancy = 0.0, plastic_share = 1.0; ///< parameters of the episode
  // fracture, S1 eqs. (8)-(11)
  bool incubating = false;
  double onset_time = 0.0;                   ///< t0 [s]
  bool fractured = false;
  double fracture_time = -1.0;               ///< [s]
};

class KineticNikolaevsky {
public:
  /// @param kinetic false: S1's quasi-static model (instant return, static fracture).
  KineticNikolaevsky(const S1Material &material, bool kinetic);

  /// Zero stress, parameters at their static values.
  KineticState initial_state() const;
  /// One explicit step with the total strain increment d eps (Mandel) over dt > 0.
  KineticState step(const KineticState &old, const Vector6 &strain_increment, double dt) const;

  /// Static surface Y*(kappa) [Pa].
  double static_cohesion(double hardening_strain) const;
  /// Phi = omega J1 + sqrt(J2) with the state's current omega.
  double yield_function(const KineticState &s) const;

  const S1Material &material() const { return m_; }
  const continuum::IsotropicElasticity &elasticity() const { return elastic_; }
  const RelaxationCalibration &relaxation() const { return relax_; }
  const FractureCriterion &fracture() const { return fracture_; }
  bool kinetic() const { return kinetic_; }

private:
  void correct(KineticState &s, const Vector6 &trial, double dt) const;
  void check_fracture(KineticState &s, const Vector6 &old_stress, double dt) const;

  S1Material m_;
  continuum::IsotropicElasticity elastic_;
  RelaxationCalibration relax_;
  FractureCriterion fracture_;
  bool kinetic_;
  double Y0_, H_;
};

} // namespace geocomp::kinetic
