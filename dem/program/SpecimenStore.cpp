#include "dem/program/SpecimenStore.h"

#include "common/AtomicFile.h"
#include "common/Hdf5.h"
#include "common/Version.h"
#include "common/BinaryState.h"

#include <algorithm>
#include <cctype>
#include <ctime>
#include <sstream>

namespace geocomp::dem {

namespace {

constexpr const char *kFormat = "geocomp core store";
constexpr long long kFormatVersion = 1;

std::string now_iso()
{
  std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::vector<double> flatten(const std::vector<Vec3> &v)
{
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3 &x : v)
    out.insert(out.end(), {x.x(), x.y(), x.z()});
  return out;
}

Vec3 row(const std::vector<double> &d, std::size_t k) { return Vec3(d[3 * k], d[3 * k + 1], d[3 * k + 2]); }

// @sect4{The binary state as a byte dataset}

void write_bytes(hid_t parent, const std::string &name, const std::string &bytes)
{
  const hsize_t n = bytes.size();
  h5::Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  h5::Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (n > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
    const hsize_t chunk = std::min<hsize_t>(n, 1 << 20);
    H5Pset_chunk(plist.id(), 1, &chunk);
    H5Pset_deflate(plist.id(), 6);
  }
  h5::Handle set(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_UCHAR, space.id(), H5P_DEFAULT, plist.id(), H5P_DEFAULT),
                 H5Dclose);
  if (!set.valid())
    throw StoreError("HDF5: cannot create dataset " + name);
  if (n > 0 && H5Dwrite(set.id(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0)
    throw StoreError("HDF5: cannot write dataset " + name);
}

std::string read_bytes(hid_t parent, const std::string &name)
{
  h5::Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid())
    throw StoreError("HDF5: cannot open dataset " + name);
  h5::Handle space(H5Dget_space(set.id()), H5Sclose);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.id(), &n, nullptr);
  std::string bytes(n, '\0');
  if (n > 0 && H5Dread(set.id(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0)
    throw StoreError("HDF5: cannot read dataset " + name);
  return bytes;
}

// @sect4{Metadata and record as attributes}

void write_metadata(hid_t g, const SpecimenMetadata &m)
{
  using h5::write_attribute;
  write_attribute(g, "N", (long long)m.particles);
  write_attribute(g, "eta", m.packing_fraction);
  write_attribute(g, "R", m.radius);
  write_attribute(g, "L0", m.box_size);
  write_attribute(g, "sigma_0", m.isotropic_pressure);
  write_attribute(g, "density", m.density);
  write_attribute(g, "size_distribution", m.size_distribution);
  write_attribute(g, "radius_spread", m.radius_spread);
  write_attribute(g, "lognormal_sigma", m.lognormal_sigma);
  write_attribute(g, "aristotelian", (long long)m.aristotelian);
  write_attribute(g, "seed", (long long)m.seed);
  write_attribute(g, "contact_model", m.contact.model);
  write_attribute(g, "mu_s", m.contact.particle_friction);
  write_attribute(g, "mu_p", m.contact.wall_friction);
  write_attribute(g, "c_r", m.contact.restitution);
  write_attribute(g, "E", m.contact.youngs_modulus);
  write_attribute(g, "nu", m.contact.poisson_ratio);
  write_attribute(g, "V_c", m.contact.impact_velocity);
  write_attribute(g, "k_n", m.contact.normal_stiffness);
  write_attribute(g, "c_n", m.contact.normal_damping);
  write_attribute(g, "k_t_over_k_n", m.contact.tangential_stiffness_ratio);
  write_attribute(g, "dt", m.time_step);
  write_attribute(g, "case_file", m.case_file);
  write_attribute(g, "created", m.created);
  write_attribute(g, "version", m.version);
  write_attribute(g, "units", std::string("SI: m, kg, s, N, Pa; stress tension positive, pressures compression positive"));
  h5::write(g, "case_text", std::vector<std::string>{m.case_text});
}

SpecimenMetadata read_metadata(hid_t g)
{
  using namespace h5;
  SpecimenMetadata m;
  m.particles = std::size_t(read_int_attribute(g, "N"));
  m.packing_fraction = read_double_attribute(g, "eta");
  m.radius = read_double_attribute(g, "R");
  m.box_size = read_double_attribute(g, "L0");
  m.isotropic_pressure = read_double_attribute(g, "sigma_0");
  m.density = read_double_attribute(g, "density");
  m.size_distribution = read_string_attribute(g, "size_distribution");
  m.radius_spread = read_double_attribute(g, "radius_spread");
  m.lognormal_sigma = read_double_attribute(g, "lognormal_sigma");
  m.aristotelian = read_int_attribute(g, "aristotelian") != 0;
  m.seed = std::uint64_t(read_int_attribute(g, "seed"));
  m.contact.model = read_string_attribute(g, "contact_model");
  m.contact.particle_friction = read_double_attribute(g, "mu_s");
  m.contact.wall_friction = read_double_attribute(g, "mu_p");
  m.contact.restitution = read_double_attribute(g, "c_r");
  m.contact.youngs_modulus = read_double_attribute(g, "E");
  m.contact.poisson_ratio = read_double_attribute(g, "nu");
  m.contact.impact_velocity = read_double_attribute(g, "V_c");
  m.contact.normal_stiffness = read_double_attribute(g, "k_n");
  m.contact.normal_damping = read_double_attribute(g, "c_n");
  m.contact.tangential_stiffness_ratio = read_double_attribute(g, "k_t_over_k_n");
  m.time_step = read_double_attribute(g, "dt");
  m.case_file = read_string_attribute(g, "case_file");
  m.created = read_string_attribute(g, "created");
  m.version = read_string_attribute(g, "version");
  const auto text = read_strings(g, "case_text");
  m.case_text = text.empty() ? std::string() : text[0];
  return m;
}

/// The record's numbers, each as one attribute (name = the field's name).
template <class F>
void record_fields(F &&f, PreparationRecord &r)
{
  f("initial_packing_fraction", r.initial_packing_fraction);
  f("grown_packing_fraction", r.grown_packing_fraction);
  f("final_packing_fraction", r.final_packing_fraction);
  f("box_size", r.box_size);
  f("mean_radius", r.mean_radius);
  f("pressure", r.pressure);
  f("grown_pressure", r.grown_pressure);
  for (auto [name, cost] : {std::pair{"growth", &r.growth}, std::pair{"frictionless", &r.frictionless},
                            std::pair{"frictional", &r.frictional}, std::pair{"consolidation", &r.consolidation}}) {
    f(std::string(name) + "_time", cost->time);
    f(std::string(name) + "_wall_seconds", cost->wall_seconds);
  }
  for (auto [name, rest] : {std::pair{"frictionless", &r.frictionless_rest}, std::pair{"frictional", &r.frictional_rest},
                            std::pair{"consolidated", &r.consolidated_rest}}) {
    f(std::string(name) + "_unbalanced", rest->unbalanced);
    f(std::string(name) + "_kinetic", rest->kinetic);
    f(std::string(name) + "_elastic", rest->elastic);
  }
  f("consolidated_stress_error", r.consolidated.stress_error);
  f("consolidated_servo_unbalanced", r.consolidated.unbalanced);
  f("coordination", r.coordination);
  f("mean_overlap", r.mean_overlap);
  f("wall_seconds", r.wall_seconds);
}

void write_record(hid_t g, const PreparationRecord &rec)
{
  PreparationRecord r = rec;
  record_fields([g](const std::string &name, double &v) { h5::write_attribute(g, name, v); }, r);
  h5::write_attribute(g, "method", r.method);
  h5::write_attribute(g, "size_distribution", r.size_distribution);
  h5::write_attribute(g, "description", r.describe());
  h5::write_attribute(g, "seed", (long long)r.seed);
  h5::write_attribute(g, "particles", (long long)r.particles);
  h5::write_attribute(g, "aristotelian", (long long)r.aristotelian);
  h5::write_attribute(g, "frictionless_converged", (long long)r.frictionless_converged);
  h5::write_attribute(g, "frictional_converged", (long long)r.frictional_converged);
  h5::write_attribute(g, "consolidated_converged", (long long)r.consolidated.converged);
  h5::write_attribute(g, "growth_steps", (long long)r.growth.steps);
  h5::write_attribute(g, "frictionless_steps", (long long)r.frictionless.steps);
  h5::write_attribute(g, "frictional_steps", (long long)r.frictional.steps);
  h5::write_attribute(g, "consolidation_steps", (long long)r.consolidation.steps);
  h5::write_attribute(g, "steps", (long long)r.steps);
}

PreparationRecord read_record(hid_t g)
{
  PreparationRecord r;
  record_fields([g](const std::string &name, double &v) { v = h5::read_double_attribute(g, name); }, r);
  r.method = h5::read_string_attribute(g, "method");
  r.size_distribution = h5::read_string_attribute(g, "size_distribution");
  r.seed = std::uint64_t(h5::read_int_attribute(g, "seed"));
  r.particles = std::size_t(h5::read_int_attribute(g, "particles"));
  r.aristotelian = h5::read_int_attribute(g, "aristotelian") != 0;
  r.frictionless_converged = h5::read_int_attribute(g, "frictionless_converged") != 0;
  r.frictional_converged = h5::read_int_attribute(g, "frictional_converged") != 0;
  r.consolidated.converged = h5::read_int_attribute(g, "consolidated_converged") != 0;
  r.growth.steps = std::uint64_t(h5::read_int_attribute(g, "growth_steps"));
  r.frictionless.steps = std::uint64_t(h5::read_int_attribute(g, "frictionless_steps"));
  r.frictional.steps = std::uint64_t(h5::read_int_attribute(g, "frictional_steps"));
  r.consolidation.steps = std::uint64_t(h5::read_int_attribute(g, "consolidation_steps"));
  r.steps = std::uint64_t(h5::read_int_attribute(g, "steps"));
  return r;
}

// @sect4{Portable datasets}

void write_portable(hid_t g, const DemSystem &s)
{
  const std::size_t n = s.n_particles();
  std::vector<Vec3> x(n), v(n), w(n);
  std::vector<double> radius(n), mass(n), q(4 * n);
  for (ParticleId id = 0; id < n; ++id) {
    x[id] = s.position(id);
    v[id] = s.velocity(id);
    w[id] = s.angular_velocity(id);
    const Index k = s.index_of(id);
    radius[id] = s.particles().radius[k];
    mass[id] = s.particles().mass[k];
    const Quat o = s.orientation(id);
    q[4 * id] = o.w();
    q[4 * id + 1] = o.x();
    q[4 * id + 2] = o.y();
    q[4 * id + 3] = o.z();
  }
  {
    h5::Handle p = h5::create_group(g, "particles");
    h5::write(p.id(), "position", flatten(x), {n, 3}, "m");
    h5::write(p.id(), "radius", radius, {n}, "m");
    h5::write(p.id(), "mass", mass, {n}, "kg");
    h5::write(p.id(), "orientation", q, {n, 4}, "1 (quaternion w x y z)");
    h5::write(p.id(), "velocity", flatten(v), {n, 3}, "m/s");
    h5::write(p.id(), "angular_velocity", flatten(w), {n, 3}, "rad/s");
  }
  {
    const std::size_t m = s.n_walls();
    std::vector<Vec3> point(m), normal(m), velocity(m), force(m);
    std::vector<double> friction(m);
    for (std::size_t k = 0; k < m; ++k) {
      point[k] = s.wall(k).point;
      normal[k] = s.wall(k).normal;
      velocity[k] = s.wall(k).velocity;
      force[k] = s.wall(k).force;
      friction[k] = s.wall(k).mu;
    }
    h5::Handle p = h5::create_group(g, "walls");
    h5::write(p.id(), "point", flatten(point), {m, 3}, "m");
    h5::write(p.id(), "normal", flatten(normal), {m, 3}, "1 (into the specimen)");
    h5::write(p.id(), "velocity", flatten(velocity), {m, 3}, "m/s");
    h5::write(p.id(), "force", flatten(force), {m, 3}, "N (exerted by the particles)");
    h5::write(p.id(), "friction", friction, {m}, "1");
  }
  {
    const std::vector<ContactState> cs = s.export_contact_state();
    const std::size_t m = cs.size();
    std::vector<int> wall(m);
    std::vector<long long> i(m), j(m);
    std::vector<double> overlap(m);
    std::vector<Vec3> shear(m);
    for (std::size_t k = 0; k < m; ++k) {
      wall[k] = cs[k].wall ? 1 : 0;
      i[k] = cs[k].i;
      j[k] = cs[k].j;
      overlap[k] = cs[k].overlap;
      shear[k] = cs[k].shear;
    }
    h5::Handle p = h5::create_group(g, "contacts");
    h5::write(p.id(), "wall", wall);
    h5::write(p.id(), "i", i);
    h5::write(p.id(), "j", j);
    h5::write(p.id(), "overlap", overlap, {m}, "m");
    h5::write(p.id(), "shear", flatten(shear), {m, 3}, "m or N (tangential history of the law, on j)");
  }
}

/// The system rebuilt from the portable datasets and the stored contact law.
DemSystem rebuild_portable(hid_t g, const SpecimenMetadata &m)
{
  h5::Handle pg = h5::open_group(g, "particles");
  const std::vector<double> x = h5::read_doubles(pg.id(), "position"), r = h5::read_doubles(pg.id(), "radius"),
                            v = h5::read_doubles(pg.id(), "velocity"),
                            w = h5::read_doubles(pg.id(), "angular_velocity");
  h5::Handle wg = h5::open_group(g, "walls");
  const std::vector<double> point = h5::read_doubles(wg.id(), "point"), mu = h5::read_doubles(wg.id(), "friction");
  if (point.size() < 18 || mu.size() < 6 || x.size() != 3 * r.size())
    throw StoreError("store: the portable datasets are incomplete");
  Packing p;
  p.density = m.density;
  p.box_min = Vec3(row(point, 0).x(), row(point, 2).y(), row(point, 4).z());
  p.box_max = Vec3(row(point, 1).x(), row(point, 3).y(), row(point, 5).z());
  for (std::size_t k = 0; k < r.size(); ++k) {
    p.position.push_back(row(x, k));
    p.radius.push_back(r[k]);
  }
  DemParameters d;
  DemSystem s = make_system(p, m.contact, d);
  const std::vector<double> wall_v = h5::read_doubles(wg.id(), "velocity");
  for (std::size_t k = 0; k < 6; ++k) {
    s.set_wall_friction(k, mu[k]);
    s.set_wall_position(k, row(point, k));
    s.set_wall_velocity(k, row(wall_v, k));
  }
  for (ParticleId id = 0; id < r.size(); ++id) {
    s.set_velocity(id, row(v, id));
    s.set_angular_velocity(id, row(w, id));
  }
  h5::Handle cg = h5::open_group(g, "contacts");
  const auto wall = h5::read_ints(cg.id(), "wall");
  const auto i = h5::read_int64s(cg.id(), "i"), j = h5::read_int64s(cg.id(), "j");
  const auto overlap = h5::read_doubles(cg.id(), "overlap"), shear = h5::read_doubles(cg.id(), "shear");
  std::vector<ContactState> cs(wall.size());
  for (std::size_t k = 0; k < cs.size(); ++k)
    cs[k] = {wall[k] != 0, std::uint32_t(i[k]), ParticleId(j[k]), overlap[k], row(shear, k)};
  s.import_contact_state(cs);
  if (m.time_step > 0.0)
    s.set_time_step(m.time_step);
  return s;
}

h5::Handle open_store(const std::filesystem::path &path)
{
  if (!std::filesystem::exists(path))
    throw StoreError("core store '" + path.string() + "' does not exist");
  h5::Handle f;
  try {
    f = h5::open_file(path);
  } catch (const h5::Error &) {
    throw StoreError("'" + path.string() + "' is not an HDF5 file");
  }
  if (!h5::has_attribute(f.id(), "format") || h5::read_string_attribute(f.id(), "format") != kFormat)
    throw StoreError("'" + path.string() + "' is not a geocomp core store (no format = \"" + kFormat +
                     "\" attribute)");
  if (h5::read_int_attribute(f.id(), "format_version") != kFormatVersion)
    throw StoreError("core store '" + path.string() + "' has another format version");
  return f;
}

} // namespace

bool valid_specimen_name(const std::string &name)
{
  if (name.empty() || name == "." || name == "..")
    return false;
  for (char ch : name)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.'))
      return false;
  return true;
}

SpecimenMetadata SpecimenMetadata::from_case(const DemCase &c, const PreparedSpecimen &s)
{
  SpecimenMetadata m;
  m.particles = s.system.n_particles();
  m.packing_fraction = c.specimen.packing_fraction;
  m.radius = c.specimen.radius;
  m.box_size = s.record.box_size;
  m.isotropic_pressure = c.specimen.isotropic_pressure;
  m.density = c.specimen.density;
  m.size_distribution = c.specimen.size_distribution;
  m.radius_spread = c.specimen.radius_spread;
  m.lognormal_sigma = c.specimen.lognormal_sigma;
  m.aristotelian = c.specimen.aristotelian;
  m.seed = c.seed;
  m.contact = c.contact;
  m.time_step = s.system.time_step();
  m.case_file = c.file;
  m.case_text = c.text;
  m.created = now_iso();
  m.version = std::string(GEOCOMP_VERSION) + " (" + GEOCOMP_GIT_HASH + ")";
  return m;
}

std::vector<std::string> stored_specimen_names(const std::filesystem::path &path)
{
  h5::Handle f = open_store(path);
  if (!h5::exists(f.id(), "specimens"))
    return {};
  h5::Handle g = h5::open_group(f.id(), "specimens");
  return h5::list(g.id());
}

void write_stored_specimen(const std::filesystem::path &path, const std::string &name, const PreparedSpecimen &s,
                           const SpecimenMetadata &metadata)
{
  if (!valid_specimen_name(name))
    throw StoreError("specimen name '" + name + "': use letters, digits, '_', '-' and '.'");
  std::vector<std::string> keep;
  if (std::filesystem::exists(path))
    for (const std::string &n : stored_specimen_names(path))
      if (n != name)
        keep.push_back(n);
  std::ostringstream state;
  s.system.write_state(state);
  write_atomically(path, [&](const std::filesystem::path &tmp) {
    h5::Handle out = h5::create_file(tmp);
    h5::write_attribute(out.id(), "format", std::string(kFormat));
    h5::write_attribute(out.id(), "format_version", kFormatVersion);
    h5::Handle specimens = h5::create_group(out.id(), "specimens");
    if (!keep.empty()) {
      // The other specimens are copied as they are (HDF5 does not reclaim the space of a
      // replaced group in place, so the store is always written anew).
      h5::Handle in = open_store(path);
      h5::Handle from = h5::open_group(in.id(), "specimens");
      for (const std::string &n : keep)
        if (H5Ocopy(from.id(), n.c_str(), specimens.id(), n.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
          throw StoreError("HDF5: cannot copy specimen " + n);
    }
    h5::Handle g = h5::create_group(specimens.id(), name);
    write_metadata(g.id(), metadata);
    {
      h5::Handle r = h5::create_group(g.id(), "record");
      write_record(r.id(), s.record);
    }
    write_portable(g.id(), s.system);
    write_bytes(g.id(), "state", state.str());
  });
}

StoredSpecimen read_stored_specimen(const std::filesystem::path &path, const std::string &name)
{
  h5::Handle f = open_store(path);
  std::vector<std::string> names;
  if (h5::exists(f.id(), "specimens")) {
    h5::Handle g = h5::open_group(f.id(), "specimens");
    names = h5::list(g.id());
  }
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const auto &n : names)
      list += (list.empty() ? "" : ", ") + n;
    throw StoreError("core store '" + path.string() + "' holds no specimen '" + name + "' (it holds: " +
                       (list.empty() ? std::string("none") : list) + ")",
                     true);
  }
  try {
    h5::Handle g = h5::open_group(f.id(), "specimens/" + name);
    StoredSpecimen s;
    s.name = name;
    s.metadata = read_metadata(g.id());
    {
      h5::Handle r = h5::open_group(g.id(), "record");
      s.record = read_record(r.id());
    }
    try {
      std::istringstream in(read_bytes(g.id(), "state"));
      s.system.read_state(in);
      s.exact = true;
    } catch (const binary::StateError &) {
      s.system = rebuild_portable(g.id(), s.metadata);
      s.exact = false;
    }
    return s;
  } catch (const h5::Error &e) {
    throw StoreError("core store '" + path.string() + "', specimen '" + name + "': " + e.what());
  }
}

} // namespace geocomp::dem
