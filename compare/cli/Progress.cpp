#include "Progress.h"

#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace geocomp::cli {

ProgressPrinter::ProgressPrinter(std::string engine, double log_interval_seconds)
  : engine_(std::move(engine)), tty_(::isatty(STDERR_FILENO) != 0), log_interval_(log_interval_seconds),
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
} // namespace

void ProgressPrinter::operator()(const RunProgress &p)
{
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // Overall fraction: finished stages plus the current one's estimate.
  const double overall = (p.stage + (p.branch ? 0.0 : p.stage_fraction)) / std::max(1, p.stage_count);
  const double eta = overall > 1e-3 ? elapsed * (1.0 - overall) / overall : -1.0;
  const double gamma = p.sample ? gamma_max(p.sample->strain) : 0.0;
  const double tau = p.sample ? tau_max(p.sample->stress) : 0.0;
  char line[256];
  if (tty_) {
    const int width = 30, filled = static_cast<int>(overall * width + 0.5);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::snprintf(line, sizeof line, "\r%s [%s] %3.0f%% stage %d/%d%s gamma %.4f tau %.3g MPa  %s elapsed, ETA %s ",
                  engine_.c_str(), bar.c_str(), 100 * overall, p.stage + 1, p.stage_count,
                  p.branch ? (" branch " + std::to_string(p.branch)).c_str() : "", gamma, tau * 1e-6,
                  clock(elapsed).c_str(), clock(eta).c_str());
    std::cerr << line << std::flush;
    drawn_ = true;
  } else if (std::chrono::duration<double>(now - last_).count() >= log_interval_) {
    last_ = now;
    std::snprintf(line, sizeof line, "%s: %.0f%% stage %d/%d%s t=%.4g s gamma_max=%.4f tau_max=%.4g MPa elapsed %s ETA %s",
                  engine_.c_str(), 100 * overall, p.stage + 1, p.stage_count,
                  p.branch ? (" branch " + std::to_string(p.branch)).c_str() : "", p.time, gamma, tau * 1e-6,
                  clock(elapsed).c_str(), clock(eta).c_str());
    std::cerr << line << "\n";
  }
}

void ProgressPrinter::finish()
{
  if (drawn_)
    std::cerr << "\n";
  drawn_ = false;
}

} // namespace geocomp::cli
