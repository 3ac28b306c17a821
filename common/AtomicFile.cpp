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

void replace_folder_atomically(const std::filesystem::path &dir,
                               const std::function<void(const std::filesystem::path &)> &write)
{
  namespace fs = std::filesystem;
  static std::atomic<int> counter{0};
  const fs::path target = fs::absolute(dir);
  fs::create_directories(target.parent_path());
  const std::string stamp = std::to_string(::getpid()) + "." + std::to_string(counter++);
  const fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp." + stamp);
  try {
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    write(tmp);
    fs::path old;
    if (fs::exists(target)) {
      old = target.parent_path() / ("." + target.filename().string() + ".old." + stamp);
      fs::rename(target, old);
    }
    fs::rename(tmp, target);
    if (!old.empty())
      fs::remove_all(old);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
}

} // namespace geocomp
