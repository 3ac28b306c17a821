// A fresh folder under the system's temporary folder for one test, removed with everything
// in it when the test ends; unique per process, so tests running at once do not meet.
#pragma once

#include <filesystem>
#include <string>
#include <unistd.h>

namespace geocomp::test {

struct ScratchFolder {
  std::filesystem::path dir;
  explicit ScratchFolder(const std::string &name)
    : dir(std::filesystem::temp_directory_path() / ("geocomp-" + name + "-" + std::to_string(::getpid())))
  {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~ScratchFolder() { std::filesystem::remove_all(dir); }
  ScratchFolder(const ScratchFolder &) = delete;
  ScratchFolder &operator=(const ScratchFolder &) = delete;
};

} // namespace geocomp::test
