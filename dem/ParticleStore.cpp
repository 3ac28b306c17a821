#include "dem/ParticleStore.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
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

namespace {
/// a[k] = a[order[k]] for every k, through `scratch` (n elements of the largest type).
template <class T>
void gather(std::vector<T>& a, const std::vector<Index>& order, unsigned char* scratch, int threads)
{
  // Moved by bytes: plain numbers, or Eigen's fixed-size types, which hold only their
  // coefficients (as the checkpoints and the batched kernels read them too).
  const std::int64_t n = std::int64_t(a.size());
  unsigned char* const base = reinterpret_cast<unsigned char*>(a.data());
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < n; ++k) std::memcpy(scratch + k * sizeof(T), base + order[k] * sizeof(T), sizeof(T));
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < n; ++k) std::memcpy(base + k * sizeof(T), scratch + k * sizeof(T), sizeof(T));
  }
}
}  // namespace

void ParticleStore::permute(const std::vector<Index>& order, int threads)
{
  const std::size_t n = size();
  if (order.size() != n) throw std::invalid_argument("ParticleStore::permute: wrong size");
  constexpr std::size_t kLargest = std::max({sizeof(Vec3), sizeof(Quat), sizeof(double), sizeof(ParticleId)});
  const std::unique_ptr<unsigned char[]> scratch(new unsigned char[n * kLargest]);
  for (auto* a : {&x, &v, &omega, &force, &torque}) gather(*a, order, scratch.get(), threads);
  gather(orientation, order, scratch.get(), threads);
  for (auto* a : {&radius, &mass, &inv_mass, &inv_inertia}) gather(*a, order, scratch.get(), threads);
  gather(id, order, scratch.get(), threads);
  gather(body, order, scratch.get(), threads);
  gather(flags, order, scratch.get(), threads);
}

std::size_t ParticleStore::memory_bytes() const
{
  return (x.capacity() + v.capacity() + omega.capacity() + force.capacity() + torque.capacity()) * sizeof(Vec3)
       + orientation.capacity() * sizeof(Quat)
       + (radius.capacity() + mass.capacity() + inv_mass.capacity() + inv_inertia.capacity()) * sizeof(double)
       + id.capacity() * sizeof(ParticleId) + body.capacity() * sizeof(std::int32_t)
       + flags.capacity() * sizeof(std::uint32_t);
}

}  // namespace geocomp::dem
