#include "Progress.h"
#include "Log.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace geocomp::cli {

ProgressPrinter::ProgressPrinter(std::string engine, double log_interval_seconds, std::optional<bool> terminal)
  : engine_(std::move(engine)), tty_(terminal.value_or(::isatty(STDERR_FILENO) != 0)),
    log_interval_(log_interval_seconds),
    start_(std::chrono::steady_clock::now()), last_(start_)
{
}

namespace {
std::string clock(double seconds)
{
  if (!(seconds >= 0) || seconds > 1e7)
    return "--:--";
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", s / 60, s % 60);
  return buf;
}

/// "[#####.....]" for a fraction in [0, 1].
std::string bar(double fraction, int width = 30)
{
  std::string b(static_cast<std::size_t>(std::clamp(fraction, 0.0, 1.0) * width + 0.5), '#');
  b.resize(static_cast<std::size_t>(width), '.');
  return "[" + b + "]";
}

/// Seconds left when `fraction` of a task took `elapsed` seconds (-1: unknown yet).
double eta_of(double elapsed, double fraction)
{
  return fraction > 1e-3 ? elapsed * (1.0 - fraction) / fraction : -1.0;
}

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}
} // namespace

void ProgressPrinter::operator()(const RunProgress &p)
{
  if (!log::progress_shown())
    return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = seconds_between(start_, now);
  if (p.branch != branch_) {
    branch_ = p.branch;
    branch_start_ = now;
  }
  if (p.branch == 0)
    main_fraction_ = p.stage_fraction;
  // Overall fraction: finished stages plus the current one's estimate (a branch holds the
  // main path's); a branch also shows its own progress towards its target and its ETA.
  const double overall = (p.stage + main_fraction_) / std::max(1, p.stage_count);
  const double eta = eta_of(elapsed, overall);
  std::string branch;
  if (p.branch) {
    const double branch_eta = eta_of(seconds_between(branch_start_, now), p.stage_fraction);
    branch = " branch " + std::to_string(p.branch) + " " + std::to_string(int(100 * p.stage_fraction + 0.5)) +
             "% (ETA " + clock(branch_eta) + ")";
  }
  const double gamma = p.sample ? gamma_max(p.sample->strain) : 0.0;
  const double tau = p.sample ? tau_max(p.sample->stress) : 0.0;
  char line[320];
  if (tty_) {
    std::snprintf(line, sizeof line, "\r%s %s %3.0f%% stage %d/%d%s gamma %.4f tau %.3g MPa  %s elapsed, ETA %s ",
                  engine_.c_str(), bar(overall).c_str(), 100 * overall, p.stage + 1, p.stage_count, branch.c_str(),
                  gamma, tau * 1e-6, clock(elapsed).c_str(), clock(eta).c_str());
    std::cerr << line << std::flush;
    drawn_ = true;
  } else if (seconds_between(last_, now) >= log_interval_) {
    last_ = now;
    std::snprintf(line, sizeof line, "%s: %.0f%% stage %d/%d%s t=%.4g s gamma_max=%.4f tau_max=%.4g MPa elapsed %s ETA %s",
                  engine_.c_str(), 100 * overall, p.stage + 1, p.stage_count, branch.c_str(), p.time, gamma,
                  tau * 1e-6, clock(elapsed).c_str(), clock(eta).c_str());
    std::cerr << line << "\n";
  }
}

void ProgressPrinter::finish()
{
  if (drawn_)
    std::cerr << "\n";
  drawn_ = false;
}

PhasePrinter::PhasePrinter(std::string engine, double log_interval_seconds, std::optional<bool> terminal)
  : engine_(std::move(engine)), tty_(terminal.value_or(::isatty(STDERR_FILENO) != 0)),
    log_interval_(log_interval_seconds),
    phase_start_(std::chrono::steady_clock::now()), last_(phase_start_)
{
}

void PhasePrinter::operator()(const std::string &phase, double dem_time, double fraction)
{
  if (!log::progress_shown())
    return;
  const auto now = std::chrono::steady_clock::now();
  const bool new_phase = phase != phase_;
  if (new_phase) {
    if (drawn_)
      std::cerr << "\n";
    drawn_ = false;
    phase_ = phase;
    phase_start_ = now;
  }
  const double elapsed = seconds_between(phase_start_, now);
  char line[320];
  std::snprintf(line, sizeof line, "%s: preparing: %s %s %3.0f%%, %.4g s of DEM time, elapsed %s, ETA %s",
                engine_.c_str(), phase.c_str(), bar(fraction, 20).c_str(), 100 * fraction, dem_time,
                clock(elapsed).c_str(), clock(fraction >= 1.0 ? 0.0 : eta_of(elapsed, fraction)).c_str());
  if (tty_) {
    std::cerr << "\r" << line << " " << std::flush;
    drawn_ = true;
  } else if (new_phase || fraction >= 1.0 || seconds_between(last_, now) >= log_interval_) {
    last_ = now;
    std::cerr << line << "\n";
  }
}

void PhasePrinter::finish()
{
  if (drawn_)
    std::cerr << "\n";
  drawn_ = false;
}

} // namespace geocomp::cli
