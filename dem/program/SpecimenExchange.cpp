#include "dem/program/SpecimenExchange.h"

#include <stdexcept>

namespace geocomp::dem {

bool is_lammps_data_file(const std::filesystem::path &file)
{
  return file.extension() == ".data";
}

Packing read_packing_file(const std::filesystem::path &file)
{
  return is_lammps_data_file(file) ? read_lammps_data(file) : read_xyzr(file);
}

void write_packing_file(const std::filesystem::path &file, const Packing &packing)
{
  if (is_lammps_data_file(file))
    write_lammps_data(file, packing);
  else
    write_xyzr(file, packing);
}

Packing packing_of(const DemSystem &system, double density)
{
  if (system.n_walls() < 6)
    throw std::invalid_argument("packing_of: the specimen has " + std::to_string(system.n_walls()) +
                                " walls, expected the six faces of its box");
  Packing p;
  p.density = density;
  for (int a = 0; a < 3; ++a) { // walls 2a (lower face) and 2a + 1 (upper face) of add_box()
    p.box_min[a] = system.wall(2 * a).point[a];
    p.box_max[a] = system.wall(2 * a + 1).point[a];
  }
  p.position.reserve(system.n_particles());
  p.radius.reserve(system.n_particles());
  const ParticleStore &s = system.particles();
  for (ParticleId id = 0; id < system.n_particles(); ++id) {
    const Index i = system.index_of(id);
    p.position.push_back(s.x[i]);
    p.radius.push_back(s.radius[i]);
  }
  return p;
}

} // namespace geocomp::dem
