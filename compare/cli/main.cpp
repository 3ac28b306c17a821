// geocomp: DEM and elastoplastic continuum runs of one loading program, compared.
#include "Commands.h"
#include "Log.h"
#include "Mpi.h"

#include "common/Version.h"
#include "common/case/CaseParameters.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <memory>
#include <optional>
#include <iostream>

namespace geocomp::cli {

namespace {
void print_help(std::ostream &out)
{
  out << "geocomp " << GEOCOMP_VERSION << " - DEM and Mohr-Coulomb continuum runs of one loading program\n\n"
      << "usage: geocomp <command> [options]\n       geocomp <command> --help\n       geocomp --version\n\n"
      << "commands:\n";
  for (const auto &c : commands())
    out << "  " << c.name << std::string(c.name.size() < 18 ? 18 - c.name.size() : 1, ' ') << c.summary << "\n";
  out << "\nexit codes: 0 success, 1 run failure (results so far written, /meta/status says why; also a stage\n"
         "            ended by its max duration before its stop condition), 2 bad input\n"
      << "options of every command: -q, --quiet (warnings and errors only, no progress display),\n"
         "            -v, --verbose (also details: case read, engine set-up, files written)\n"
      << "units: SI; stresses tension positive inside the code and in results files\n";
}
} // namespace

namespace {

/// The subcommand and its own arguments, parsed by CLI11 (each command parses the rest,
/// Arguments.cpp); none with the exit code when the line is help, version or malformed.
struct Dispatch {
  const Command *command = nullptr;
  std::vector<std::string> rest;
};

std::optional<Dispatch> dispatch(const std::vector<std::string> &args, int &code)
{
  if (args.empty() || args[0] == "help") {
    print_help(std::cout);
    code = args.empty() ? bad_input : ok;
    return std::nullopt;
  }
  CLI::App app("DEM and Mohr-Coulomb continuum runs of one loading program", "geocomp");
  app.set_help_flag(); // print_help: the commands with their summaries and the exit codes
  bool help = false, version = false, quiet = false, verbose = false;
  app.add_flag("-h,--help", help);
  app.add_flag("--version", version);
  app.add_flag("-q,--quiet", quiet); // also accepted after the command (Arguments.cpp)
  app.add_flag("-v,--verbose", verbose);
  app.require_subcommand(0, 1);
  for (const auto &c : commands())
    app.add_subcommand(c.name, c.summary)->prefix_command(); // the command parses the rest
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError &e) {
    const auto word = std::find_if(args.begin(), args.end(), [](const std::string &a) { return a.rfind('-', 0) != 0; });
    std::cerr << "geocomp: unknown " << (word == args.end() ? "option '" + args[0] : "command '" + *word) << "'\n\n";
    print_help(std::cerr);
    code = bad_input;
    return std::nullopt;
  }
  if (quiet && verbose) {
    std::cerr << "geocomp: --quiet and --verbose exclude each other\n";
    code = bad_input;
    return std::nullopt;
  }
  if (quiet || verbose)
    log::set_verbosity(quiet ? log::Verbosity::quiet : log::Verbosity::verbose);
  if (help || version || app.get_subcommands().empty()) {
    if (version)
      std::cout << "geocomp " << GEOCOMP_VERSION << " (git " << GEOCOMP_GIT_HASH << ")\n";
    else
      print_help(help ? std::cout : std::cerr); // options without a command: bad input
    code = help || version ? ok : bad_input;
    return std::nullopt;
  }
  const CLI::App *sub = app.get_subcommands().front();
  Dispatch d;
  for (const auto &c : commands())
    if (c.name == sub->get_name())
      d.command = &c;
  d.rest = sub->remaining();
  return d;
}

} // namespace
} // namespace geocomp::cli

int main(int argc, char **argv)
{
  using namespace geocomp::cli;
  set_mpi_arguments(argc, argv);
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string line = "geocomp";
  for (const auto &a : args)
    line += " " + a;
  set_command_line(line);
  int code = ok;
  const std::optional<Dispatch> d = dispatch(args, code);
  if (!d)
    return code;
  const Command &c = *d->command;
  for (const auto &a : d->rest)
    if (a == "--help" || a == "-h") {
      std::cout << c.usage;
      return ok;
    }
  try {
    code = c.run(d->rest);
    finalize_mpi();
    return code;
  } catch (const UsageError &e) {
    std::cerr << "geocomp " << c.name << ": " << e.what() << "\n\n" << c.usage;
    return bad_input;
  } catch (const geocomp::CaseError &e) {
    log::error(e.what());
    return bad_input;
  } catch (const std::exception &e) {
    log::error("geocomp " + c.name + ": run failed: " + e.what());
    return run_failure;
  }
}
