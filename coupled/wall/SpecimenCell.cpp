#include "coupled/wall/SpecimenCell.h"

#include "dem/periodic/PeriodicPreparation.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geocomp::coupled {

SpecimenCell cell_of_specimen(const dem::DemSystem &specimen, const RveGrains &g, const RvePreparationSettings &s,
                              const RveProtocol &k)
{
  if (specimen.n_walls() < 6)
    throw std::invalid_argument("cell_of_specimen: needs the six walls of the specimen's box");
  dem::Packing packing;
  packing.density = g.density;
  for (int a = 0; a < 3; ++a) {
    packing.box_min[a] = specimen.wall(2 * a).point[a];
    packing.box_max[a] = specimen.wall(2 * a + 1).point[a];
  }
  for (dem::ParticleId id = 0; id < specimen.n_particles(); ++id) {
    packing.position.push_back(specimen.position(id));
    packing.radius.push_back(specimen.particles().radius[specimen.index_of(id)]);
  }
  dem::PeriodicCell::Parameters cp;
  cp.time_step = specimen.time_step();
  cp.friction = g.friction;
  cp.local_damping = s.local_damping;
  SpecimenCell out{dem::cell_from_packing(packing, g.law, cp), 0, 0.0};
  const double volume0 = out.cell.cell().volume();
  const dem::CompressionResult c = compress_rve(out.cell, s.pressure, k);
  if (!c.converged)
    throw std::runtime_error("cell_of_specimen: the isotropic compression to " + std::to_string(s.pressure) +
                             " Pa did not converge in " + std::to_string(c.steps) + " steps");
  out.compression_steps = c.steps;
  out.volume_change = std::log(out.cell.cell().volume() / volume0);
  return out;
}

} // namespace geocomp::coupled
