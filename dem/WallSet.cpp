#include "dem/WallSet.h"

#include <algorithm>
#include <stdexcept>

namespace geocomp::dem {

std::size_t WallSet::add(const PlaneWall& w)
{
  PlaneWall c = w;
  const double len = c.normal.norm();
  if (!(len > 0.0)) throw std::invalid_argument("DemSystem::add_wall: zero normal");
  if (!(c.mu >= 0.0)) throw std::invalid_argument("DemSystem::add_wall: friction must be >= 0");
  c.normal /= len;
  if (c.bounded()) {  // a rectangle (S4's split box): its axis must lie in the plane
    c.axis -= c.axis.dot(c.normal) * c.normal;
    if (!(c.axis.norm() > 1e-12) || !(c.half_u > 0.0) || !(c.half_v > 0.0))
      throw std::invalid_argument("DemSystem::add_wall: a bounded wall needs an in-plane axis and positive half-sizes");
    c.axis.normalize();
  }
  walls_.push_back(c);
  return walls_.size() - 1;
}

void WallSet::remember_forces()
{
  force_old_.resize(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) force_old_[w] = walls_[w].force;
}

void WallSet::move(double dt)
{
  for (PlaneWall& w : walls_) w.point += dt * w.velocity;
}

void WallSet::add_work(double dt, EnergyLedger& losses)
{
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    PlaneWall& w = walls_[k];
    // The particles receive -F from the wall; trapezoidal rule over the step.
    const double dw = -0.5 * (force_old_[k] + w.force).dot(w.velocity) * dt;
    w.work += dw;
    losses.wall_work += dw;
  }
}

bool WallSet::all_unbounded() const
{
  return std::none_of(walls_.begin(), walls_.end(), [](const PlaneWall& w) { return w.bounded(); });
}

void WallSet::pack(PairBatchArgs& a)
{
  const std::size_t nw = walls_.size();
  packed_.resize(10 * nw);
  double* const p = packed_.data();
  for (std::size_t k = 0; k < nw; ++k)
    for (int d = 0; d < 3; ++d) {
      p[3 * k + d] = walls_[k].point[d];
      p[3 * (nw + k) + d] = walls_[k].normal[d];
      p[3 * (2 * nw + k) + d] = walls_[k].velocity[d];
    }
  for (std::size_t k = 0; k < nw; ++k) p[9 * nw + k] = walls_[k].mu;
  a.wall_point = p;
  a.wall_normal = p + 3 * nw;
  a.wall_velocity = p + 6 * nw;
  a.wall_mu = p + 9 * nw;
}

std::size_t WallSet::memory_bytes() const
{
  return walls_.capacity() * sizeof(PlaneWall) + force_old_.capacity() * sizeof(Vec3) +
         terms_.capacity() * sizeof(Term);
}

}  // namespace geocomp::dem
