#include "common/AtomicFile.h"

#include <atomic>
#include <string>
#include <unistd.h>

namespace geocomp {

void write_atomically(const std::filesystem::path &path,
                      const std::function<void(const std::filesystem::path &)> &write)
{
  static std::atomic<int> counter{0};
  if (path.has_parent_path())
    std::filesystem::create_directories(path.parent_path());
  std::filesystem::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  try {
    write(tmp);
    std::filesystem::rename(tmp, path);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
}

} // namespace geocomp
