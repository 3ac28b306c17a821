// @sect3{The ContactLaw class template: normal x tangential x rolling x cohesion parts}
//
// Why it exists: a contact law is a composition of orthogonal parts (MercuryDPM's
// Species<Normal, Friction, Adhesive>), chosen at compile time so the per-contact loop has
// no branch on the law type (Lethe PR #300).
// `ContactLaw<Normal, Tangential, Rolling, Cohesion>` calls
// `Normal::evaluate(kinematics)` and hands its `NormalResponse` to
// `Tangential::evaluate(kinematics, normal_response, history)`; a rolling part adds a
// moment $M_r$ on j (LinearRolling.h, S2) and a cohesion part adds bond and adhesion
// forces that outlive the overlap (S3Bonding.h, S3). Rolling and Cohesion default to
// the "none" parts (NoContactPart.h): then `has_memory` is false, the law takes only the
// tangential history, and the code compiled for it is the plain normal x tangential
// law. The same object evaluates particle-particle and particle-wall contacts; only
// the kinematics builder differs (ContactKinematics.h).
//
// The force on j is $F = F_n n + F_t$ (plus the moment $M_r$ on j, $-M_r$ on i). The
// per-step losses are returned for the energy ledger: normal dashpot
// $-(F_n - F_n^{el})v_n\Delta t$ (this also counts the clamp correctly), tangential dashpot,
// sliding and rolling slip, and the energy released by bonds.
//
// With a cohesion part, a contact is evaluated while bodies are apart ($\delta \le 0$): the
// normal, tangential and rolling parts then give nothing and their springs reset (the
// grains do not touch), and only bonds and adhesion act.
//
// Placement overlap of fragments (S2, ContactMemory::placement). A law with memory
// evaluates a contact that still holds a placement overlap $\delta_p$ at the effective
// overlap $\delta_e = \delta - \delta_p$ (nothing while $\delta_e \le 0$), and every
// advancing evaluation lowers it at the stored rate,
// $$ \delta_p \leftarrow \max\bigl(0, \min(\delta_p - \dot\delta_p\,\Delta t,\ \delta)\bigr) $$
// (a contact whose overlap fell below $\delta_p$ holds nothing to release). Lowering
// $\delta_p$ at fixed $\delta$ raises the stored normal energy by
// $W(\delta) = E_n(\delta - \delta_p^{new}) - E_n(\delta - \delta_p^{old}) \ge 0$: the release
// work, returned for the ledger (EnergyLedger::release_work), taken at the overlap of this
// evaluation (the balance then converges to first order in the time step; taken at the
// previous overlap, or at the mean of both, it drifted about 100 times more).
// For a linear spring the rest overlap moves at the constant speed $u = \dot\delta_p$, and
// an undamped pair of reduced mass $m^*$ that starts at rest follows
// $s(t) = u t - (u/\omega)\sin\omega t$, $\omega^2 = k_n/m^*$: its relative speed never
// exceeds $2u$, so the kinetic energy the release gives is at most
// $2 m^* u^2 = 4 E_p/(\omega T)^2$ for a release time $T = \delta_p/u$ (against the whole
// $E_p = \tfrac12 k_n \delta_p^2$ for an instant release).
//
// `ContactModel` is the closed set of laws a run can choose at run time; the engine
// dispatches on it once per step (std::visit), outside the contact loop.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/ContactMemory.h"
#include "dem/HertzNormal.h"
#include "dem/LinearNormal.h"
#include "dem/LinearRolling.h"
#include "dem/LinearTangential.h"
#include "dem/MindlinTangential.h"
#include "dem/NoContactPart.h"
#include "dem/S3Bonding.h"
#include "dem/StickSlipTangential.h"

#include <algorithm>

#include <type_traits>
#include <variant>

namespace geocomp::dem {

struct ContactForce
{
  double normal = 0.0;        ///< F_n (> 0 repulsive)
  Vec3 tangential;            ///< F_t on j
  Vec3 moment;                ///< rolling moment on j (laws with a rolling part only)
  double damping_loss = 0.0;  ///< dashpot energy dissipated in this increment
  double friction_loss = 0.0; ///< sliding (and rolling slip) energy dissipated in this increment
  double bond_loss = 0.0;     ///< energy released by bond breakage / adhesion formation
  double release_work = 0.0;  ///< work of the placement-overlap release in this increment (S2)
};

struct ContactEnergy
{
  double normal = 0.0;
  double tangential = 0.0;
  double rolling = 0.0;
  double bond = 0.0;          ///< bond spring + adhesion potential (may be negative)
};

template <class Normal, class Tangential, class Rolling = NoRolling, class Cohesion = NoCohesion>
class ContactLaw
{
public:
  using NormalPart = Normal;
  using TangentialPart = Tangential;
  using RollingPart = Rolling;
  using CohesionPart = Cohesion;
  static constexpr bool has_rolling = Rolling::enabled;
  static constexpr bool has_cohesion = Cohesion::enabled;
  /// The law needs a ContactMemory per contact besides the tangential history.
  static constexpr bool has_memory = has_rolling || has_cohesion;

