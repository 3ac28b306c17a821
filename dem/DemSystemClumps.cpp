// DemSystem: clumps (rigid clusters of member spheres), see ClumpSet.h for the scheme.
#include "dem/DemSystem.h"
#include "dem/LocalDamping.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

std::size_t DemSystem::add_clump(const std::vector<ClumpMember>& members, double density, const Vec3& v,
                                 const Vec3& omega, double voxel)
{
  if (!(density > 0.0)) throw std::invalid_argument("DemSystem::add_clump: density must be positive");
  const ClumpMassProperties props = voxel_mass_properties(members, voxel);
  const std::size_t c = clumps_.size();
  const double inv_M = 1.0 / (density * props.volume);
  std::vector<ParticleId> ids;
  ids.reserve(members.size());
  for (const ClumpMember& m : members) {
    const ParticleId id = add_sphere(m.centre, m.radius, density);
    const Index k = index_of_[id];
    store_.flags[k] |= flag::member;
    store_.body[k] = std::int32_t(c);
    store_.inv_mass[k] = inv_M;   // m* of a member contact is the clumps' effective mass
    store_.inv_inertia[k] = 0.0;  // members do not turn on their own
    ids.push_back(id);
  }
  clumps_.add(props, density, members, ids);
  clumps_.v[c] = v;
  clumps_.set_angular_velocity(c, omega);
  place_members(c, true);
  rebuild_requested_ = true;
  invalidate();
  return c;
}

std::vector<ParticleId> DemSystem::clump_members(std::size_t c) const
{
  if (c >= clumps_.size()) throw std::out_of_range("DemSystem::clump_members: no such clump");
  return std::vector<ParticleId>(clumps_.member_id.begin() + clumps_.member_offset[c],
                                 clumps_.member_id.begin() + clumps_.member_offset[c + 1]);
}

void DemSystem::set_clump_velocity(std::size_t c, const Vec3& v)
{
  clumps_.v.at(c) = v;
  place_members(c, false);
  invalidate();
}

void DemSystem::set_clump_angular_velocity(std::size_t c, const Vec3& omega)
{
  if (c >= clumps_.size()) throw std::out_of_range("DemSystem::set_clump_angular_velocity: no such clump");
  clumps_.set_angular_velocity(c, omega);
  place_members(c, false);
  invalidate();
}

void DemSystem::place_members(std::size_t c, bool positions)
{
  const Eigen::Matrix3d R = clumps_.q[c].toRotationMatrix();
  const Vec3 w = clumps_.angular_velocity(c);
  const Vec3& xg = clumps_.x[c];
  for (std::uint32_t m = clumps_.member_offset[c]; m < clumps_.member_offset[c + 1]; ++m) {
    const Index k = index_of_[clumps_.member_id[m]];
    if (positions) {
      store_.x[k] = xg + R * clumps_.member_body[m];
      store_.orientation[k] = clumps_.q[c];
    }
    store_.v[k] = clumps_.v[c] + w.cross(store_.x[k] - xg);  // rigid velocity of the member centre
    store_.omega[k] = w;
  }
}

void DemSystem::gather_clump_loads()
{
  for (std::size_t c = 0; c < clumps_.size(); ++c) {
    Vec3 f = clumps_.mass[c] * gravity_, t = Vec3::Zero();
    for (std::uint32_t m = clumps_.member_offset[c]; m < clumps_.member_offset[c + 1]; ++m) {
      const Index k = index_of_[clumps_.member_id[m]];
      const Vec3 fc = store_.force[k] - store_.mass[k] * gravity_;  // contacts only
      f += fc;
      t += (store_.x[k] - clumps_.x[c]).cross(fc) + store_.torque[k];
    }
    clumps_.force[c] = f;
    clumps_.torque[c] = t;
  }
}

void DemSystem::kick_clump(std::size_t c, double dt, double& loss)
{
  Vec3 f = clumps_.force[c], t = clumps_.torque[c];
  const double lambda = integrator_.local_damping();
  if (lambda > 0.0) {
    loss += 0.5 * dt * local_damping(f, clumps_.v[c], lambda);
    loss += 0.5 * dt * local_damping(t, clumps_.angular_velocity(c), lambda);
  }
  clumps_.kick(c, 0.5 * dt, f, t);
}

double DemSystem::kick_drift_clumps(double dt)
{
  const std::vector<Vec3>& x_ref = search_.reference_positions();
  double max_d2 = 0.0, loss = 0.0;
  for (std::size_t c = 0; c < clumps_.size(); ++c) {
    kick_clump(c, dt, loss);
    clumps_.drift(c, dt);
    place_members(c, true);
    if (x_ref.size() == store_.size())
      for (std::uint32_t m = clumps_.member_offset[c]; m < clumps_.member_offset[c + 1]; ++m) {
        const Index k = index_of_[clumps_.member_id[m]];
        max_d2 = std::max(max_d2, (store_.x[k] - x_ref[k]).squaredNorm());
      }
  }
  energy_.add_local(loss);
  return max_d2;
}

void DemSystem::kick_clumps(double dt)
{
  double loss = 0.0;
  for (std::size_t c = 0; c < clumps_.size(); ++c) {
    kick_clump(c, dt, loss);
    place_members(c, false);
  }
  energy_.add_local(loss);
}

}  // namespace geocomp::dem
