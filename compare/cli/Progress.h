#pragma once
// Progress of a running program on the terminal: a bar with ETA when stderr is a
// terminal, a one-line log every `log_interval` seconds otherwise (batch jobs, CI).
#include "common/ProgramRunner.h"

#include <chrono>
#include <string>

namespace geocomp::cli {

class ProgressPrinter {
public:
  explicit ProgressPrinter(std::string engine, double log_interval_seconds = 10.0);
  void operator()(const RunProgress &p);
  /// Ends the bar line (call once the run returns).
  void finish();

private:
  std::string engine_;
  bool tty_;
  double log_interval_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

} // namespace geocomp::cli
