// One subcommand's command line, parsed by CLI11 (Debian's libcli11-dev): the options a
// command declares (`--name value` or `--name=value`, and flags) and its positional
// arguments. A malformed line (an option the command does not have, an option without its
// value) is a UsageError with CLI11's message, which main prints with the command's usage
// and exit code 2. -q/--quiet and -v/--verbose belong to every command (Log.h). Each command prints its own usage text for --help (main.cpp), so CLI11's
// generated help is switched off here.
#include "Commands.h"
#include "Log.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <map>

namespace geocomp::cli {

Arguments Arguments::parse(const std::vector<std::string> &args, const std::vector<std::string> &valued,
                           const std::vector<std::string> &flags)
{
  CLI::App app;
  app.set_help_flag();
  Arguments a;
  app.add_option("arguments", a.positional);
  std::map<std::string, std::vector<std::string>> values;
  std::map<std::string, std::int64_t> counts;
  for (const std::string &name : valued)
    app.add_option("--" + name, values[name])->allow_extra_args(false);
  for (const std::string &name : flags)
    app.add_flag("--" + name, counts[name]);
  bool quiet = false, verbose = false; // every command's (Log.h)
  app.add_flag("-q,--quiet", quiet);
  app.add_flag("-v,--verbose", verbose);
  std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError &e) {
    throw UsageError(e.what());
  }
  if (quiet && verbose)
    throw UsageError("--quiet and --verbose exclude each other");
  if (quiet || verbose)
    log::set_verbosity(quiet ? log::Verbosity::quiet : log::Verbosity::verbose);
  for (const std::string &name : valued)
    for (const std::string &v : values[name])
      a.options.emplace_back(name, v);
  for (const std::string &name : flags)
    if (counts[name] > 0)
      a.options.emplace_back(name, "");
  return a;
}

bool Arguments::has(const std::string &name) const
{
  return std::any_of(options.begin(), options.end(), [&](const auto &o) { return o.first == name; });
}

std::string Arguments::get(const std::string &name, const std::string &fallback) const
{
  for (const auto &[n, v] : options)
    if (n == name)
      return v;
  return fallback;
}

} // namespace geocomp::cli
