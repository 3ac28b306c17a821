#include "continuum/kinetic/HomogeneousUniaxial.h"

#include "continuum/kinetic/PlaneStress.h"

#include <cmath>
#include <stdexcept>

namespace geocomp::kinetic {

const char *to_string(LoadingMode mode) { return mode == LoadingMode::compression ? "compression" : "tension"; }

UniaxialPointResult run_uniaxial_point(const KineticNikolaevsky &model, LoadingMode mode, double strain_rate,
                                       int steps_to_static_strength, int sample_every)
{
  if (!(strain_rate > 0.0) || steps_to_static_strength < 10)
    throw std::invalid_argument("run_uniaxial_point: expected a positive strain rate and >= 10 steps");
  const S1Material &m = model.material();
  const double sign = mode == LoadingMode::compression ? -1.0 : 1.0;
  const double strength = mode == LoadingMode::compression ? m.compressive_strength : m.tensile_strength;
  const double dt = strength / (m.youngs_modulus * strain_rate) / steps_to_static_strength;
  const double d_axial = sign * strain_rate * dt;
  const auto &el = model.elasticity();
  const double slope = el.lame_lambda() + 2.0 * el.shear_modulus() + el.lame_lambda();

  UniaxialPointResult r;
  KineticState s = model.initial_state();
  double strain = 0.0;
  const long max_steps = 200L * steps_to_static_strength; // far past any strength of S1's curves
  for (long n = 0; n < max_steps && !s.fractured; ++n) {
    KineticState next;
    Vector6 d_eps = Vector6::Zero();
    d_eps(1) = d_axial;
    auto lateral_stress = [&](double x) {
      d_eps(0) = d_eps(2) = x;
      next = model.step(s, d_eps, dt);
      return next.stress(0);
    };
    const double guess = -m.poisson_ratio * d_axial;
    const double x = monotone_root(lateral_stress, guess, slope,
                                   1e-10 * (s.stress.cwiseAbs().maxCoeff() + 1.0) + 1e-3);
    if (d_eps(0) != x)
      lateral_stress(x);
    strain += std::abs(d_axial);
    if (r.yield_stress < 0.0 && next.plastic_shear > 0.0)
      r.yield_stress = std::abs(s.stress(1));
    const double stress = std::abs(next.stress(1));
    if (stress > r.peak_stress && sign * next.stress(1) > 0.0) {
      r.peak_stress = stress;
      r.strain_at_peak = strain;
    }
    if (sample_every > 0 && n % sample_every == 0)
      r.curve.emplace_back(strain, stress);
    s = next;
  }
  r.fracture_time = s.fractured ? s.fracture_time : -1.0;
  return r;
}

} // namespace geocomp::kinetic