  ContactLaw() = default;
  ContactLaw(const Normal& n, const Tangential& t) : normal_(n), tangential_(t) {}
  ContactLaw(const Normal& n, const Tangential& t, const Rolling& r) : normal_(n), tangential_(t), rolling_(r) {}
  ContactLaw(const Normal& n, const Tangential& t, const Rolling& r, const Cohesion& c)
    : normal_(n), tangential_(t), rolling_(r), cohesion_(c)
  {}

  const Normal& normal() const { return normal_; }
  const Tangential& tangential() const { return tangential_; }
  const Rolling& rolling() const { return rolling_; }
  const Cohesion& cohesion() const { return cohesion_; }

  /// Largest gap at which a contact of effective radius R* still carries force (0
  /// without a cohesion part): the neighbour lists must reach this far.
  double reach(double r_eff) const
  {
    if constexpr (has_cohesion) return cohesion_.reach(r_eff);
    else return 0.0 * r_eff;
  }

  /// Evaluates a law without memory at kinematics `k` (delta > 0), advancing the
  /// tangential history `shear` by k.dt (k.dt == 0 evaluates without advancing it).
  GEOCOMP_CONTACT_KERNEL ContactForce evaluate(const ContactKinematics& k, Vec3& shear) const
  {
    static_assert(!has_memory, "this law needs its ContactMemory: evaluate(k, shear, memory)");
    const NormalResponse nr = normal_.evaluate(k);
    const TangentialResponse tr = tangential_.evaluate(k, nr, shear);
    ContactForce f;
    f.normal = nr.force;
    f.tangential = tr.force;
    f.damping_loss = -(nr.force - nr.elastic) * k.v_n * k.dt + tr.damping_loss;
    f.friction_loss = tr.friction_loss;
    return f;
  }

  /// Evaluates a law with memory (also for delta <= 0 when it has a cohesion part).
  ContactForce evaluate(const ContactKinematics& k, Vec3& shear, ContactMemory& memory) const
  {
    if (memory.placement != 0.0) return evaluate_placed(k, shear, memory);
    return evaluate_touching(k, shear, memory);
  }

  /// A contact with a placement overlap: evaluated at delta - delta_p, which is lowered
  /// when the history advances (k.dt > 0); the release work is returned.
  ContactForce evaluate_placed(const ContactKinematics& k, Vec3& shear, ContactMemory& memory) const
  {
    const double before = memory.placement;
    double after = std::min(before, std::max(k.overlap, 0.0));
    if (k.dt > 0.0) after = std::max(0.0, std::min(before - memory.placement_rate * k.dt, k.overlap));
    ContactKinematics e = k;
    e.overlap = k.overlap - after;
    e.overlap_old = std::max(0.0, k.overlap_old - before);
    ContactForce f = evaluate_touching(e, shear, memory);
    if (k.dt > 0.0) {
      f.release_work = normal_energy(k, k.overlap - after) - normal_energy(k, k.overlap - before);
      memory.placement = after;
      if (after == 0.0) memory.placement_rate = 0.0;
    }
    return f;
  }

  /// The normal part's stored energy at overlap x (0 when x <= 0).
  double normal_energy(const ContactKinematics& k, double x) const
  {
    return x > 0.0 ? normal_.elastic_energy(x, k.m_eff, k.r_eff) : 0.0;
  }

