#include "dem/ParticleStore.h"

#include <stdexcept>

namespace geocomp::dem {

Index ParticleStore::add_sphere(ParticleId pid, const Vec3& pos, double r, double m)
{
  if (!(r > 0.0) || !(m > 0.0))
    throw std::invalid_argument("ParticleStore: radius and mass must be positive");
  x.push_back(pos);
  v.push_back(Vec3::Zero());
  omega.push_back(Vec3::Zero());
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  orientation.push_back(Quat::Identity());
  radius.push_back(r);
  mass.push_back(m);
  inv_mass.push_back(1.0 / m);
  inv_inertia.push_back(1.0 / (0.4 * m * r * r));  // sphere: I = 2/5 m R^2
  id.push_back(pid);
  body.push_back(kOwnBody);
  flags.push_back(0u);
  return Index(x.size() - 1);
}

void ParticleStore::reserve(std::size_t n)
{
  x.reserve(n); v.reserve(n); omega.reserve(n); force.reserve(n); torque.reserve(n);
  orientation.reserve(n);
  radius.reserve(n); mass.reserve(n); inv_mass.reserve(n); inv_inertia.reserve(n);
  id.reserve(n); body.reserve(n); flags.reserve(n);
}

void ParticleStore::set_fixed(Index k, bool fixed)
{
  if (fixed) {
    flags[k] |= flag::fixed;
    inv_mass[k] = 0.0;
    inv_inertia[k] = 0.0;
  } else {
    flags[k] &= ~flag::fixed;
    inv_mass[k] = 1.0 / mass[k];
    inv_inertia[k] = 1.0 / (0.4 * mass[k] * radius[k] * radius[k]);
  }
}

void ParticleStore::remove(Index k)
{
  if (k >= size()) throw std::out_of_range("ParticleStore::remove: no such index");
  const std::size_t last = size() - 1;
  auto move_last = [&](auto& a) {
    a[k] = a[last];
    a.pop_back();
  };
  move_last(x); move_last(v); move_last(omega); move_last(force); move_last(torque);
  move_last(orientation);
  move_last(radius); move_last(mass); move_last(inv_mass); move_last(inv_inertia);
  move_last(id); move_last(body); move_last(flags);
}

void ParticleStore::permute(const std::vector<Index>& order)
{
  const std::size_t n = size();
  if (order.size() != n) throw std::invalid_argument("ParticleStore::permute: wrong size");
  visited_.assign(n, 0);
  for (std::size_t start = 0; start < n; ++start) {
    if (visited_[start] || order[start] == start) {
      visited_[start] = 1;
      continue;
    }
    // Walk the cycle start <- order[start] <- order[order[start]] ... back to start.
    const Vec3 tx = x[start], tv = v[start], tw = omega[start], tf = force[start], tt = torque[start];
    const Quat tq = orientation[start];
    const double tr = radius[start], tm = mass[start], tim = inv_mass[start], tii = inv_inertia[start];
    const ParticleId tid = id[start];
    const std::int32_t tb = body[start];
    const std::uint32_t tfl = flags[start];
    std::size_t dst = start;
    for (;;) {
      visited_[dst] = 1;
      const std::size_t src = order[dst];
      if (src == start) {
        x[dst] = tx; v[dst] = tv; omega[dst] = tw; force[dst] = tf; torque[dst] = tt;
        orientation[dst] = tq;
        radius[dst] = tr; mass[dst] = tm; inv_mass[dst] = tim; inv_inertia[dst] = tii;
        id[dst] = tid; body[dst] = tb; flags[dst] = tfl;
        break;
      }
      x[dst] = x[src]; v[dst] = v[src]; omega[dst] = omega[src];
      force[dst] = force[src]; torque[dst] = torque[src];
      orientation[dst] = orientation[src];
      radius[dst] = radius[src]; mass[dst] = mass[src];
      inv_mass[dst] = inv_mass[src]; inv_inertia[dst] = inv_inertia[src];
      id[dst] = id[src]; body[dst] = body[src]; flags[dst] = flags[src];
      dst = src;
    }
  }
}

std::size_t ParticleStore::memory_bytes() const
{
  return (x.capacity() + v.capacity() + omega.capacity() + force.capacity() + torque.capacity()) * sizeof(Vec3)
       + orientation.capacity() * sizeof(Quat)
       + (radius.capacity() + mass.capacity() + inv_mass.capacity() + inv_inertia.capacity()) * sizeof(double)
       + id.capacity() * sizeof(ParticleId) + body.capacity() * sizeof(std::int32_t)
       + flags.capacity() * sizeof(std::uint32_t) + visited_.capacity();
}

}  // namespace geocomp::dem
