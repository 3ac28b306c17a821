#include "coupled/wall/PackingState.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::coupled {

double sampled_solid_fraction(const std::vector<dem::Vec3> &x, const std::vector<double> &r, const dem::Vec3 &lo,
                              const dem::Vec3 &hi, double h)
{
  if (!(h > 0.0) || !((hi - lo).minCoeff() > 0.0) || x.size() != r.size())
    throw std::invalid_argument("sampled_solid_fraction: needs a box with hi > lo, a spacing h > 0 and a radius per centre");
  // The spheres that reach into the box, binned by centre in cells of edge r_max: a point
  // inside a sphere has that sphere's centre within r_max, i.e. in the 3 x 3 x 3 cells about it.
  double r_max = 0.0;
  for (double ri : r)
    r_max = std::max(r_max, ri);
  if (!(r_max > 0.0))
    return 0.0;
  const dem::Vec3 origin = lo - dem::Vec3::Constant(r_max);
  int bins[3];
  for (int a = 0; a < 3; ++a)
    bins[a] = std::max(1, int(std::ceil((hi[a] - lo[a] + 2.0 * r_max) / r_max)));
  auto bin_of = [&](double coordinate, int a) { return std::clamp(int((coordinate - origin[a]) / r_max), 0, bins[a] - 1); };
  auto flat = [&](int i, int j, int k) { return (std::size_t(k) * std::size_t(bins[1]) + std::size_t(j)) * std::size_t(bins[0]) + std::size_t(i); };
  std::vector<std::vector<std::size_t>> cell(std::size_t(bins[0]) * std::size_t(bins[1]) * std::size_t(bins[2]));
  for (std::size_t p = 0; p < x.size(); ++p) {
    const dem::Vec3 nearest = x[p].cwiseMax(lo).cwiseMin(hi);
    if ((x[p] - nearest).norm() < r[p])
      cell[flat(bin_of(x[p][0], 0), bin_of(x[p][1], 1), bin_of(x[p][2], 2))].push_back(p);
  }
  int points[3];
  for (int a = 0; a < 3; ++a)
    points[a] = std::max(1, int(std::floor((hi[a] - lo[a]) / h)));
  std::size_t inside = 0;
  for (int k = 0; k < points[2]; ++k)
    for (int j = 0; j < points[1]; ++j)
      for (int i = 0; i < points[0]; ++i) {
        const dem::Vec3 q = lo + h * dem::Vec3(i + 0.5, j + 0.5, k + 0.5);
        const int b[3] = {bin_of(q[0], 0), bin_of(q[1], 1), bin_of(q[2], 2)};
        bool covered = false;
        for (int dk = -1; dk <= 1 && !covered; ++dk)
          for (int dj = -1; dj <= 1 && !covered; ++dj)
            for (int di = -1; di <= 1 && !covered; ++di) {
              const int bi = b[0] + di, bj = b[1] + dj, bk = b[2] + dk;
              if (bi < 0 || bj < 0 || bk < 0 || bi >= bins[0] || bj >= bins[1] || bk >= bins[2])
                continue;
              for (std::size_t p : cell[flat(bi, bj, bk)])
                if ((x[p] - q).squaredNorm() < r[p] * r[p]) {
                  covered = true;
                  break;
                }
            }
        inside += covered ? 1 : 0;
      }
  return double(inside) / (double(points[0]) * double(points[1]) * double(points[2]));
}

PackingState packing_state(const dem::DemSystem &specimen, double margin)
{
  if (specimen.n_walls() < 6 || specimen.n_particles() == 0)
    throw std::invalid_argument("packing_state: needs a specimen with particles in the six walls of its box");
  PackingState s;
  s.particles = specimen.n_particles();
  std::vector<dem::Vec3> x(s.particles);
  std::vector<double> r(s.particles);
  double solid = 0.0;
  for (dem::ParticleId id = 0; id < s.particles; ++id) {
    const dem::Index i = specimen.index_of(id);
    x[id] = specimen.particles().x[i];
    r[id] = specimen.particles().radius[i];
    s.mean_diameter += 2.0 * r[id];
    solid += 4.0 / 3.0 * M_PI * r[id] * r[id] * r[id];
  }
  s.mean_diameter /= double(s.particles);
  dem::Vec3 lo, hi;
  for (int a = 0; a < 3; ++a) {
    lo[a] = specimen.wall(2 * a).point[a];
    hi[a] = specimen.wall(2 * a + 1).point[a];
  }
  const double volume = (hi - lo).prod();
  s.edge = std::cbrt(volume) / s.mean_diameter;
  s.packing_fraction = solid / volume;

  std::vector<unsigned> contacts(s.particles, 0);
  std::size_t pairs = 0;
  for (const dem::ContactState &c : specimen.export_contact_state())
    if (!c.wall && c.overlap > 0.0) {
      ++contacts[c.i];
      ++contacts[c.j];
      ++pairs;
    }
  s.coordination = 2.0 * double(pairs) / double(s.particles);

  const dem::Vec3 inner_lo = lo + dem::Vec3::Constant(margin * s.mean_diameter);
  const dem::Vec3 inner_hi = hi - dem::Vec3::Constant(margin * s.mean_diameter);
  if (!((inner_hi - inner_lo).minCoeff() > 0.0))
    throw std::invalid_argument("packing_state: the box is narrower than twice the margin");
  std::size_t inner_contacts = 0;
  for (dem::ParticleId id = 0; id < s.particles; ++id)
    if ((x[id].array() > inner_lo.array()).all() && (x[id].array() < inner_hi.array()).all()) {
      ++s.inner_particles;
      inner_contacts += contacts[id];
    }
  s.inner_coordination = s.inner_particles > 0 ? double(inner_contacts) / double(s.inner_particles) : 0.0;
  s.inner_packing_fraction = sampled_solid_fraction(x, r, inner_lo, inner_hi, s.mean_diameter / 20.0);
  return s;
}

PackingState packing_state(const dem::PeriodicCell &cell)
{
  PackingState s;
  s.particles = cell.n_particles();
  for (double r : cell.particles().radius)
    s.mean_diameter += 2.0 * r;
  s.mean_diameter /= double(std::max<std::size_t>(s.particles, 1));
  s.edge = std::cbrt(cell.cell().volume()) / s.mean_diameter;
  s.packing_fraction = cell.packing_fraction();
  s.coordination = cell.coordination();
  s.inner_particles = s.particles;
  s.inner_packing_fraction = s.packing_fraction;
  s.inner_coordination = s.coordination;
  return s;
}

} // namespace geocomp::coupled