  /// evaluate() at the overlap k.overlap as it stands (no placement overlap).
  ContactForce evaluate_touching(const ContactKinematics& k, Vec3& shear, ContactMemory& memory) const
  {
    ContactForce f;
    f.tangential.setZero();
    f.moment.setZero();
    if (k.overlap > 0.0) {
      const NormalResponse nr = normal_.evaluate(k);
      const TangentialResponse tr = tangential_.evaluate(k, nr, shear);
      f.normal = nr.force;
      f.tangential = tr.force;
      f.damping_loss = -(nr.force - nr.elastic) * k.v_n * k.dt + tr.damping_loss;
      f.friction_loss = tr.friction_loss;
      if constexpr (has_rolling) {
        const RollingResponse rr = rolling_.evaluate(k, tangential_stiffness(k, nr), nr.force, memory.rolling);
        f.moment = rr.moment;
        f.friction_loss += rr.loss;
      }
    } else {
      shear.setZero();
      if constexpr (has_rolling) memory.rolling.setZero();
    }
    if constexpr (has_cohesion) {
      const BondResponse b = cohesion_.evaluate(k, memory);
      f.normal += b.normal;
      f.tangential += b.tangential;
      f.bond_loss = b.loss;
    }
    return f;
  }

  /// Energy stored in the springs of one contact (no side effects on the history).
  ContactEnergy elastic_energy(double overlap, double m_eff, double r_eff, const Vec3& shear) const
  {
    ContactKinematics k;
    k.overlap = overlap;
    k.m_eff = m_eff;
    k.r_eff = r_eff;
    return elastic_energy(k, shear, ContactMemory{});
  }

  /// The same with the contact's memory and friction coefficient (k.overlap, k.m_eff,
  /// k.r_eff and k.mu are read).
  /// A placement overlap counts: the springs hold the energy of delta - delta_p.
  ContactEnergy elastic_energy(const ContactKinematics& k_in, const Vec3& shear, const ContactMemory& memory) const
  {
    ContactKinematics k = k_in;
    k.overlap -= memory.placement;
    ContactEnergy e;
    if (k.overlap > 0.0) {
      e.normal = normal_.elastic_energy(k.overlap, k.m_eff, k.r_eff);
      const NormalResponse nr = normal_.evaluate(k);
      if constexpr (std::is_same_v<Tangential, MindlinTangential>)
        e.tangential = tangential_.elastic_energy(k.overlap, k.r_eff, shear);
      else if constexpr (std::is_same_v<Tangential, StickSlipTangential>)
        e.tangential = tangential_.elastic_energy(k.mu, nr, shear);
      else
        e.tangential = tangential_.elastic_energy(nr, shear);
      if constexpr (has_rolling)
        e.rolling = rolling_.elastic_energy(tangential_stiffness(k, nr), k.r_eff, memory.rolling);
    }
    if constexpr (has_cohesion) e.bond = cohesion_.elastic_energy(k.overlap, k.r_eff, memory);
    return e;
  }

  /// Tangential stiffness k_t at this contact (the rolling stiffness is k_t R*^2).
  double tangential_stiffness(const ContactKinematics& k, const NormalResponse& nr) const
  {
    if constexpr (std::is_same_v<Tangential, MindlinTangential>) return tangential_.stiffness(k.overlap, k.r_eff);
    else if constexpr (std::is_same_v<Tangential, StickSlipTangential>) return tangential_.stiffness(k.mu, nr);
    else return tangential_.stiffness(nr);
  }

private:
  Normal normal_{};
  Tangential tangential_{};
  Rolling rolling_{};
  Cohesion cohesion_{};
};

/// S0: linear spring-dashpot with incremental Coulomb spring.
using LinearSpringDashpot = ContactLaw<LinearNormal, LinearTangential>;
/// S4: Hertz with nonlinear damping and Mindlin's tangential stiffness.
using HertzMindlin = ContactLaw<HertzNormal, MindlinTangential>;
/// S2: PFC's rolling resistance linear model (linear spring-dashpot + rolling spring).
using LinearRollingResistance = ContactLaw<LinearNormal, LinearTangential, LinearRolling>;
/// S4's Hertz-Mindlin with a rolling spring.
using HertzMindlinRolling = ContactLaw<HertzNormal, MindlinTangential, LinearRolling>;
/// Linear spring-dashpot with Coulomb friction, rolling resistance and S3's bonds.
using LinearCohesive = ContactLaw<LinearNormal, LinearTangential, LinearRolling, S3Bonding>;
/// S3's soil: linear normal, anchor-spring friction with k_phi, bonds and adhesion.
using S3Soil = ContactLaw<LinearNormal, StickSlipTangential, LinearRolling, S3Bonding>;

using ContactModel =
  std::variant<LinearSpringDashpot, HertzMindlin, LinearRollingResistance, HertzMindlinRolling, LinearCohesive, S3Soil>;

}  // namespace geocomp::dem
