#pragma once
// Progress of a running program on the terminal: a bar with ETA when stderr is a
// terminal, a one-line log every `log_interval` seconds otherwise (batch jobs, CI). An
// unloading branch keeps the overall bar where the main path left it and shows its own
// progress and ETA; specimen preparation (PhasePrinter) shows each phase with its own.
#include "common/ProgramRunner.h"

#include <chrono>
#include <optional>
#include <string>

namespace geocomp::cli {

class ProgressPrinter {
public:
  /// `terminal`: draw a bar (true) or log lines (false); by default, whether stderr is a terminal.
  explicit ProgressPrinter(std::string engine, double log_interval_seconds = 10.0,
                           std::optional<bool> terminal = std::nullopt);
  void operator()(const RunProgress &p);
  /// Ends the bar line (call once the run returns).
  void finish();

private:
  std::string engine_;
  bool tty_;
  double log_interval_;
  std::chrono::steady_clock::time_point start_, last_, branch_start_;
  bool drawn_ = false;
  int branch_ = 0;               ///< the branch under way (0: main path)
  double main_fraction_ = 0.0;   ///< the stage's fraction where the main path left off
};

/// The phases of specimen preparation (dem::PhaseProgress): "dem: preparing: growth
/// [####......] 40 %, 0.12 s of DEM time, elapsed 00:08, ETA 00:12", one bar per phase on
/// a terminal, a log line every `log_interval` seconds and at each phase's end otherwise.
class PhasePrinter {
public:
  explicit PhasePrinter(std::string engine, double log_interval_seconds = 10.0,
                        std::optional<bool> terminal = std::nullopt);
  void operator()(const std::string &phase, double dem_time, double fraction);
  void finish();

private:
  std::string engine_, phase_;
  bool tty_;
  double log_interval_;
  std::chrono::steady_clock::time_point phase_start_, last_;
  bool drawn_ = false;
};

} // namespace geocomp::cli
