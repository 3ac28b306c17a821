// @sect3{The HertzNormal contact part (S4 Hertz with nonlinear normal damping)}
//
// Why it exists: S4's clumps use Hertz-Mindlin, and Hertz is the physically derived
// law for elastic spheres. The elastic force and stiffness (S4 eq. (15), (18)):
// $$ F_n^{el} = K_n\delta^{3/2},\quad K_n = \tfrac43 E^*\sqrt{R^*},\quad
//    S_n = \partial F/\partial\delta = 2E^*\sqrt{R^*\delta}, $$
// with $E^* = E/(2(1-\nu^2))$ for like materials. Two nonlinear dashpots:
//  - `restitution` (default; LIGGGHTS gran_model_hertz, LAMMPS, Lethe, Tsuji type):
//    $\eta_n = -2\sqrt{5/6}\,\beta\sqrt{S_n m^*}$, $\beta = \ln e/\sqrt{\ln^2 e + \pi^2}$;
//    the restitution is then independent of impact speed.
//  - `brilliantov` (S4 eq. (15) literally): $F_n = K_n\delta^{3/2} + \tfrac32 A K_n\delta^{1/2}\dot\delta$,
//    i.e. $\eta_n = \tfrac32 A K_n\sqrt\delta$, with A [s] fitted to e at one speed.
// $F_n = F_n^{el} - \eta_n v_n$, clamped to $\ge 0$ unless `clamp_tensile` is false.
// The elastic energy is $\tfrac25 K_n\delta^{5/2}$.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/NormalResponse.h"

#include <algorithm>
#include <cmath>

namespace geocomp::dem {

class HertzNormal
{
public:
  enum class Damping { restitution, brilliantov };

  struct Parameters
  {
    double youngs_modulus = 0.0;  ///< E [Pa]
    double poisson_ratio = 0.0;   ///< nu
    Damping damping_input = Damping::restitution;
    double restitution = 1.0;     ///< e when damping_input == restitution
    double brilliantov_a = 0.0;   ///< A [s] when damping_input == brilliantov
    bool clamp_tensile = true;
  };

  HertzNormal() = default;
  explicit HertzNormal(const Parameters& p);

  const Parameters& parameters() const { return p_; }
  double effective_modulus() const { return e_star_; }

  NormalResponse evaluate(const ContactKinematics& k) const
  {
    NormalResponse r;
    const double sr = std::sqrt(k.r_eff);
    const double sd = std::sqrt(k.overlap);
    const double kn = 4.0 / 3.0 * e_star_ * sr;        // S4 eq. (18)
    r.elastic = kn * k.overlap * sd;                    // S4 eq. (15), elastic part
    r.stiffness = 2.0 * e_star_ * sr * sd;              // S_n = 2 E* sqrt(R* delta)
    if (p_.damping_input == Damping::restitution)
      r.damping = -2.0 * std::sqrt(5.0 / 6.0) * beta_ * std::sqrt(r.stiffness * k.m_eff);
    else
      r.damping = 1.5 * p_.brilliantov_a * kn * sd;     // S4 eq. (15), damping part
    const double f = r.elastic - r.damping * k.v_n;
    r.force = p_.clamp_tensile ? std::max(f, 0.0) : f;
    return r;
  }

  double elastic_energy(double overlap, double /*m_eff*/, double r_eff) const
  {
    return 0.4 * (4.0 / 3.0) * e_star_ * std::sqrt(r_eff) * overlap * overlap * std::sqrt(overlap);
  }

  /// Tangent stiffness at a given overlap (for time-step and servo-gain estimates).
  double max_stiffness(double /*m_eff*/, double r_eff, double overlap) const
  {
    return 2.0 * e_star_ * std::sqrt(r_eff * overlap);
  }

private:
  Parameters p_{};
  double e_star_ = 0.0;
  double beta_ = 0.0;
};

}  // namespace geocomp::dem
