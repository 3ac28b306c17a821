#include "continuum/kinetic/PlaneStress.h"

#include <cmath>

namespace geocomp::kinetic {

KineticState plane_stress_step(const KineticNikolaevsky &model, const KineticState &old,
                               const Eigen::Vector3d &in_plane, double dt, double tolerance)
{
  const auto &el = model.elasticity();
  const double lambda = el.lame_lambda(), G = el.shear_modulus();
  Vector6 d_eps = Vector6::Zero();
  d_eps(0) = in_plane(0);
  d_eps(1) = in_plane(1);
  d_eps(5) = in_plane(2) / std::sqrt(2.0); // Mandel: sqrt2 * eps_xy = gamma_xy / sqrt2
  KineticState result;
  const double scale = old.stress.cwiseAbs().maxCoeff() + el.youngs_modulus() * in_plane.cwiseAbs().maxCoeff();
  auto sigma_zz = [&](double ezz) {
    d_eps(2) = ezz;
    result = model.step(old, d_eps, dt);
    return result.stress(2);
  };
  const double guess = -lambda / (lambda + 2.0 * G) * (in_plane(0) + in_plane(1)) +
                       (old.stress(2) != 0.0 ? -old.stress(2) / (lambda + 2.0 * G) : 0.0);
  const double root = monotone_root(sigma_zz, guess, lambda + 2.0 * G, tolerance * scale + 1.0);
  if (d_eps(2) != root)
    sigma_zz(root);
  return result;
}

} // namespace geocomp::kinetic
