#include "dem/ClumpSet.h"

#include "dem/RigidRotation.h"

#include <stdexcept>

namespace geocomp::dem {

std::size_t ClumpSet::add(const ClumpMassProperties& props, double density, const std::vector<ClumpMember>& members,
                          const std::vector<ParticleId>& ids)
{
  if (!(density > 0.0)) throw std::invalid_argument("ClumpSet::add: density must be positive");
  if (members.size() != ids.size() || members.empty()) throw std::invalid_argument("ClumpSet::add: one id per member");
  const double m = density * props.volume;
  x.push_back(props.centroid);
  v.push_back(Vec3::Zero());
  L_body.push_back(Vec3::Zero());
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  Quat q0(props.axes);  // body (principal) frame -> world
  q0.normalize();
  q.push_back(q0);
  mass.push_back(m);
  inv_mass.push_back(1.0 / m);
  const Vec3 I = density * props.principal_moments;
  inertia.push_back(I);
  inv_inertia.push_back(I.cwiseInverse());
  for (std::size_t k = 0; k < members.size(); ++k) {
    member_id.push_back(ids[k]);
    member_body.push_back(props.axes.transpose() * (members[k].centre - props.centroid));  // S3 eq. (17)
  }
  member_offset.push_back(std::uint32_t(member_id.size()));
  return x.size() - 1;
}

Vec3 ClumpSet::angular_velocity(std::size_t c) const
{
  return q[c] * Vec3(L_body[c].cwiseProduct(inv_inertia[c]));
}

void ClumpSet::set_angular_velocity(std::size_t c, const Vec3& omega)
{
  L_body[c] = inertia[c].cwiseProduct(q[c].conjugate() * omega);
}

double ClumpSet::kinetic_energy(std::size_t c) const
{
  return 0.5 * mass[c] * v[c].squaredNorm() + 0.5 * L_body[c].dot(L_body[c].cwiseProduct(inv_inertia[c]));
}

void ClumpSet::kick(std::size_t c, double half_dt, const Vec3& f, const Vec3& t)
{
  v[c] += (half_dt * inv_mass[c]) * f;
  L_body[c] += half_dt * (q[c].conjugate() * t);  // torque in the body frame
}

void ClumpSet::drift(std::size_t c, double dt)
{
  x[c] += dt * v[c];
  free_rotation_step(q[c], L_body[c], inv_inertia[c], dt);
}

std::size_t ClumpSet::memory_bytes() const
{
  return (x.capacity() + v.capacity() + L_body.capacity() + force.capacity() + torque.capacity() +
          inertia.capacity() + inv_inertia.capacity() + member_body.capacity()) * sizeof(Vec3) +
         q.capacity() * sizeof(Quat) + (mass.capacity() + inv_mass.capacity()) * sizeof(double) +
         member_offset.capacity() * sizeof(std::uint32_t) + member_id.capacity() * sizeof(ParticleId);
}

}  // namespace geocomp::dem
