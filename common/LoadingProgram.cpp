#include "common/LoadingProgram.h"

#include <cmath>
#include <map>
#include <sstream>

namespace geocomp {

namespace {
const std::map<std::string, Quantity> &quantity_names()
{
  static const std::map<std::string, Quantity> names = {
    {"time", Quantity::Time},         {"stage_time", Quantity::StageTime},
    {"eps_xx", Quantity::EpsXX},      {"eps_yy", Quantity::EpsYY},
    {"eps_zz", Quantity::EpsZZ},      {"sig_xx", Quantity::SigXX},
    {"sig_yy", Quantity::SigYY},      {"sig_zz", Quantity::SigZZ},
    {"gamma_max", Quantity::GammaMax}, {"tau_max", Quantity::TauMax},
    {"eps_vol", Quantity::VolumetricStrain}, {"mean_stress", Quantity::MeanStress},
    {"stress_ratio", Quantity::StressRatio}, {"peak_drop", Quantity::PeakDrop},
    {"servo_error", Quantity::ServoError}};
  return names;
}

std::string trim(const std::string &s)
{
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos)
    return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}
} // namespace

std::string condition_quantity_names()
{
  std::string out;
  for (const auto &[name, q] : quantity_names())
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

Condition parse_condition(const std::string &text, const std::string &where)
{
  const std::string t = trim(text);
  const auto ge = t.find(">=");
  const auto le = t.find("<=");
  if ((ge == std::string::npos) == (le == std::string::npos))
    throw ProgramError(where, "expected a condition 'QUANTITY >= VALUE' or 'QUANTITY <= VALUE', got '" + t + "'");
  const auto op = ge != std::string::npos ? ge : le;
  const std::string name = trim(t.substr(0, op));
  const std::string value = trim(t.substr(op + 2));
  const auto it = quantity_names().find(name);
  if (it == quantity_names().end())
    throw ProgramError(where, "unknown quantity '" + name + "' in condition '" + t +
                                "'; expected one of: " + condition_quantity_names());
  Condition c;
  c.quantity = it->second;
  c.at_least = ge != std::string::npos;
  c.text = t;
  try {
    std::size_t used = 0;
    c.value = std::stod(value, &used);
    if (used != value.size() || !std::isfinite(c.value))
      throw std::invalid_argument(value);
  } catch (const std::exception &) {
    throw ProgramError(where, "expected a finite number after the comparison in '" + t + "', got '" + value + "'");
  }
  return c;
}

BranchTrigger parse_trigger(const std::string &text, const std::string &where)
{
  BranchTrigger b;
  b.text = trim(text);
  if (b.text == "peak") {
    b.kind = BranchTrigger::Kind::AtPeak;
    return b;
  }
  b.kind = BranchTrigger::Kind::WhenCondition;
  b.condition = parse_condition(b.text, where);
  return b;
}

bool Stage::has_stress_axis() const
{
  if (isochoric)
    return false;
  for (const auto &a : axes)
    if (a.is_stress())
      return true;
  return false;
}

void LoadingProgram::validate() const
{
  if (stages.empty())
    throw ProgramError("program", "the loading program has no stage; expected at least one 'subsection stage 1'");
  if (!(sample_interval > 0.0) || !std::isfinite(sample_interval))
    throw ProgramError("program/sampling interval", "expected a positive time in seconds");
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const Stage &s = stages[i];
    const std::string w = "program/stage " + std::to_string(i + 1);
    if (s.isochoric) {
      if (!(s.lambda >= -1.0 && s.lambda <= 1.0))
        throw ProgramError(w + "/lambda", "S0 eq. (3) needs lambda in [-1, 1], got " + std::to_string(s.lambda));
      if (!(s.isochoric_rate > 0.0))
        throw ProgramError(w + "/isochoric rate", "expected a positive rate 2 v0 / L0 in 1/s");
    } else {
      bool moves = false;
      for (const auto &a : s.axes)
        moves = moves || a.is_stress() || a.value != 0.0;
      if (!moves)
        throw ProgramError(w, "every axis is fixed: nothing would load the specimen; give a rate or a stress on at least one axis");
    }
    if (s.stop_any.empty())
      throw ProgramError(w + "/stop when", "expected at least one stop condition");
    if (!(s.max_duration > 0.0) || !std::isfinite(s.max_duration))
      throw ProgramError(w + "/max duration", "expected a positive time in seconds");
    if (s.max_duration < sample_interval)
      throw ProgramError(w + "/max duration", "is shorter than the sampling interval");
    if (!s.unload_to_start && !(s.unload_to_tau >= 0.0))
      throw ProgramError(w + "/unload to", "expected 'start' or a non-negative tau_max in Pa");
    if (!(s.peak_tolerance > 0.0 && s.peak_tolerance < 1.0))
      throw ProgramError(w + "/peak tolerance", "expected a fraction in (0, 1)");
    if (!s.unload_at.empty() && s.has_stress_axis() == false && !s.isochoric) {
      bool any_rate = false;
      for (const auto &a : s.axes)
        any_rate = any_rate || a.value != 0.0;
      if (!any_rate)
        throw ProgramError(w + "/unload at", "unloading needs a kinematic axis to reverse");
    }
  }
}

double StageControl::strain(int axis, double t) const
{
  const Stage &s = *stage;
  const double dt = direction * (t - t0);
  if (!s.isochoric)
    return eps0[axis] + s.axes[axis].value * dt;
  // S0 eq. (3), imposed as positions: x and y walls move in at v0 and lambda v0,
  // L_z = V / (L_x L_y) keeps the volume of the box at t0.
  const double ex = eps0[0] - s.isochoric_rate * dt;
  const double ey = eps0[1] - s.lambda * s.isochoric_rate * dt;
  if (axis == 0)
    return ex;
  if (axis == 1)
    return ey;
  const double volume = (1.0 + eps0[0]) * (1.0 + eps0[1]) * (1.0 + eps0[2]);
  return volume / ((1.0 + ex) * (1.0 + ey)) - 1.0;
}

double StageControl::strain_rate(int axis, double t) const
{
  const Stage &s = *stage;
  if (!s.isochoric)
    return direction * s.axes[axis].value;
  const double rx = -direction * s.isochoric_rate;
  const double ry = -direction * s.lambda * s.isochoric_rate;
  if (axis == 0)
    return rx;
  if (axis == 1)
    return ry;
  const double ex = 1.0 + strain(0, t), ey = 1.0 + strain(1, t);
  const double volume = (1.0 + eps0[0]) * (1.0 + eps0[1]) * (1.0 + eps0[2]);
  return -volume * (rx * ey + ry * ex) / (ex * ex * ey * ey);
}

} // namespace geocomp
