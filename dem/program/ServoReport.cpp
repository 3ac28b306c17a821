#include "dem/program/ServoReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace geocomp::dem {

namespace {
/// The stage's fastest kinematic axis, -1 if none.
int axial_axis(const Stage &stage)
{
  int axial = -1;
  for (int a = 0; a < 3; ++a)
    if (!stage.axes[a].is_stress() &&
        (axial < 0 || std::abs(stage.axes[a].value) > std::abs(stage.axes[axial].value)))
      axial = a;
  return axial;
}

int column(const Response &r, const char *name)
{
  const int k = r.extra_index(name);
  if (k < 0)
    throw std::invalid_argument(std::string("servo_report: the response has no '") + name + "' column");
  return k;
}
} // namespace

double ServoReport::worst_mean() const
{
  double w = 0.0;
  for (const AxisDeviation &a : axes)
    w = std::max(w, a.mean);
  return w;
}

double ServoReport::worst_instantaneous() const
{
  double w = 0.0;
  for (const AxisDeviation &a : axes)
    w = std::max(w, a.instantaneous);
  return w;
}

double ServoReport::worst_step() const
{
  double w = 0.0;
  for (const AxisDeviation &a : axes)
    w = std::max(w, a.step);
  return w;
}

std::string ServoReport::describe() const
{
  std::string out;
  char line[256];
  for (const AxisDeviation &a : axes) {
    std::snprintf(line, sizeof line,
                  "stage %d axis %c: goal %.6g Pa, interval mean within %.3f %% (worst %+.3f %%), "
                  "instantaneous %.3f %%, any step %.3f %% (%zu samples)\n",
                  a.stage + 1, "xyz"[a.axis], a.goal, 100.0 * a.mean, 100.0 * a.mean_signed,
                  100.0 * a.instantaneous, 100.0 * a.step, a.samples);
    out += line;
  }
  std::snprintf(line, sizeof line, "servo wall-speed reversals: %.0f in %.0f steps\n", reversals, steps);
  return out + line;
}

ServoReport servo_report(const Response &r, const LoadingProgram &program, double allowance)
{
  const int k_dev = column(r, "servo_deviation"), k_rev = column(r, "servo_reversals"), k_steps = column(r, "steps");
  ServoReport report;
  for (std::size_t si = 0; si < program.stages.size(); ++si) {
    const Stage &stage = program.stages[si];
    if (!stage.has_stress_axis())
      continue;
    const int axial = axial_axis(stage);
    if (axial < 0) // every axis on a stress goal: an approach, ended by its own stop condition
      continue;
    std::vector<const ResponseSample *> path;
    for (const ResponseSample *s : r.path(0))
      if (s->stage == int(si))
        path.push_back(s);
    if (path.size() < 2)
      continue;
    const double eps0 = path.front()->strain(axial, axial);
    const std::size_t first = report.axes.size();
    for (int a = 0; a < 3; ++a)
      if (stage.axes[a].is_stress())
        report.axes.push_back({int(si), a, stage.axes[a].value});
    const double *previous_steps = &path.front()->extras[k_steps];
    for (std::size_t k = 1; k < path.size(); ++k) {
      const ResponseSample &s = *path[k];
      const double steps = s.extras[k_steps] - *previous_steps;
      previous_steps = &s.extras[k_steps];
      if (std::abs(s.strain(axial, axial) - eps0) < allowance)
        continue;
      report.reversals += s.extras[k_rev];
      report.steps += steps;
      for (std::size_t j = first; j < report.axes.size(); ++j) {
        AxisDeviation &d = report.axes[j];
        const double scale = d.goal != 0.0 ? std::abs(d.goal) : 1.0;
        const double mean = (s.stress_mean(d.axis, d.axis) - d.goal) / scale;
        if (std::abs(mean) > d.mean) {
          d.mean = std::abs(mean);
          d.mean_signed = mean;
        }
        d.instantaneous = std::max(d.instantaneous, std::abs(s.stress(d.axis, d.axis) - d.goal) / scale);
        d.step = std::max(d.step, s.extras[k_dev]);
        ++d.samples;
      }
    }
  }
  return report;
}

} // namespace geocomp::dem
