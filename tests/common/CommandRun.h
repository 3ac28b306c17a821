// Running a program under test as a user would, through the shell: its exit code and what
// it wrote to standard error (standard output is discarded). Shared by the command-line
// tests (tests/cli, tests/bench).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace geocomp::test {

struct CommandResult
{
  int code = -1;    ///< exit code (-1: killed by a signal)
  std::string err;  ///< standard error
};

/// Runs `command` with sh -c; stderr goes through a file unique to this process and call
/// (ctest runs several such tests at once, often in the same directory).
inline CommandResult run_command(const std::string& command)
{
  static int calls = 0;
  const std::filesystem::path err_file = std::filesystem::temp_directory_path() /
                                         ("geocomp-stderr-" + std::to_string(::getpid()) + "-" + std::to_string(++calls));
  const int status = std::system(("(" + command + ") >/dev/null 2>'" + err_file.string() + "'").c_str());
  CommandResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  std::stringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  std::filesystem::remove(err_file);
  return r;
}

}  // namespace geocomp::test
