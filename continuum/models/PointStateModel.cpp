#include "continuum/models/PointStateModel.h"

namespace geocomp::continuum {

PlasticHistory PointStateModel::initial_history(const Vector6 &initial_strain) const
{
  PlasticHistory h;
  h.state = initial_state(initial_strain);
  return h;
}

MaterialPointUpdate PointStateModel::update(const Vector6 &total_strain, const PlasticHistory &old) const
{
  if (!old.state)
    throw std::logic_error(name() + ": a point-state model needs the history of initial_history(), got none");
  PointStateUpdate u = advance(total_strain, old.state);
  MaterialPointUpdate out;
  out.stress = u.stress;
  out.tangent = u.tangent;
  out.history.state = std::move(u.state);
  return out;
}

Matrix9 jaumann_spatial_tangent(const Matrix6 &tangent, const Matrix3 &tau, double jacobian)
{
  const auto delta = [](int a, int b) { return a == b ? 1.0 : 0.0; };
  Matrix9 a;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      // C : sym(e_k (x) e_l), the symmetric part of the unit perturbation.
      Matrix3 unit = Matrix3::Zero();
      unit(k, l) += 0.5;
      unit(l, k) += 0.5;
      const Matrix3 material = jacobian * from_mandel(tangent * to_mandel(unit));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          a(pair_index(i, j), pair_index(k, l)) =
            material(i, j) +
            0.5 * (delta(i, k) * tau(j, l) - delta(i, l) * tau(j, k) - tau(i, k) * delta(j, l) +
                   tau(i, l) * delta(j, k)) +
            tau(i, j) * delta(k, l) - tau(i, l) * delta(j, k);
    }
  return a;
}

} // namespace geocomp::continuum
