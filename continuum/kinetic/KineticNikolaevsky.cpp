#include "continuum/kinetic/KineticNikolaevsky.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocomp::kinetic {

using continuum::mandel_identity;

namespace {
const double minimum_share = 1e-12;
}

KineticNikolaevsky::KineticNikolaevsky(const S1Material &material, bool kinetic)
  : m_((material.validate(), material)), elastic_(material.youngs_modulus, material.poisson_ratio), relax_(material),
    fracture_(material), kinetic_(kinetic), Y0_(material.static_cohesion()), H_(material.hardening_modulus())
{
}

KineticState KineticNikolaevsky::initial_state() const
{
  KineticState s;
  s.omega = m_.omega();
  s.dilatancy = m_.dilatancy;
  s.plastic_share = 1.0;
  return s;
}

double KineticNikolaevsky::static_cohesion(double hardening_strain) const { return Y0_ + H_ * hardening_strain; }

double KineticNikolaevsky::yield_function(const KineticState &s) const
{
  const Invariants inv = invariants(s.stress);
  return s.omega * inv.J1 + inv.tau; // S1 eq. (1)
}

KineticState KineticNikolaevsky::step(const KineticState &old, const Vector6 &d_eps, double dt) const
{
  KineticState s = old;
  s.time = old.time + dt;
  if (old.fractured) {
    // Post-fracture: no deviator, no tension, compression carried through the bulk modulus.
    const double p = (old.stress(0) + old.stress(1) + old.stress(2)) / 3.0 +
                     elastic_.bulk_modulus() * (d_eps(0) + d_eps(1) + d_eps(2));
    s.stress = std::min(0.0, p) * mandel_identity();
    return s;
  }
  const Vector6 trial = old.stress + elastic_.stiffness() * d_eps;
  correct(s, trial, dt);
  s.plastic_strain = old.plastic_strain + d_eps - elastic_.compliance() * (s.stress - old.stress);
  check_fracture(s, old.stress, dt);
  return s;
}

void KineticNikolaevsky::correct(KineticState &s, const Vector6 &trial, double dt) const
{
  s.stress = trial;
  if (!s.relaxing) {
    s.omega = m_.omega();
    s.dilatancy = m_.dilatancy;
    s.plastic_share = 1.0;
  }
  const double Y_star = static_cohesion(s.hardening_strain);
  const Invariants inv = invariants(trial);
  double phi = s.omega * inv.J1 + inv.tau; // S1 eq. (1)
  if (phi <= Y_star) {
    s.relaxing = false; // elastic step: the overstress episode is over
    s.omega = m_.omega();
    s.dilatancy = m_.dilatancy;
    s.plastic_share = 1.0;
    return;
  }
  if (kinetic_ && (!s.relaxing || phi > s.dynamic_yield)) {
    // A new dynamic elastic limit: T_r and the rate-dependent parameters follow from it.
    const double y = phi / Y_star;
    const double rate = relax_.equivalent_rate(y);           // inverse of S1 eq. (19)
    s.relaxation_time = relax_.relaxation_time(y);           // S1 eqs. (20)-(21)
    s.omega = m_.omega() * relax_.friction_ratio(rate);      // S1 eq. (23)
    s.dilatancy = m_.dilatancy * relax_.dilatancy_ratio(rate); // S1 eq. (28)
    s.plastic_share = std::max(minimum_share, relax_.plastic_share(rate)); // S1 eq. (29)
    phi = s.omega * inv.J1 + inv.tau;
    if (phi <= Y_star) {
      s.relaxing = false;
      return;
    }
    s.relaxing = true;
    s.dynamic_yield = phi;
    s.relaxation_rate = s.relaxation_time > 0.0 ? (phi - Y_star) / s.relaxation_time
                                                : std::numeric_limits<double>::infinity();
  }
  const NikolaevskyConstants c{elastic_.shear_modulus(), elastic_.bulk_modulus(), s.omega, s.dilatancy};
  const double H_eff = H_ / s.plastic_share;
  const double overstress = phi - Y_star;
  // Reduction of the overstress Phi - Y*: Phi falls by c.denominator() d gamma and Y*
  // rises by H_eff d gamma. Quasi-static: all of it; kinetic: R dt of it (S1 eq. (13)).
  const double reduction = kinetic_ ? std::min(overstress, s.relaxation_rate * dt) : overstress;
  const double d_gamma = reduction / (c.denominator() + H_eff);
  const WilkinsResult w = wilkins_correction(trial, c.denominator() * d_gamma, c);
  s.stress = w.stress;
  s.plastic_shear += w.plastic_shear;
  s.hardening_strain += w.plastic_shear / s.plastic_share;
  if (kinetic_ && reduction >= overstress)
    s.relaxing = false; // landed on the surface: the episode is complete
}

void KineticNikolaevsky::check_fracture(KineticState &s, const Vector6 &old_stress, double dt) const
{
  bool fractured = false;
  if (!kinetic_) {
    fractured = fracture_.static_criterion_met(s.stress); // S1 eq. (6)
  } else {
    const double sc = m_.compressive_strength, a = m_.compressive_strength / m_.tensile_strength;
    const double now = drucker_prager_parameter(s.stress, a);
    if (now < sc) {
      s.incubating = false; // below the static strength: no incubation (S1 eq. (8))
    } else {
      if (!s.incubating) {
        // t0: the static strength is reached inside this step (linear interpolation).
        const double before = drucker_prager_parameter(old_stress, a);
        const double w = before < sc && now > before ? (sc - before) / (now - before) : 1.0;
        s.incubating = true;
        s.onset_time = s.time - dt + w * dt;
      }
      fractured = fracture_.dynamic_criterion_met(s.stress, s.time - s.onset_time); // S1 eq. (11)
    }
  }
  if (fractured) {
    s.fractured = true;
    s.fracture_time = s.time;
    s.relaxing = false;
    const double p = (s.stress(0) + s.stress(1) + s.stress(2)) / 3.0;
    s.stress = std::min(0.0, p) * mandel_identity();
  }
}

} // namespace geocomp::kinetic
