#pragma once
// The `geocomp` command line: one Command per subcommand, each with its own --help.
// Exit codes: 0 success, 2 bad input (case file, specimen file, command line),
// 1 the run itself failed.
#include "EngineRun.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::cli {

enum ExitCode { ok = 0, run_failure = 1, bad_input = 2 };

/// Thrown for a malformed command line; main prints it with the usage and exits 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Command {
  std::string name;
  std::string summary; ///< one line for `geocomp --help`
  std::string usage;   ///< full text for `geocomp NAME --help`
  std::function<int(const std::vector<std::string> &args)> run;
};

/// Every subcommand, in the order `geocomp --help` lists them.
const std::vector<Command> &commands();

/// Parsed "--name value" options and positional arguments of one subcommand.
struct Arguments {
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> options;
  /// Splits args; `valued` lists options that take a value, `flags` those that do not.
  static Arguments parse(const std::vector<std::string> &args, const std::vector<std::string> &valued,
                         const std::vector<std::string> &flags);
  bool has(const std::string &name) const;
  std::string get(const std::string &name, const std::string &fallback = "") const;
};

// Registered by the files that implement them.
Command check_command();
Command print_parameters_command();
Command dem_command();
Command liggghts_command();
Command material_point_command();
Command continuum_command();
Command fem_dem_command();
Command pair_command();
Command report_command();
Command compare_command();
Command calibrate_command();
Command sweep_command();
Command study_command();
Command pack_command();
Command export_command();
Command import_command();
Command rate_sweep_command();
Command crush_command();
Command shear_box_command();
/// The command line, stored in every results file.
void set_command_line(const std::string &line);
/// The settings of a command-line run (RunCommands.cpp): the world's communicator, the
/// command line, the terminal's progress display, checkpoints on SIGINT/SIGTERM.
RunSettings command_run_settings(bool reuse, int liggghts_ranks = 1);

} // namespace geocomp::cli
