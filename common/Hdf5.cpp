#include "common/Hdf5.h"

namespace geocomp::h5 {

namespace {
void check(herr_t status, const std::string &what)
{
  if (status < 0)
    throw Error("HDF5: " + what + " failed");
}
hid_t checked(hid_t id, const std::string &what)
{
  if (id < 0)
    throw Error("HDF5: " + what + " failed");
  return id;
}
/// Silences HDF5's own stack printing while a scope is alive; errors become exceptions.
struct Quiet {
  H5E_auto2_t func = nullptr;
  void *data = nullptr;
  Quiet()
  {
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~Quiet() { H5Eset_auto2(H5E_DEFAULT, func, data); }
};
Handle string_type()
{
  hid_t t = checked(H5Tcopy(H5T_C_S1), "H5Tcopy");
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return Handle(t, H5Tclose);
}
template <typename T>
void write_array(hid_t parent, const std::string &name, const T *data, const std::vector<hsize_t> &shape,
                 hid_t type)
{
  Handle space(checked(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), "H5Screate"),
               H5Sclose);
  Handle set(checked(H5Dcreate2(parent, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     "create dataset " + name),
             H5Dclose);
  hsize_t n = 1;
  for (auto d : shape)
    n *= d;
  if (n > 0)
    check(H5Dwrite(set.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name);
}
Handle open_dataset(hid_t parent, const std::string &name)
{
  Quiet q;
  return Handle(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
}
std::vector<hsize_t> dataset_shape(hid_t set)
{
  Handle space(checked(H5Dget_space(set), "H5Dget_space"), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::vector<hsize_t> shape(rank > 0 ? rank : 0);
  if (rank > 0)
    H5Sget_simple_extent_dims(space.id(), shape.data(), nullptr);
  return shape;
}
hsize_t count(const std::vector<hsize_t> &shape)
{
  hsize_t n = 1;
  for (auto d : shape)
    n *= d;
  return n;
}
} // namespace

Handle &Handle::operator=(Handle &&o) noexcept
{
  if (this != &o) {
    if (id_ >= 0 && closer_)
      closer_(id_);
    id_ = o.id_;
    closer_ = o.closer_;
    o.id_ = -1;
  }
  return *this;
}

Handle::~Handle()
{
  if (id_ >= 0 && closer_)
    closer_(id_);
}

Handle create_file(const std::filesystem::path &path)
{
  Quiet q;
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  H5Pset_link_creation_order(fcpl.id(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  return Handle(checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), H5P_DEFAULT),
                        "create file " + path.string()),
                H5Fclose);
}

Handle open_file(const std::filesystem::path &path, bool writable)
{
  Quiet q;
  return Handle(checked(H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT),
                        "open file " + path.string()),
                H5Fclose);
}

Handle create_group(hid_t parent, const std::string &name)
{
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_link_creation_order(gcpl.id(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  return Handle(checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT),
                        "create group " + name),
                H5Gclose);
}

Handle open_group(hid_t parent, const std::string &name)
{
  Quiet q;
  return Handle(checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), "open group " + name), H5Gclose);
}

bool exists(hid_t parent, const std::string &name)
{
  Quiet q;
  return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0;
}

void write(hid_t parent, const std::string &name, const std::vector<double> &data,
           const std::vector<hsize_t> &shape, const std::string &units)
{
  if (count(shape) != data.size())
    throw Error("HDF5: shape does not match data for " + name);
  write_array(parent, name, data.data(), shape, H5T_NATIVE_DOUBLE);
  if (!units.empty()) {
    Handle set = open_dataset(parent, name);
    write_attribute(set.id(), "units", units);
  }
}

void write(hid_t parent, const std::string &name, const std::vector<int> &data)
{
  write_array(parent, name, data.data(), {data.size()}, H5T_NATIVE_INT);
}

void write(hid_t parent, const std::string &name, const std::vector<long long> &data)
{
  write_array(parent, name, data.data(), {data.size()}, H5T_NATIVE_LLONG);
}

void write(hid_t parent, const std::string &name, const std::vector<std::string> &data)
{
  std::vector<const char *> ptrs;
  for (const auto &s : data)
    ptrs.push_back(s.c_str());
  Handle type = string_type();
  write_array(parent, name, ptrs.data(), {data.size()}, type.id());
}

void write_attribute(hid_t object, const std::string &name, const std::string &value)
{
  Handle type = string_type();
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(checked(H5Acreate2(object, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
                      "create attribute " + name),
              H5Aclose);
  const char *p = value.c_str();
  check(H5Awrite(attr.id(), type.id(), &p), "write attribute " + name);
}

void write_attribute(hid_t object, const std::string &name, double value)
{
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(checked(H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                      "create attribute " + name),
              H5Aclose);
  check(H5Awrite(attr.id(), H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

void write_attribute(hid_t object, const std::string &name, long long value)
{
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(checked(H5Acreate2(object, name.c_str(), H5T_NATIVE_LLONG, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                      "create attribute " + name),
              H5Aclose);
  check(H5Awrite(attr.id(), H5T_NATIVE_LLONG, &value), "write attribute " + name);
}

std::vector<double> read_doubles(hid_t parent, const std::string &name, std::vector<hsize_t> *shape)
{
  Handle set = open_dataset(parent, name);
  const auto s = dataset_shape(set.id());
  if (shape)
    *shape = s;
  std::vector<double> out(count(s));
  if (!out.empty())
    check(H5Dread(set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::vector<int> read_ints(hid_t parent, const std::string &name)
{
  Handle set = open_dataset(parent, name);
  std::vector<int> out(count(dataset_shape(set.id())));
  if (!out.empty())
    check(H5Dread(set.id(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::vector<long long> read_int64s(hid_t parent, const std::string &name)
{
  Handle set = open_dataset(parent, name);
  std::vector<long long> out(count(dataset_shape(set.id())));
  if (!out.empty())
    check(H5Dread(set.id(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::vector<std::string> read_strings(hid_t parent, const std::string &name)
{
  Handle set = open_dataset(parent, name);
  const hsize_t n = count(dataset_shape(set.id()));
  std::vector<char *> ptrs(n, nullptr);
  Handle type = string_type();
  if (n > 0)
    check(H5Dread(set.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()), "read " + name);
  std::vector<std::string> out;
  for (char *p : ptrs)
    out.emplace_back(p ? p : "");
  if (n > 0) {
    Handle space(H5Dget_space(set.id()), H5Sclose);
    H5Dvlen_reclaim(type.id(), space.id(), H5P_DEFAULT, ptrs.data());
  }
  return out;
}

bool has_attribute(hid_t object, const std::string &name)
{
  Quiet q;
  return H5Aexists(object, name.c_str()) > 0;
}

std::string read_string_attribute(hid_t object, const std::string &name)
{
  Quiet q;
  Handle attr(checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
  Handle type = string_type();
  char *p = nullptr;
  check(H5Aread(attr.id(), type.id(), &p), "read attribute " + name);
  std::string out = p ? p : "";
  H5free_memory(p);
  return out;
}

double read_double_attribute(hid_t object, const std::string &name)
{
  Quiet q;
  Handle attr(checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
  double v = 0;
  check(H5Aread(attr.id(), H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}

long long read_int_attribute(hid_t object, const std::string &name)
{
  Quiet q;
  Handle attr(checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
  long long v = 0;
  check(H5Aread(attr.id(), H5T_NATIVE_LLONG, &v), "read attribute " + name);
  return v;
}

std::vector<std::string> list(hid_t group)
{
  std::vector<std::string> names;
  auto cb = [](hid_t, const char *name, const H5L_info_t *, void *data) -> herr_t {
    static_cast<std::vector<std::string> *>(data)->emplace_back(name);
    return 0;
  };
  hsize_t idx = 0;
  Quiet q;
  if (H5Literate(group, H5_INDEX_CRT_ORDER, H5_ITER_INC, &idx, cb, &names) < 0) {
    names.clear();
    idx = 0;
    check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &idx, cb, &names), "list group");
  }
  return names;
}

} // namespace geocomp::h5
