// See CrossEngine.h: the rms differences of two engines' curves and of specimens.
#include "compare/CrossEngine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>

namespace geocomp::compare {

namespace {
/// The values of curve `key` along a curve: eta = q/p' (p' = -p), eps_v, or the plotted y.
std::vector<double> values(const Curve &c, const std::string &key)
{
  if (key == "volumetric_strain")
    return c.eps_v;
  if (key == "curve")
    return c.y;
  if (key != "stress_ratio")
    throw std::invalid_argument("no curve '" + key + "'");
  std::vector<double> eta(c.q.size());
  for (std::size_t i = 0; i < eta.size(); ++i)
    eta[i] = c.p[i] < 0.0 ? c.q[i] / -c.p[i] : nan; // no ratio without compression
  return eta;
}

/// The scale s_f of the reference's curve (CrossEngine.h).
double scale(const std::vector<double> &f, const std::string &key)
{
  double s = 0.0;
  for (double v : f)
    if (std::isfinite(v))
      s = std::max(s, std::abs(v));
  return key == "volumetric_strain" ? std::max(s, 1e-3) : s;
}

/// f at x by linear interpolation over the first segment of (xs, fs) that holds x; NaN
/// outside every segment.
double interpolate(const std::vector<double> &xs, const std::vector<double> &fs, double x)
{
  for (std::size_t j = 0; j + 1 < xs.size(); ++j) {
    const double a = xs[j], b = xs[j + 1];
    if (x < std::min(a, b) || x > std::max(a, b))
      continue;
    if (a == b)
      return fs[j];
    const double w = (x - a) / (b - a);
    return (1.0 - w) * fs[j] + w * fs[j + 1];
  }
  return nan;
}

std::string percent_up(double fraction)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", std::ceil(fraction * 1000.0 - 1e-9) / 10.0);
  return buf;
}
} // namespace

std::pair<double, std::size_t> relative_rms(const Curve &reference, const Curve &other, const std::string &key)
{
  const std::vector<double> f_ref = values(reference, key), f_other = values(other, key);
  double sum2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < reference.x.size(); ++i) {
    const double v = interpolate(other.x, f_other, reference.x[i]);
    if (!std::isfinite(v) || !std::isfinite(f_ref[i]))
      continue;
    sum2 += (v - f_ref[i]) * (v - f_ref[i]);
    ++n;
  }
  const double s = scale(f_ref, key);
  return {n > 0 && s > 0.0 ? std::sqrt(sum2 / double(n)) / s : nan, n};
}

CrossEngineTable cross_engine_table(const NamedCurve &reference, const NamedCurve &other,
                                    const std::vector<NamedCurve> &specimens)
{
  CrossEngineTable t;
  t.reference = reference.name;
  t.other = other.name;
  for (const auto &s : specimens)
    t.specimens.push_back(s.name);
  const std::string plotted = reference.curve.y_name + " (the plotted curve)";
  const std::vector<std::pair<std::string, std::string>> curves = {
    {"stress_ratio", "stress ratio q/p' (p' compression positive)"},
    {"volumetric_strain", "volumetric strain ln(V/V0)"},
    {"curve", plotted}};
  for (const auto &[key, label] : curves) {
    CrossEngineRow row;
    row.key = key;
    row.label = label;
    row.scale = scale(values(reference.curve, key), key);
    std::size_t n = 0;
    std::tie(row.engines, n) = relative_rms(reference.curve, other.curve, key);
    if (key == "stress_ratio")
      t.common_samples = n;
    for (const auto &s : specimens)
      row.specimens.push_back(relative_rms(reference.curve, s.curve, key).first);
    t.rows.push_back(row);
  }
  if (t.common_samples < 3)
    throw std::invalid_argument("fewer than 3 samples of " + reference.name + " lie inside " + other.name +
                                "'s strain range");
  t.agreement = std::max(t.rows[0].engines, t.rows[1].engines);
  t.verdict = "engines agree within " + percent_up(t.agreement) + " % (rms of the stress ratio and of the "
              "volumetric strain, the larger)";
  if (!specimens.empty()) {
    double seeds = 0.0;
    for (std::size_t r = 0; r < 2; ++r)
      for (double v : t.rows[r].specimens)
        seeds = std::max(seeds, std::isfinite(v) ? v : 0.0);
    t.scatter_note = "specimens of the same program differ from " + reference.name + " by up to " + percent_up(seeds) +
                     " %: the engines' difference is " +
                     (t.agreement <= seeds ? "within the specimen-to-specimen scatter"
                                           : "larger than the specimen-to-specimen scatter");
  }
  return t;
}

} // namespace geocomp::compare
