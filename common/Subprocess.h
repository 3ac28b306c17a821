#pragma once
// Starting another program (gnuplot) from an argument vector, never through a shell.
//
// Why it exists: `system("cd '" + dir + "' && gnuplot ...")` hands a command line to
// /bin/sh, and a folder name holding a quote, `$(...)` or `;` becomes a command of its
// own. Here the program is started with posix_spawnp() from a vector of arguments - the
// folder, the program and each argument arrive as they are, whatever characters they
// hold; the working directory and the output file are set by the spawn's file actions,
// not by a shell.
#include <filesystem>
#include <string>
#include <vector>

namespace geocomp {

struct SubprocessOptions {
  std::filesystem::path directory;   ///< working directory of the program; empty: ours
  std::filesystem::path stdout_file; ///< standard output (truncated); empty: /dev/null
  std::filesystem::path stderr_file; ///< standard error; empty: /dev/null; == stdout_file: the same file
  double timeout_seconds = 0.0;      ///< > 0: killed (SIGKILL) when it runs longer
};

struct SubprocessResult {
  bool started = false;   ///< false: not found or not executable (`error` says why)
  int exit_code = -1;     ///< when it exited; -1 when killed by a signal
  int signal = 0;         ///< the signal that ended it, if one did
  bool timed_out = false; ///< killed after SubprocessOptions::timeout_seconds
  std::string error;      ///< why it did not start
  bool succeeded() const { return started && exit_code == 0; }
};

/// Runs argv[0] (searched in PATH when it holds no '/') with the arguments argv[1...],
/// waits for it and returns how it ended. Standard input is /dev/null.
SubprocessResult run_subprocess(const std::vector<std::string> &argv, const SubprocessOptions &options = {});

/// True when `program` (a path, or a name searched in PATH) is an executable file.
bool program_available(const std::string &program);

} // namespace geocomp
