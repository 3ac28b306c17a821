#include "dem/specimen/Packing.h"

#include "common/AtomicFile.h"

#include <cmath>
#include <fstream>
#include <algorithm>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>

namespace geocomp::dem {

double Packing::packing_fraction() const
{
  double v = 0.0;
  for (double r : radius)
    v += 4.0 / 3.0 * M_PI * r * r * r;
  return v / box_volume();
}

namespace {
std::ifstream open(const std::filesystem::path &file)
{
  std::ifstream in(file);
  if (!in)
    throw PackingFileError(file.string(), 0, "cannot be read");
  return in;
}

void check_particle(const std::filesystem::path &file, int line, const Eigen::Vector3d &x, double r)
{
  if (!x.allFinite() || !std::isfinite(r))
    throw PackingFileError(file.string(), line, "expected finite numbers");
  if (!(r > 0.0))
    throw PackingFileError(file.string(), line, "expected a positive radius, got " + std::to_string(r));
}

void check_box(const std::filesystem::path &file, const Packing &p)
{
  if (!((p.box_max - p.box_min).array() > 0.0).all())
    throw PackingFileError(file.string(), 0, "expected a box with positive size");
  if (p.radius.empty())
    throw PackingFileError(file.string(), 0, "contains no particle");
}
} // namespace

Packing read_xyzr(const std::filesystem::path &file)
{
  std::ifstream in = open(file);
  Packing p;
  std::string line;
  int n = 0;
  bool have_box = false;
  // Header: "# x y z r   box [lo,hi]^3" or "# ... box [xlo,xhi]x[ylo,yhi]x[zlo,zhi]"
  static const std::regex cube(R"(box\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\]\^3)");
  static const std::regex boxes(
    R"(box\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\]\s*x\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\]\s*x\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\])");
  while (std::getline(in, line)) {
    ++n;
    if (line.empty())
      continue;
    if (line[0] == '#') {
      std::smatch m;
      if (std::regex_search(line, m, boxes)) {
        p.box_min = {std::stod(m[1]), std::stod(m[3]), std::stod(m[5])};
        p.box_max = {std::stod(m[2]), std::stod(m[4]), std::stod(m[6])};
        have_box = true;
      } else if (std::regex_search(line, m, cube)) {
        p.box_min.setConstant(std::stod(m[1]));
        p.box_max.setConstant(std::stod(m[2]));
        have_box = true;
      }
      continue;
    }
    std::istringstream s(line);
    Eigen::Vector3d x;
    double r;
    std::string extra;
    if (!(s >> x[0] >> x[1] >> x[2] >> r) || (s >> extra))
      throw PackingFileError(file.string(), n, "expected 'x y z r' (four numbers), got '" + line + "'");
    check_particle(file, n, x, r);
    p.position.push_back(x);
    p.radius.push_back(r);
  }
  if (!have_box)
    throw PackingFileError(file.string(), 1, "expected a header line '# x y z r box [lo,hi]^3' or "
                                            "'# x y z r box [xlo,xhi]x[ylo,yhi]x[zlo,zhi]'");
  check_box(file, p);
  return p;
}

void write_xyzr(const std::filesystem::path &file, const Packing &p, int digits)
{
  write_atomically(file, [&](const std::filesystem::path &tmp) {
    std::ofstream out(tmp);
    out << std::setprecision(digits);
    out << "# x y z r   box [" << p.box_min[0] << "," << p.box_max[0] << "]x[" << p.box_min[1] << ","
        << p.box_max[1] << "]x[" << p.box_min[2] << "," << p.box_max[2] << "]\n";
    for (std::size_t i = 0; i < p.size(); ++i)
      out << p.position[i][0] << " " << p.position[i][1] << " " << p.position[i][2] << " " << p.radius[i] << "\n";
    if (!out)
      throw PackingFileError(file.string(), 0, "could not be written");
  });
}

namespace {
/// One "id vx vy vz [wx wy wz]" line of a Velocities section into the atom's slot.
void read_velocity_line(const std::filesystem::path &file, int n, const std::string &line,
                        const std::map<long long, std::size_t> &index, Packing &p, std::vector<bool> &seen)
{
  std::istringstream s(line);
  long long id;
  Eigen::Vector3d v, w = Eigen::Vector3d::Zero();
  if (!(s >> id >> v[0] >> v[1] >> v[2]))
    throw PackingFileError(file.string(), n, "expected a Velocities line 'id vx vy vz [wx wy wz]', got '" + line + "'");
  s >> w[0] >> w[1] >> w[2];
  const auto it = index.find(id);
  if (it == index.end())
    throw PackingFileError(file.string(), n,
                           "velocity of atom " + std::to_string(id) + ", which the Atoms section does not list");
  if (!v.allFinite() || !w.allFinite())
    throw PackingFileError(file.string(), n, "expected finite numbers");
  if (p.velocity.empty()) {
    p.velocity.assign(p.size(), Eigen::Vector3d::Zero());
    p.angular_velocity.assign(p.size(), Eigen::Vector3d::Zero());
    seen.assign(p.size(), false);
  }
  p.velocity[it->second] = v;
  p.angular_velocity[it->second] = w;
  seen[it->second] = true;
}
} // namespace

Packing read_lammps_data(const std::filesystem::path &file)
{
  std::ifstream in = open(file);
  Packing p;
  std::string line;
  int n = 0;
  long long atoms = -1;
  enum class Section { header, atoms, velocities, other } at = Section::header;
  bool have_atoms = false, have_density = false;
  std::map<long long, std::size_t> index; // atom id -> position in the packing
  std::vector<bool> seen;                 // atoms given a velocity
  static const std::regex bounds(R"(^\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s+([xyz])lo\s+[xyz]hi)");
  static const std::regex count(R"(^\s*([0-9]+)\s+atoms\s*$)");
  static const std::regex section(R"(^\s*([A-Z][A-Za-z ]*?)\s*(#.*)?$)");
  while (std::getline(in, line)) {
    ++n;
    if (n == 1)
      continue; // title line
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::smatch m;
    if (std::regex_match(line, m, section)) {
      at = m[1] == "Atoms" ? Section::atoms : m[1] == "Velocities" ? Section::velocities : Section::other;
      have_atoms = have_atoms || at == Section::atoms;
      continue;
    }
    if (at == Section::header) {
      if (std::regex_search(line, m, bounds)) {
        const int a = m[3].str()[0] - 'x';
        p.box_min[a] = std::stod(m[1]);
        p.box_max[a] = std::stod(m[2]);
      } else if (std::regex_match(line, m, count)) {
        atoms = std::stoll(m[1]);
      }
      continue;
    }
    if (at == Section::velocities) {
      read_velocity_line(file, n, line, index, p, seen);
      continue;
    }
    if (at != Section::atoms)
      continue; // sections geocomp does not use (Masses, ...)
    std::istringstream s(line);
    long long id, type;
    double d, rho;
    Eigen::Vector3d x;
    if (!(s >> id >> type >> d >> rho >> x[0] >> x[1] >> x[2]))
      throw PackingFileError(file.string(), n,
                             "expected an atom_style granular line 'id type diameter density x y z', got '" + line + "'");
    check_particle(file, n, x, 0.5 * d);
    if (!index.emplace(id, p.size()).second)
      throw PackingFileError(file.string(), n, "atom " + std::to_string(id) + " is listed twice");
    if (!have_density) {
      p.density = rho;
      have_density = true;
    }
    p.position.push_back(x);
    p.radius.push_back(0.5 * d);
  }
  if (!have_atoms)
    throw PackingFileError(file.string(), 0, "has no 'Atoms' section");
  if (atoms >= 0 && static_cast<long long>(p.size()) != atoms)
    throw PackingFileError(file.string(), 0, "declares " + std::to_string(atoms) + " atoms but lists " +
                                               std::to_string(p.size()));
  if (!p.velocity.empty() && std::find(seen.begin(), seen.end(), false) != seen.end())
    throw PackingFileError(file.string(), 0, "its Velocities section does not list every atom");
  check_box(file, p);
  return p;
}

void write_lammps_data(const std::filesystem::path &file, const Packing &p, int digits)
{
  write_atomically(file, [&](const std::filesystem::path &tmp) {
    std::ofstream out(tmp);
    out << std::setprecision(digits);
    out << "geocomp packing N=" << p.size() << " (atom_style granular: id type diameter density x y z)\n\n"
        << p.size() << " atoms\n1 atom types\n\n";
    const char *axis[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
      out << p.box_min[a] << " " << p.box_max[a] << " " << axis[a] << "lo " << axis[a] << "hi\n";
    out << "\nAtoms\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
      out << i + 1 << " 1 " << 2.0 * p.radius[i] << " " << p.density << " " << p.position[i][0] << " "
          << p.position[i][1] << " " << p.position[i][2] << "\n";
    if (!p.velocity.empty()) {
      out << "\nVelocities\n\n";
      for (std::size_t i = 0; i < p.size(); ++i)
        out << i + 1 << " " << p.velocity[i][0] << " " << p.velocity[i][1] << " " << p.velocity[i][2] << " "
            << p.angular_velocity[i][0] << " " << p.angular_velocity[i][1] << " " << p.angular_velocity[i][2] << "\n";
    }
    if (!out)
      throw PackingFileError(file.string(), 0, "could not be written");
  });
}

} // namespace geocomp::dem
