#include "dem/program/Fields.h"

#include "common/AtomicFile.h"
#include "common/Hdf5.h"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace geocomp::dem {

namespace {
// @sect4{HDF5 helpers for shapes common/Hdf5.h does not cover}

std::vector<double> flatten(const std::vector<Vector3> &v)
{
  std::vector<double> out(3 * v.size());
  for (std::size_t k = 0; k < v.size(); ++k)
    for (int a = 0; a < 3; ++a)
      out[3 * k + a] = v[k][a];
  return out;
}

std::vector<Vector3> unflatten(const std::vector<double> &d)
{
  std::vector<Vector3> out(d.size() / 3);
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = Vector3(d[3 * k], d[3 * k + 1], d[3 * k + 2]);
  return out;
}

void write_vectors(hid_t g, const std::string &name, const std::vector<Vector3> &v, const std::string &units)
{
  h5::write(g, name, flatten(v), {hsize_t(v.size()), 3}, units);
}

std::vector<Vector3> read_vectors(hid_t g, const std::string &name) { return unflatten(h5::read_doubles(g, name)); }

void write_pairs(hid_t g, const std::string &name, const std::vector<std::array<std::int64_t, 2>> &pairs)
{
  const hsize_t dims[2] = {hsize_t(pairs.size()), 2};
  h5::Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  h5::Handle set(H5Dcreate2(g, name.c_str(), H5T_STD_I64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose);
  if (!set.valid())
    throw h5::Error("cannot create dataset " + name);
  if (!pairs.empty() &&
      H5Dwrite(set.id(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, pairs.front().data()) < 0)
    throw h5::Error("cannot write dataset " + name);
}

std::vector<std::array<std::int64_t, 2>> read_pairs(hid_t g, const std::string &name)
{
  h5::Handle set(H5Dopen2(g, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid())
    throw h5::Error("cannot open dataset " + name);
  h5::Handle space(H5Dget_space(set.id()), H5Sclose);
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(space.id()) != 2)
    throw h5::Error("dataset " + name + " is not n x 2");
  H5Sget_simple_extent_dims(space.id(), dims, nullptr);
  std::vector<std::array<std::int64_t, 2>> out(dims[0]);
  if (!out.empty() && H5Dread(set.id(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.front().data()) < 0)
    throw h5::Error("cannot read dataset " + name);
  return out;
}

std::string snapshot_name(std::size_t k)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "s%06zu", k);
  return buf;
}

std::vector<double> as_vector(const Vector3 &v) { return {v[0], v[1], v[2]}; }

// @sect4{The XDMF sidecar}

std::string data_item(const std::string &file, const std::string &path, std::size_t rows, int cols,
                      const char *number_type, int precision)
{
  std::ostringstream s;
  s << "<DataItem Dimensions=\"" << rows;
  if (cols > 1)
    s << " " << cols;
  s << "\" NumberType=\"" << number_type << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << file << ":"
    << path << "</DataItem>";
  return s.str();
}

void write_xdmf(const std::filesystem::path &h5_file, const std::filesystem::path &target)
{
  const std::string file = h5_file.filename().string();
  h5::Handle f = h5::open_file(h5_file);
  h5::Handle root = h5::open_group(f.id(), "snapshots");
  std::ostringstream x;
  x << std::setprecision(17);
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"dem\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const std::string &name : h5::list(root.id())) {
    h5::Handle g = h5::open_group(root.id(), name);
    const double time = h5::read_double_attribute(g.id(), "time");
    const std::size_t n = h5::read_int64s(g.id(), "ids").size();
    const std::size_t c = read_pairs(g.id(), "contact_pairs").size();
    const std::string base = "/snapshots/" + name + "/";
    x << "   <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "    <Time Value=\"" << time << "\"/>\n"
      << "    <Grid Name=\"particles\" GridType=\"Uniform\">\n"
      << "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n"
      << "     <Geometry GeometryType=\"XYZ\">" << data_item(file, base + "positions", n, 3, "Float", 8)
      << "</Geometry>\n";
    const char *vectors[] = {"displacements", "velocities", "angular_velocities"};
    for (const char *v : vectors)
      x << "     <Attribute Name=\"" << v << "\" AttributeType=\"Vector\" Center=\"Node\">"
        << data_item(file, base + v, n, 3, "Float", 8) << "</Attribute>\n";
    x << "     <Attribute Name=\"radius\" AttributeType=\"Scalar\" Center=\"Node\">"
      << data_item(file, base + "radii", n, 1, "Float", 8) << "</Attribute>\n"
      << "     <Attribute Name=\"id\" AttributeType=\"Scalar\" Center=\"Node\">"
      << data_item(file, base + "ids", n, 1, "Int", 8) << "</Attribute>\n"
      << "    </Grid>\n";
    if (c > 0) {
      // Contacts as line cells between particle centres (ids are the node indices).
      x << "    <Grid Name=\"contacts\" GridType=\"Uniform\">\n"
        << "     <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << c << "\" NodesPerElement=\"2\">"
        << data_item(file, base + "contact_pairs", c, 2, "Int", 8) << "</Topology>\n"
        << "     <Geometry GeometryType=\"XYZ\">" << data_item(file, base + "positions", n, 3, "Float", 8)
        << "</Geometry>\n"
        << "     <Attribute Name=\"force\" AttributeType=\"Vector\" Center=\"Cell\">"
        << data_item(file, base + "contact_forces", c, 3, "Float", 8) << "</Attribute>\n"
        << "     <Attribute Name=\"normal_force\" AttributeType=\"Scalar\" Center=\"Cell\">"
        << data_item(file, base + "contact_normal_forces", c, 1, "Float", 8) << "</Attribute>\n"
        << "     <Attribute Name=\"overlap\" AttributeType=\"Scalar\" Center=\"Cell\">"
        << data_item(file, base + "contact_overlaps", c, 1, "Float", 8) << "</Attribute>\n"
        << "    </Grid>\n";
    }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  write_atomically(target, [&](const std::filesystem::path &tmp) {
    std::ofstream out(tmp);
    out << x.str();
    if (!out)
      throw std::runtime_error("cannot write " + tmp.string());
  });
}
} // namespace

std::filesystem::path xdmf_path(const std::filesystem::path &h5_file)
{
  std::filesystem::path p = h5_file;
  p.replace_extension(".xdmf");
  return p;
}

// @sect4{Appending and reading snapshots}

std::size_t append_snapshot(const std::filesystem::path &h5_file, const ParticleFields &f)
{
  const std::size_t n = f.ids.size();
  if (f.positions.size() != n || f.displacements.size() != n || f.velocities.size() != n ||
      f.angular_velocities.size() != n || f.radii.size() != n)
    throw std::invalid_argument("append_snapshot: particle arrays of different lengths");
  for (std::size_t k = 0; k < n; ++k)
    if (f.ids[k] != std::int64_t(k))
      throw std::invalid_argument("append_snapshot: particles must be in id order 0..N-1");
  std::size_t index = 0;
  write_atomically(h5_file, [&](const std::filesystem::path &tmp) {
    const bool exists = std::filesystem::exists(h5_file);
    if (exists)
      std::filesystem::copy_file(h5_file, tmp, std::filesystem::copy_options::overwrite_existing);
    h5::Handle file = exists ? h5::open_file(tmp, true) : h5::create_file(tmp);
    if (!exists)
      h5::write_attribute(file.id(), "content", std::string("geocomp DEM particle snapshots; sidecar .xdmf"));
    h5::Handle root = h5::exists(file.id(), "snapshots") ? h5::open_group(file.id(), "snapshots")
                                                         : h5::create_group(file.id(), "snapshots");
    index = h5::list(root.id()).size();
    h5::Handle g = h5::create_group(root.id(), snapshot_name(index));
    h5::write_attribute(g.id(), "time", f.time);
    h5::write_attribute(g.id(), "label", f.label);
    h5::write(g.id(), "box_min", as_vector(f.box_min), {3}, "m");
    h5::write(g.id(), "box_max", as_vector(f.box_max), {3}, "m");
    h5::write(g.id(), "box_size0", as_vector(f.box_size0), {3}, "m");
    h5::write(g.id(), "ids", std::vector<long long>(f.ids.begin(), f.ids.end()));
    write_vectors(g.id(), "positions", f.positions, "m");
    write_vectors(g.id(), "displacements", f.displacements, "m");
    write_vectors(g.id(), "velocities", f.velocities, "m/s");
    write_vectors(g.id(), "angular_velocities", f.angular_velocities, "rad/s");
    h5::write(g.id(), "radii", f.radii, {hsize_t(n)}, "m");
    write_pairs(g.id(), "contact_pairs", f.contact_pairs);
    write_vectors(g.id(), "contact_points", f.contact_points, "m");
    write_vectors(g.id(), "contact_forces", f.contact_forces, "N");
    h5::write(g.id(), "contact_normal_forces", f.contact_normal_forces, {hsize_t(f.contact_normal_forces.size())},
              "N");
    h5::write(g.id(), "contact_overlaps", f.contact_overlaps, {hsize_t(f.contact_overlaps.size())}, "m");
    write_pairs(g.id(), "wall_contacts", f.wall_contacts);
    write_vectors(g.id(), "wall_contact_points", f.wall_contact_points, "m");
    write_vectors(g.id(), "wall_contact_forces", f.wall_contact_forces, "N");
  });
  write_xdmf(h5_file, xdmf_path(h5_file));
  return index;
}

std::vector<ParticleFields> read_snapshots(const std::filesystem::path &h5_file)
{
  std::vector<ParticleFields> out;
  h5::Handle file = h5::open_file(h5_file);
  h5::Handle root = h5::open_group(file.id(), "snapshots");
  for (const std::string &name : h5::list(root.id())) {
    h5::Handle g = h5::open_group(root.id(), name);
    ParticleFields f;
    f.time = h5::read_double_attribute(g.id(), "time");
    f.label = h5::read_double_attribute(g.id(), "label");
    const auto v3 = [&](const char *n) {
      const std::vector<double> d = h5::read_doubles(g.id(), n);
      return Vector3(d.at(0), d.at(1), d.at(2));
    };
    f.box_min = v3("box_min");
    f.box_max = v3("box_max");
    f.box_size0 = v3("box_size0");
    const std::vector<long long> ids = h5::read_int64s(g.id(), "ids");
    f.ids.assign(ids.begin(), ids.end());
    f.positions = read_vectors(g.id(), "positions");
    f.displacements = read_vectors(g.id(), "displacements");
    f.velocities = read_vectors(g.id(), "velocities");
    f.angular_velocities = read_vectors(g.id(), "angular_velocities");
    f.radii = h5::read_doubles(g.id(), "radii");
    f.contact_pairs = read_pairs(g.id(), "contact_pairs");
    f.contact_points = read_vectors(g.id(), "contact_points");
    f.contact_forces = read_vectors(g.id(), "contact_forces");
    f.contact_normal_forces = h5::read_doubles(g.id(), "contact_normal_forces");
    f.contact_overlaps = h5::read_doubles(g.id(), "contact_overlaps");
    f.wall_contacts = read_pairs(g.id(), "wall_contacts");
    f.wall_contact_points = read_vectors(g.id(), "wall_contact_points");
    f.wall_contact_forces = read_vectors(g.id(), "wall_contact_forces");
    out.push_back(std::move(f));
  }
  return out;
}

} // namespace geocomp::dem
