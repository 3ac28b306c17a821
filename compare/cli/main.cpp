// geocomp: DEM and elastoplastic continuum runs of one loading program, compared.
#include "Commands.h"

#include "common/Version.h"
#include "common/case/CaseParameters.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <memory>
#include <iostream>

namespace geocomp::cli {

namespace {
int saved_argc = 0;
char **saved_argv = nullptr;
std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
} // namespace

void ensure_mpi()
{
  // Started only by commands that run engines: checking a case needs no MPI.
  if (!mpi)
    mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(saved_argc, saved_argv, 1);
}

void finalize_mpi() { mpi.reset(); }

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
      << "units: SI; stresses tension positive inside the code and in results files\n";
}
} // namespace

Arguments Arguments::parse(const std::vector<std::string> &args, const std::vector<std::string> &valued,
                           const std::vector<std::string> &flags)
{
  Arguments a;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string &s = args[i];
    if (s.rfind("--", 0) != 0 || s == "--") {
      a.positional.push_back(s);
      continue;
    }
    std::string name = s.substr(2), value;
    const auto eq = name.find('=');
    const bool inline_value = eq != std::string::npos;
    if (inline_value) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (std::find(valued.begin(), valued.end(), name) != valued.end()) {
      if (!inline_value) {
        if (i + 1 >= args.size())
          throw UsageError("option --" + name + " expects a value");
        value = args[++i];
      }
      a.options.emplace_back(name, value);
    } else if (std::find(flags.begin(), flags.end(), name) != flags.end() && !inline_value) {
      a.options.emplace_back(name, "");
    } else {
      throw UsageError("unknown option --" + name);
    }
  }
  return a;
}

bool Arguments::has(const std::string &name) const
{
  for (const auto &[n, v] : options)
    if (n == name)
      return true;
  return false;
}

std::string Arguments::get(const std::string &name, const std::string &fallback) const
{
  for (const auto &[n, v] : options)
    if (n == name)
      return v;
  return fallback;
}

} // namespace geocomp::cli

int main(int argc, char **argv)
{
  using namespace geocomp::cli;
  saved_argc = argc;
  saved_argv = argv;
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string line = "geocomp";
  for (const auto &a : args)
    line += " " + a;
  set_command_line(line);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(std::cout);
    return args.empty() ? bad_input : ok;
  }
  if (args[0] == "--version") {
    std::cout << "geocomp " << GEOCOMP_VERSION << " (git " << GEOCOMP_GIT_HASH << ")\n";
    return ok;
  }
  for (const auto &c : commands()) {
    if (c.name != args[0])
      continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    for (const auto &a : rest)
      if (a == "--help" || a == "-h") {
        std::cout << c.usage;
        return ok;
      }
    try {
      const int code = c.run(rest);
      finalize_mpi();
      return code;
    } catch (const UsageError &e) {
      std::cerr << "geocomp " << c.name << ": " << e.what() << "\n\n" << c.usage;
      return bad_input;
    } catch (const geocomp::CaseError &e) {
      std::cerr << "error: " << e.what() << "\n";
      return bad_input;
    } catch (const std::exception &e) {
      std::cerr << "geocomp " << c.name << ": run failed: " << e.what() << "\n";
      return run_failure;
    }
  }
  std::cerr << "geocomp: unknown command '" << args[0] << "'\n\n";
  print_help(std::cerr);
  return bad_input;
}
