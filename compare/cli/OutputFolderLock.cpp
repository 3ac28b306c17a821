// See OutputFolderLock.h: flock() on <folder>/.geocomp.lock, the holder named from its text.
#include "OutputFolderLock.h"
#include "Log.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
/// The holder's text, first line only ("process 1234 on host: geocomp pair ...").
std::string holder_of(int fd)
{
  char buffer[1024];
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  std::string text(buffer, n > 0 ? std::size_t(n) : 0);
  text = text.substr(0, text.find('\n'));
  return text;
}

/// "process 1234 on host: geocomp pair case.prm" for this process (its command line from
/// /proc/self/cmdline, arguments separated by spaces, line breaks as spaces).
std::string this_holder()
{
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string line((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (char &c : line)
    if (c == '\0' || c == '\n' || c == '\r')
      c = ' ';
  while (!line.empty() && line.back() == ' ')
    line.pop_back();
  return "process " + std::to_string(::getpid()) + " on " + host + ": " + line.substr(0, 512);
}
} // namespace

fs::path OutputFolderLock::file_in(const fs::path &dir) { return dir / ".geocomp.lock"; }

OutputFolderLock::OutputFolderLock(const fs::path &dir, const std::string &file_named_in, const std::string &parameter)
  : dir_(dir)
{
  const std::string name = "'" + dir.string() + "'";
  std::error_code ec;
  if (dir.empty())
    throw CaseError(file_named_in, parameter, "the output folder is empty: expected a folder name");
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw CaseError(file_named_in, parameter, name + " exists and is not a folder: expected a folder (or a path that does not exist yet)");
  if (!fs::exists(dir, ec)) {
    for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
      created_.push_back(p);
      if (p == p.parent_path())
        break;
    }
    fs::create_directories(dir, ec);
    if (ec) {
      remove_created();
      throw CaseError(file_named_in, parameter, name + " cannot be created (" + ec.message() + "): expected a folder that can be written");
    }
  }
  const fs::path file = file_in(dir);
  // Open, lock, then check that the file locked is still the one at the path: a run that
  // ends unlinks its lock file, and one that opened it just before must not hold a lock
  // on a file nobody else will ever see.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
      const std::string why = std::strerror(errno);
      remove_created();
      throw CaseError(file_named_in, parameter, name + " cannot be written (" + why + "): expected a folder this user can write");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = holder_of(fd);
      ::close(fd);
      throw CaseError(file_named_in, parameter,
                      name + " is in use by another run (" + (holder.empty() ? std::string("holder unknown") : holder) +
                        "; lock file " + file.string() + "): expected a folder no other run writes to - wait for "
                        "that run to end or choose another output folder");
    }
    struct stat locked {}, at_path {};
    if (::fstat(fd, &locked) == 0 && ::stat(file.c_str(), &at_path) == 0 && locked.st_ino == at_path.st_ino &&
        locked.st_dev == at_path.st_dev) {
      fd_ = fd;
      break;
    }
    ::close(fd);
  }
  if (fd_ < 0) {
    remove_created();
    throw CaseError(file_named_in, parameter, name + ": its lock file " + file.string() + " keeps changing: expected one run at a time");
  }
  const std::string stale = holder_of(fd_);
  if (!stale.empty()) {
    const std::string text = "output folder " + name + ": took over the lock left by " + stale +
                             ", which no longer holds it (the run ended without removing it)";
    warning_ = "warning: " + text;
    log::warning(text);
  }
  const std::string text = this_holder() + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) != ssize_t(text.size()))
    log::warning("output folder " + name + ": cannot write the lock file " + file.string());
}

OutputFolderLock::~OutputFolderLock()
{
  std::error_code ec;
  fs::remove(file_in(dir_), ec); // while still locked: a waiting run then finds no file or a new one
  ::close(fd_);
  remove_created();
}

void OutputFolderLock::remove_created() const
{
  std::error_code ec;
  for (const fs::path &p : created_)
    if (fs::is_directory(p, ec) && fs::is_empty(p, ec))
      fs::remove(p, ec);
}

std::unique_ptr<OutputFolderLock> lock_for_run(const fs::path &dir, const std::string &file,
                                               const std::string &parameter, MPI_Comm comm)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (size == 1)
    return std::make_unique<OutputFolderLock>(dir, file, parameter);
  std::unique_ptr<OutputFolderLock> lock;
  std::string refusal;
  if (rank == 0) {
    try {
      lock = std::make_unique<OutputFolderLock>(dir, file, parameter);
    } catch (const CaseError &e) {
      refusal = e.what();
    }
  }
  int length = static_cast<int>(refusal.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  if (length == 0)
    return lock;
  refusal.resize(std::size_t(length));
  MPI_Bcast(refusal.data(), length, MPI_CHAR, 0, comm);
  const std::string prefix = file + ": parameter '" + parameter + "': ";
  throw CaseError(file, parameter, refusal.rfind(prefix, 0) == 0 ? refusal.substr(prefix.size()) : refusal);
}

} // namespace geocomp::cli
