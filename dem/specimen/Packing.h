#pragma once
// A packing: spheres in an axis-aligned box, the plain data a specimen starts from and
// the unit of exchange with other tools. The DEM engine loads a Packing into its
// particle arrays; importers and exporters read and write other tools' formats:
//   - text "x y z r" per line, box in a '#' header line (the format of bench/*.xyzr);
//   - LAMMPS/LIGGGHTS data files with atom_style granular ("id type diameter density x y z"),
//     and their Velocities section ("id vx vy vz wx wy wz") when there is one.
#include <Eigen/Dense>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::dem {

/// A packing file that cannot be read: which file, which line, what was expected.
struct PackingFileError : std::runtime_error {
  PackingFileError(const std::string &file, int line, const std::string &message)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + message) {}
};

struct Packing {
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d box_max = Eigen::Vector3d::Ones();
  std::vector<Eigen::Vector3d> position;
  std::vector<double> radius;
  double density = 2650.0; ///< [kg/m^3], one material per packing
  /// [m/s] and [1/s], by particle, when the file gives them (a LAMMPS data file's
  /// Velocities section); empty otherwise (at rest).
  std::vector<Eigen::Vector3d> velocity, angular_velocity;

  std::size_t size() const { return radius.size(); }
  double box_volume() const { return (box_max - box_min).prod(); }
  /// Solid volume / box volume (overlaps counted twice, as tools usually do).
  double packing_fraction() const;
};

Packing read_xyzr(const std::filesystem::path &file);
/// Writes with 17 significant digits unless `digits` says otherwise.
void write_xyzr(const std::filesystem::path &file, const Packing &p, int digits = 17);
Packing read_lammps_data(const std::filesystem::path &file);
void write_lammps_data(const std::filesystem::path &file, const Packing &p, int digits = 17);

} // namespace geocomp::dem
