#pragma once
// Thin RAII layer over the HDF5 C API: files, groups, and the few dataset shapes
// geocomp writes (1-D double/int arrays, n x 3 x 3 tensors, strings, attributes).
// HDF5 does the storage; this only removes the handle bookkeeping from callers.
// Why a wrapper of our own (issue 37 asks to keep it only if no packaged library serves):
// the program must use the MPI build of HDF5 that deal.II links, and HDF5's own C++ API
// (H5Cpp) is not supported by the HDF5 group together with a parallel build (its configure
// refuses the pair unless forced with --enable-unsupported, as Debian does); HighFive is not
// in Debian 12; and neither would spare the few shape helpers below (n x 3 x 3 tensors,
// string lists, units attributes), which are most of this file. The layer is the C API's
// RAII handle plus those helpers, 60 lines of interface.
#include <hdf5.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::h5 {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Owns one hid_t and closes it with the right H5*close.
class Handle {
public:
  Handle() = default;
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) {}
  Handle(const Handle &) = delete;
  Handle &operator=(const Handle &) = delete;
  Handle(Handle &&o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = -1; }
  Handle &operator=(Handle &&o) noexcept;
  ~Handle();
  hid_t id() const { return id_; }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_ = -1;
  herr_t (*closer_)(hid_t) = nullptr;
};

Handle create_file(const std::filesystem::path &path);
Handle open_file(const std::filesystem::path &path, bool writable = false);
Handle create_group(hid_t parent, const std::string &name);
Handle open_group(hid_t parent, const std::string &name);
bool exists(hid_t parent, const std::string &name);

/// Writes a dataset of doubles with the given shape; `units` becomes an attribute.
void write(hid_t parent, const std::string &name, const std::vector<double> &data,
           const std::vector<hsize_t> &shape, const std::string &units = "");
void write(hid_t parent, const std::string &name, const std::vector<int> &data);
void write(hid_t parent, const std::string &name, const std::vector<long long> &data);
void write(hid_t parent, const std::string &name, const std::vector<std::string> &data);
void write_attribute(hid_t object, const std::string &name, const std::string &value);
void write_attribute(hid_t object, const std::string &name, double value);
void write_attribute(hid_t object, const std::string &name, long long value);

std::vector<double> read_doubles(hid_t parent, const std::string &name, std::vector<hsize_t> *shape = nullptr);
std::vector<int> read_ints(hid_t parent, const std::string &name);
std::vector<long long> read_int64s(hid_t parent, const std::string &name);
std::vector<std::string> read_strings(hid_t parent, const std::string &name);
std::string read_string_attribute(hid_t object, const std::string &name);
double read_double_attribute(hid_t object, const std::string &name);
long long read_int_attribute(hid_t object, const std::string &name);
bool has_attribute(hid_t object, const std::string &name);
/// Names of the links in a group, in creation order where tracked, else name order.
std::vector<std::string> list(hid_t group);

} // namespace geocomp::h5
