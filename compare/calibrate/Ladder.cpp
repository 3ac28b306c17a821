#include "compare/calibrate/Ladder.h"

#include "compare/calibrate/StartingValues.h"
#include "continuum/driver/CaseMaterial.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace geocomp::calibration {

namespace {
constexpr double inv_sqrt3 = 0.57735026918962576;

std::string family_of(const std::string &name) { return name.substr(0, name.find('[')); }

bool frees(const CalibrationParameters &o, const std::string &family)
{
  return std::any_of(o.free_parameters.begin(), o.free_parameters.end(),
                     [&](const std::string &f) { return family_of(f) == family; });
}

double largest(const HardeningTable &t)
{
  double v = t.points.front().second;
  for (const auto &point : t.points)
    v = std::max(v, point.second);
  return v;
}

/// E, nu, c, phi, psi each one number: each freed table becomes its largest knot at kappa = 0.
RungProblem constant_problem(const LadderInput &in)
{
  RungProblem out{*in.section, *in.options};
  out.start.model = "mohr-coulomb";
  out.options.free_parameters.clear();
  const std::pair<const char *, HardeningTable *> tables[] = {{"cohesion", &out.start.cohesion},
                                                               {"friction", &out.start.friction_angle},
                                                               {"dilatancy", &out.start.dilatancy_angle}};
  for (const char *f : {"E", "nu"})
    if (frees(*in.options, f))
      out.options.free_parameters.push_back(f);
  for (const auto &[family, table] : tables)
    if (frees(*in.options, family)) {
      out.options.free_parameters.push_back(family);
      table->points = {{0.0, largest(*table)}};
    }
  out.start = starting_values(out.start, *in.targets, out.options).parameters;
  return out;
}

/// S1's model started from a Mohr-Coulomb section on its compression cone (Ladder.h).
RungProblem nikolaevsky_problem(const LadderInput &in, const ContinuumParameters &mc)
{
  RungProblem out{*in.section, *in.options};
  out.start.model = "nikolaevsky";
  const double deg = M_PI / 180.0;
  const double c = largest(mc.cohesion), s = std::sin(largest(mc.friction_angle) * deg);
  const double sp = std::sin(largest(mc.dilatancy_angle) * deg);
  const double omega = 2.0 * s / (std::sqrt(3.0) * (3.0 - s));
  const double y0 = 6.0 * c * std::sqrt(1.0 - s * s) / (std::sqrt(3.0) * (3.0 - s));
  double q_scale = 0.0;
  for (const FitTarget &t : *in.targets)
    q_scale = std::max(q_scale, t.q_scale);
  NikolaevskyParameters &n = out.start.nikolaevsky;
  n.material = "custom";
  n.youngs_modulus = mc.youngs_modulus;
  n.poisson_ratio = mc.poisson_ratio;
  n.internal_friction = 3.0 * omega;
  n.yield_stress = std::max(y0 / (inv_sqrt3 - omega), 1e-3 * q_scale);
  n.compressive_strength = 1.1 * n.yield_stress;
  n.dilatancy = std::min(6.0 * sp / (std::sqrt(3.0) * (3.0 - sp)), 1.5);
  n.plastic_strain_at_strength = 0.01;
  out.options.free_parameters.clear();
  const std::pair<const char *, const char *> map[] = {{"E", "E"},
                                                        {"nu", "nu"},
                                                        {"cohesion", "yield stress"},
                                                        {"friction", "internal friction"},
                                                        {"dilatancy", "lambda"}};
  for (const auto &[mc_family, s1_name] : map)
    if (frees(*in.options, mc_family))
      out.options.free_parameters.push_back(s1_name);
  if (frees(*in.options, "cohesion") || frees(*in.options, "friction"))
    out.options.free_parameters.push_back("compressive strength");
  return out;
}

std::string value_text(double v)
{
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

/// The rung's row from its fit: RSS = 2 F, the rms of each quantity over all curves, the
/// held-out curve's rms when there is one.
compare::LadderRung rung_row(const std::string &name, const CalibrationResult &r, const FitTarget *held_out)
{
  compare::LadderRung row;
  row.name = name;
  row.k = r.parameters.size();
  row.n = r.residuals;
  row.rss = 2.0 * r.final_cost;
  row.seconds = r.seconds;
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    row.parameters.push_back(r.parameters[i].name + " = " + value_text(r.value[i]));
  auto rms = [](const std::vector<std::vector<ResidualSummary>> &curves, const std::string &quantity) {
    double sum = 0.0;
    std::size_t count = 0;
    for (const auto &rows : curves)
      for (const ResidualSummary &q : rows)
        if (q.quantity == quantity)
          for (double v : q.values) {
            sum += v * v;
            ++count;
          }
    return count ? std::sqrt(sum / double(count)) : compare::nan;
  };
  row.rms_q = rms(r.residual_summary, "q");
  row.rms_p = rms(r.residual_summary, "p");
  row.rms_eps_v = rms(r.residual_summary, "eps_v");
  if (held_out) {
    const Response predicted = simulate(*held_out, continuum::material_from_case(r.calibrated));
    const std::vector<std::vector<ResidualSummary>> one = {summarize_residuals(*held_out, predicted, r.quantities)};
    row.held_out_q = rms(one, "q");
    row.held_out_p = rms(one, "p");
    row.held_out_eps_v = rms(one, "eps_v");
  }
  return row;
}
} // namespace

RungProblem rung_problem(const std::string &rung, const LadderInput &in, const CalibrationResult *constant)
{
  if (rung == "mohr-coulomb constant")
    return constant_problem(in);
  if (rung == "nikolaevsky")
    return nikolaevsky_problem(in, constant ? constant->calibrated : constant_problem(in).start);
  if (rung != "mohr-coulomb tables" && rung != "drucker-prager")
    throw CalibrationError("ladder", "'" + rung + "' is not a rung of the model ladder");
  RungProblem out{*in.section, *in.options};
  out.start.model = rung == "drucker-prager" ? "drucker-prager" : "mohr-coulomb";
  out.start = starting_values(out.start, *in.targets, out.options).parameters;
  return out;
}

std::vector<compare::LadderRung> run_ladder(const LadderInput &in)
{
  std::vector<compare::LadderRung> rows;
  std::optional<CalibrationResult> constant;
  const std::vector<std::string> &names = in.options->ladder;
  // The constant rung first when nikolaevsky needs its fit as a start.
  std::vector<std::string> order = names;
  std::stable_partition(order.begin(), order.end(), [](const std::string &s) { return s == "mohr-coulomb constant"; });
  std::vector<compare::LadderRung> fitted(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    fitted[i].name = order[i];
    try {
      const RungProblem problem = rung_problem(order[i], in, constant ? &*constant : nullptr);
      const CalibrationResult r = calibrate(problem.start, *in.targets, problem.options);
      if (order[i] == "mohr-coulomb constant")
        constant = r;
      fitted[i] = rung_row(order[i], r, in.held_out);
    } catch (const CalibrationError &e) {
      fitted[i].failure = "parameter '" + e.parameter + "': " + e.what();
    } catch (const std::exception &e) {
      fitted[i].failure = e.what();
    }
  }
  for (const std::string &name : names) // back in the case's order
    rows.push_back(*std::find_if(fitted.begin(), fitted.end(), [&](const compare::LadderRung &r) { return r.name == name; }));
  compare::rank_rungs(rows);
  return rows;
}

std::string ladder_summary(const std::vector<compare::LadderRung> &rungs)
{
  std::ostringstream out;
  out << "model ladder (AIC = n ln(RSS/n) + 2k, BIC = n ln(RSS/n) + k ln n):\n";
  for (const compare::LadderRung &r : rungs) {
    out << "  " << r.name << ": ";
    if (!r.failure.empty())
      out << "not fitted (" << r.failure << ")\n";
    else
      out << "k " << r.k << ", n " << r.n << ", RSS " << r.rss << ", AIC " << r.aic << " (delta " << r.delta_aic
          << "), BIC " << r.bic << " (delta " << r.delta_bic << "), " << r.seconds << " s\n";
  }
  return out.str();
}

} // namespace geocomp::calibration
