#pragma once
// Reading a file a user names as input: opened without blocking, refused unless it is a
// regular file, read up to a bound.
//
// Why it exists: `std::ifstream` opens whatever the path names. A FIFO blocks the reader
// forever, /dev/zero or /dev/urandom feed it until memory runs out, a directory reads as
// an empty file (and then fails somewhere far from the cause). Every parameter file,
// every file it includes, goes through read_input_file(), which opens with O_NONBLOCK,
// checks with fstat() on the open descriptor (no window between check and read), and
// never reads more than `max_bytes` + 1 bytes, whatever the file claims its size is.
#include "common/case/CaseParameters.h"

#include <cstddef>
#include <string>

namespace geocomp {

/// The whole content of `path`. Throws CaseError(path, "(file)", ...) when it cannot be
/// opened ("cannot be read: expected a readable " + `kind`), when it is not a regular file
/// (naming what it is: a directory, a FIFO, a character device, ...), or when it holds
/// more than `max_bytes` bytes.
std::string read_input_file(const std::string &path, const std::string &kind, std::size_t max_bytes);

} // namespace geocomp
