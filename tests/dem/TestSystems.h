// Small specimens shared by the DEM tests.
#pragma once

#include "dem/DemSystem.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace geocomp::dem::test {

/// Linear spring-dashpot with k_n in N/m, restitution e, k_t = kt_ratio k_n, unclamped
/// unless asked.
inline LinearSpringDashpot linear_law(double k_n, double e, double kt_ratio = 2.0 / 7.0, bool clamp = false)
{
  return LinearSpringDashpot(LinearNormal::with_stiffness(k_n, e, clamp), LinearTangential::with_ratio(kt_ratio));
}

/// n equal spheres of radius R on a jittered cubic lattice with spacing 2.05 R in a box
/// of six walls, random velocities of size v_scale (fixed seed).
inline void fill_box(DemSystem& sys, int per_edge, double R, double v_scale, unsigned seed, double mu_wall = 0.0)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double a = 2.05 * R;
  for (int i = 0; i < per_edge; ++i)
    for (int j = 0; j < per_edge; ++j)
      for (int k = 0; k < per_edge; ++k) {
        const Vec3 x = Vec3(R + a * i, R + a * j, R + a * k) + 0.02 * R * Vec3(u(rng), u(rng), u(rng));
        const Vec3 v = v_scale * Vec3(u(rng), u(rng), u(rng));
        const Vec3 w = (v_scale / R) * Vec3(u(rng), u(rng), u(rng));
        sys.add_sphere(x, R, 2650.0, v, w);
      }
  const double L = a * (per_edge - 1) + 2.0 * R;
  sys.add_box(Vec3::Zero(), Vec3::Constant(L), mu_wall);
}

/// The spheres and walls of `ref` (spheres of radius R and density 2650, as fill_box
/// makes them) added to `sys` with their ids in reverse order: the id order of nearly
/// every pair is then the reverse of its storage order.
inline void add_renumbered_backwards(DemSystem& sys, const DemSystem& ref, double R)
{
  for (ParticleId id = ParticleId(ref.n_particles()); id-- > 0;)
    sys.add_sphere(ref.position(id), R, 2650.0, ref.velocity(id), ref.angular_velocity(id));
  for (std::size_t w = 0; w < ref.n_walls(); ++w) sys.add_wall(ref.wall(w));
}

/// 8^3 compressed frictional spheres (R = 10 mm, mu = 0.4, the walls moving in at
/// 0.05 m/s, dt a tenth of sqrt(m/k) at k = 1e5 N/m) under `law`: about 1 100 pair slots,
/// five blocks of 256, so two to four workers each get slots and the bodies where their
/// ranges meet are shared.
inline void compressed_box(DemSystem& sys, const ContactModel& law, bool batched, int threads)
{
  sys.set_contact_model(law);
  sys.set_friction(0.4);
  sys.set_batched_pairs(batched);
  fill_box(sys, 8, 0.01, 0.3, 7u, 0.2);
  for (std::size_t w = 0; w < 6; ++w) sys.set_wall_velocity(w, 0.05 * sys.wall(w).normal);
  const double m = 4.0 / 3.0 * M_PI * 1e-6 * 2650.0;
  sys.set_time_step(0.1 * std::sqrt(m / 1e5));
  sys.set_num_threads(threads);
}

/// Positions, velocities, spins, forces and orientations by particle id, then (with
/// `contacts`) every contact's overlap and tangential history: a run's state as raw doubles.
inline std::vector<double> state_bits(const DemSystem& sys, bool contacts = false)
{
  std::vector<double> s;
  for (ParticleId id = 0; id < sys.n_particles(); ++id) {
    for (const Vec3& v : {sys.position(id), sys.velocity(id), sys.angular_velocity(id), sys.force(id)})
      s.insert(s.end(), v.data(), v.data() + 3);
    const Quat q = sys.orientation(id);
    s.insert(s.end(), q.coeffs().data(), q.coeffs().data() + 4);
  }
  if (contacts)
    for (const ContactState& c : sys.export_contact_state()) {
      s.push_back(c.overlap);
      s.insert(s.end(), c.shear.data(), c.shear.data() + 3);
    }
  return s;
}

/// Same length and the same bits (memcmp: -0.0 and NaN payloads count).
inline bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace geocomp::dem::test
