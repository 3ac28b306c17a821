#include "Log.h"

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <memory>

namespace geocomp::cli::log {

namespace {

Verbosity current = Verbosity::normal;

/// Built on first use: "geocomp" (stdout, the message alone) and "geocomp-stderr" (stderr,
/// led by the level: "warning: ", "error: ", "debug: "), each flushed at every message so
/// that they interleave with std::cout and std::cerr in order.
struct Loggers {
  std::shared_ptr<spdlog::logger> out, err;
  Loggers()
    : out(std::make_shared<spdlog::logger>("geocomp", std::make_shared<spdlog::sinks::stdout_sink_mt>())),
      err(std::make_shared<spdlog::logger>("geocomp-stderr", std::make_shared<spdlog::sinks::stderr_sink_mt>()))
  {
    out->set_pattern("%v");
    err->set_pattern("%l: %v");
    out->flush_on(spdlog::level::trace);
    err->flush_on(spdlog::level::trace);
    apply();
  }
  void apply()
  {
    out->set_level(current == Verbosity::quiet ? spdlog::level::warn : spdlog::level::info);
    err->set_level(current == Verbosity::verbose ? spdlog::level::debug : spdlog::level::warn);
  }
};

Loggers &loggers()
{
  static Loggers l;
  return l;
}

} // namespace

void set_verbosity(Verbosity v)
{
  current = v;
  loggers().apply();
}

Verbosity verbosity() { return current; }
bool progress_shown() { return current != Verbosity::quiet; }

void info(const std::string &text) { loggers().out->info(text); }
void warning(const std::string &text) { loggers().err->warn(text); }
void error(const std::string &text) { loggers().err->error(text); }
void debug(const std::string &text) { loggers().err->debug(text); }

} // namespace geocomp::cli::log
