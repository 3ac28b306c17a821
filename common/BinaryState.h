// @sect3{Raw binary state I/O for checkpoints}
//
// Why it exists: a restarted DEM run must equal the uninterrupted one bit for bit, so
// checkpoints store the doubles themselves (no decimal round trip) and every array that
// the next steps read, in storage order. These helpers write plain values and vectors of
// fixed-size records (doubles, integers, Eigen fixed-size vectors and the slot structs)
// as their bytes, preceded by the element count and size; reading checks both, so a file
// from a build with other struct layouts is refused instead of misread. Checkpoints are
// for restarting the same build on the same machine, not an exchange format.
#pragma once

#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::binary {

/// A checkpoint that cannot be read (truncated, other build, other kind of file).
struct StateError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

template <class T>
void put(std::ostream& out, const T& value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
void get(std::istream& in, T& value)
{
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in) throw StateError("checkpoint: unexpected end of data");
}

template <class T>
void put_vector(std::ostream& out, const std::vector<T>& v)
{
  put<std::uint64_t>(out, v.size());
  put<std::uint64_t>(out, sizeof(T));
  if (!v.empty()) out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(T)));
}

template <class T>
void get_vector(std::istream& in, std::vector<T>& v)
{
  std::uint64_t n = 0, size = 0;
  get(in, n);
  get(in, size);
  if (size != sizeof(T)) throw StateError("checkpoint: record size differs (written by another build)");
  if (n > (std::uint64_t(1) << 40) / sizeof(T)) throw StateError("checkpoint: implausible array length");
  v.resize(n);
  if (n) {
    in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
    if (!in) throw StateError("checkpoint: unexpected end of data");
  }
}

/// A tag that starts a section: its name and a format version.
inline void put_tag(std::ostream& out, const char (&tag)[9], std::uint32_t version)
{
  out.write(tag, 8);
  put(out, version);
}

inline void expect_tag(std::istream& in, const char (&tag)[9], std::uint32_t version)
{
  char got[8];
  in.read(got, 8);
  if (!in || std::memcmp(got, tag, 8) != 0)
    throw StateError(std::string("checkpoint: section '") + tag + "' not found");
  std::uint32_t v = 0;
  get(in, v);
  if (v != version) throw StateError(std::string("checkpoint: section '") + tag + "' has another version");
}

}  // namespace geocomp::binary
