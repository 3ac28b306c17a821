// @sect3{The ContactLaw class template: a normal part times a tangential part}
//
// Why it exists: a contact law is a composition of orthogonal parts (MercuryDPM's
// Species<Normal, Friction>), chosen at compile time so the per-contact loop has no
// branch on the law type (Lethe PR #300). `ContactLaw<Normal, Tangential>` calls
// `Normal::evaluate(kinematics)` and hands its `NormalResponse` to
// `Tangential::evaluate(kinematics, normal_response, history)`. Rolling and cohesion
// parts will be further template parameters. The same object, and therefore the same
// code, evaluates particle-particle and particle-wall contacts; only the kinematics
// builder differs (ContactKinematics.h).
//
// The force on j is $F = F_n n + F_t$. The per-step losses are returned for the energy
// ledger: normal dashpot $-(F_n - F_n^{el})v_n\Delta t$ (this also counts the clamp
// correctly), tangential dashpot and sliding from the tangential part.
//
// `ContactModel` is the closed set of laws a run can choose at run time; the engine
// dispatches on it once per step (std::visit), outside the contact loop.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/HertzNormal.h"
#include "dem/LinearNormal.h"
#include "dem/LinearTangential.h"
#include "dem/MindlinTangential.h"

#include <type_traits>
#include <variant>

namespace geocomp::dem {

struct ContactForce
{
  double normal = 0.0;       ///< F_n (> 0 repulsive)
  Vec3 tangential;           ///< F_t on j
  double damping_loss = 0.0; ///< dashpot energy dissipated in this increment
  double friction_loss = 0.0;///< sliding energy dissipated in this increment
};

struct ContactEnergy
{
  double normal = 0.0;
  double tangential = 0.0;
};

template <class Normal, class Tangential>
class ContactLaw
{
public:
  using NormalPart = Normal;
  using TangentialPart = Tangential;

  ContactLaw() = default;
  ContactLaw(const Normal& n, const Tangential& t) : normal_(n), tangential_(t) {}

  const Normal& normal() const { return normal_; }
  const Tangential& tangential() const { return tangential_; }

  /// Evaluates the law at kinematics `k`, advancing the tangential history `shear`
  /// by k.dt (k.dt == 0 evaluates without advancing it).
  ContactForce evaluate(const ContactKinematics& k, Vec3& shear) const
  {
    const NormalResponse nr = normal_.evaluate(k);
    const TangentialResponse tr = tangential_.evaluate(k, nr, shear);
    ContactForce f;
    f.normal = nr.force;
    f.tangential = tr.force;
    f.damping_loss = -(nr.force - nr.elastic) * k.v_n * k.dt + tr.damping_loss;
    f.friction_loss = tr.friction_loss;
    return f;
  }

  /// Energy stored in the springs of one contact (no side effects on the history).
  ContactEnergy elastic_energy(double overlap, double m_eff, double r_eff, const Vec3& shear) const
  {
    ContactEnergy e;
    e.normal = normal_.elastic_energy(overlap, m_eff, r_eff);
    if constexpr (std::is_same_v<Tangential, MindlinTangential>) {
      e.tangential = tangential_.elastic_energy(overlap, r_eff, shear);
    } else {
      ContactKinematics k;
      k.overlap = overlap;
      k.m_eff = m_eff;
      k.r_eff = r_eff;
      e.tangential = tangential_.elastic_energy(normal_.evaluate(k), shear);
    }
    return e;
  }

private:
  Normal normal_{};
  Tangential tangential_{};
};

/// S0: linear spring-dashpot with incremental Coulomb spring.
using LinearSpringDashpot = ContactLaw<LinearNormal, LinearTangential>;
/// S4: Hertz with nonlinear damping and Mindlin's tangential stiffness.
using HertzMindlin = ContactLaw<HertzNormal, MindlinTangential>;

using ContactModel = std::variant<LinearSpringDashpot, HertzMindlin>;

}  // namespace geocomp::dem
