#include "MidPlane.h"
#include "Mpi.h"

#include "common/AtomicFile.h"
#include "common/Hdf5.h"

namespace geocomp::cli {

namespace fs = std::filesystem;

std::string midplane_file(const std::string &engine) { return engine + "-midplane.h5"; }

// Main-path samples of the last stage only, each once: a sample not later than the last
// recorded one (a state the runner came back to) is not recorded again.
void CubeSectionRecorder::operator()(const RunProgress &p)
{
  if (p.branch != 0 || p.stage != p.stage_count - 1 || !p.sample)
    return;
  if (!times_.empty() && !(p.sample->time > times_.back()))
    return;
  continuum::MidPlaneSample plane = cube_.mid_plane(); // collective
  if (rank_in(comm_) != 0)
    return;
  times_.push_back(p.sample->time);
  planes_.push_back(std::move(plane));
}

void CubeSectionRecorder::write(const fs::path &dir) const
{
  if (rank_in(comm_) != 0 || planes_.empty())
    return;
  fs::create_directories(dir);
  write_atomically(dir / midplane_file(engine_), [this](const fs::path &tmp) {
    const h5::Handle f = h5::create_file(tmp);
    const std::size_t n = planes_.front().x.size(), m = planes_.size();
    h5::write(f.id(), "x", planes_.front().x, {hsize_t(n)}, "m");
    h5::write(f.id(), "z", planes_.front().z, {hsize_t(n)}, "m");
    h5::write(f.id(), "time", times_, {hsize_t(m)}, "s");
    std::vector<double> ux, uz, kappa;
    for (const auto &plane : planes_) {
      ux.insert(ux.end(), plane.ux.begin(), plane.ux.end());
      uz.insert(uz.end(), plane.uz.begin(), plane.uz.end());
      kappa.insert(kappa.end(), plane.kappa.begin(), plane.kappa.end());
    }
    h5::write(f.id(), "u_x", ux, {hsize_t(m), hsize_t(n)}, "m");
    h5::write(f.id(), "u_z", uz, {hsize_t(m), hsize_t(n)}, "m");
    h5::write(f.id(), "kappa", kappa, {hsize_t(m), hsize_t(n)}, "1");
  });
}

std::optional<compare::SectionSeries> read_cube_section(const fs::path &dir, const std::string &engine,
                                                        const std::string &label,
                                                        const continuum::CubeParameters &mesh)
{
  const fs::path file = dir / midplane_file(engine);
  if (!fs::exists(file))
    return std::nullopt;
  const h5::Handle f = h5::open_file(file);
  if (!h5::exists(f.id(), "time")) // written by an older geocomp: the end state only
    return std::nullopt;
  compare::SectionSeries s;
  s.engine = label;
  s.x = h5::read_doubles(f.id(), "x");
  s.z = h5::read_doubles(f.id(), "z");
  s.times = h5::read_doubles(f.id(), "time");
  const std::vector<double> ux = h5::read_doubles(f.id(), "u_x"), uz = h5::read_doubles(f.id(), "u_z");
  const std::size_t n = s.x.size();
  if (n == 0 || ux.size() != n * s.times.size() || uz.size() != ux.size())
    throw std::runtime_error(file.string() + ": u_x and u_z are not time x points");
  for (std::size_t k = 0; k < s.times.size(); ++k) {
    s.ux.emplace_back(n);
    s.uz.emplace_back(n);
    for (std::size_t i = 0; i < n; ++i) {
      s.ux[k][i] = ux[k * n + i] - ux[i];
      s.uz[k][i] = uz[k * n + i] - uz[i];
    }
  }
  const Vector3 edges = mesh.edges();
  const std::array<unsigned, 3> cells = mesh.cells();
  s.centre_x = 0.5 * edges[0];
  s.centre_z = 0.5 * edges[2];
  const double spacing_x = edges[0] / (3.0 * std::max(1u, cells[0]));
  const double spacing_z = edges[2] / (3.0 * std::max(1u, cells[2]));
  s.strain_radius = 1.5 * std::max(spacing_x, spacing_z);
  s.marker = 0.5 * spacing_x;
  s.marker_z = 0.5 * spacing_z;
  s.tiles = true;
  return s;
}

} // namespace geocomp::cli
