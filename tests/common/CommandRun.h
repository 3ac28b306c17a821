// Running a program under test as a user would: its exit code and what it wrote to
// standard error (standard output is discarded). Shared by the command-line tests
// (tests/cli, tests/bench). run_program() starts it from an argument vector (no shell:
// paths with quotes, spaces, `$(...)` or ';' arrive as they are; it needs geocomp_common);
// run_command() hands a command line to sh -c.
#pragma once

#include "common/Subprocess.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

namespace geocomp::test {

struct CommandResult
{
  int code = -1;    ///< exit code (-1: killed by a signal)
  std::string err;  ///< standard error
  std::string out;  ///< standard output (run_program only)
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

/// Runs argv in `directory` (empty: ours), killed after `timeout_seconds`; code -1 when it
/// was killed by a signal, -2 when it ran past the timeout.
inline CommandResult run_program(const std::vector<std::string>& argv, const std::filesystem::path& directory = {},
                                 double timeout_seconds = 120.0)
{
  static int calls = 0;
  const std::string stem = std::filesystem::temp_directory_path() /
                           ("geocomp-run-" + std::to_string(::getpid()) + "-" + std::to_string(++calls));
  geocomp::SubprocessOptions o;
  o.directory = directory;
  o.stdout_file = stem + ".out";
  o.stderr_file = stem + ".err";
  o.timeout_seconds = timeout_seconds;
  const geocomp::SubprocessResult run = geocomp::run_subprocess(argv, o);
  CommandResult r;
  r.code = run.timed_out ? -2 : run.exit_code;
  const auto slurp = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    std::filesystem::remove(p);
    return ss.str();
  };
  r.out = slurp(o.stdout_file);
  r.err = slurp(o.stderr_file);
  return r;
}

}  // namespace geocomp::test
