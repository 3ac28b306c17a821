// See InputFile.h: a user's input file opened without blocking, regular files only, bounded.
#include "common/case/InputFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace geocomp {

namespace {
/// What a non-regular file is, for the message.
std::string file_type(mode_t mode)
{
  if (S_ISDIR(mode))
    return "a directory";
  if (S_ISFIFO(mode))
    return "a FIFO (named pipe)";
  if (S_ISCHR(mode))
    return "a character device";
  if (S_ISBLK(mode))
    return "a block device";
  if (S_ISSOCK(mode))
    return "a socket";
  return "not a regular file";
}

/// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor()
  {
    if (fd >= 0)
      ::close(fd);
  }
};

std::string megabytes(std::size_t bytes)
{
  return bytes % (std::size_t(1) << 20) == 0 ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}
} // namespace

std::string read_input_file(const std::string &path, const std::string &kind, std::size_t max_bytes)
{
  // A device is refused before it is opened (opening some has effects of its own); the
  // check is repeated on the open descriptor, which is what is read.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw CaseError(path, "(file)", "is " + file_type(st.st_mode) + ": expected a regular file, a " + kind);
  // O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting for one.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0)
    throw CaseError(path, "(file)",
                    "cannot be read (" + std::string(std::strerror(errno)) + "): expected a readable " + kind);
  if (::fstat(file.fd, &st) != 0)
    throw CaseError(path, "(file)", "cannot be read (" + std::string(std::strerror(errno)) + ")");
  if (!S_ISREG(st.st_mode))
    throw CaseError(path, "(file)", "is " + file_type(st.st_mode) + ": expected a regular file, a " + kind);
  if (st.st_size > 0 && static_cast<unsigned long long>(st.st_size) > max_bytes)
    throw CaseError(path, "(file)",
                    "holds " + std::to_string(st.st_size) + " bytes: expected a " + kind + " of at most " +
                      megabytes(max_bytes));
  // Read up to one byte past the bound: files under /proc report size 0 and still hold
  // text, and a file may grow between fstat() and read().
  std::string text;
  char buffer[65536];
  while (text.size() <= max_bytes) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0)
      throw CaseError(path, "(file)", "cannot be read (" + std::string(std::strerror(errno)) + ")");
    if (n == 0)
      break;
    text.append(buffer, std::size_t(n));
  }
  if (text.size() > max_bytes)
    throw CaseError(path, "(file)", "holds more than " + megabytes(max_bytes) + ": expected a " + kind +
                                      " of at most " + megabytes(max_bytes));
  return text;
}

} // namespace geocomp
