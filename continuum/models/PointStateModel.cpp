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

} // namespace geocomp::continuum
