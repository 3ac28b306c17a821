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

namespace {
/// Why stop condition `c` of `stage` can never hold, or "" if it can. `first`: the stage
/// starts the program (time and strains 0, known), so the direction of a kinematic axis
/// decides. Later stages start where the previous one ended, unknown here: only what no
/// start can change is checked (sign-definite quantities, stage time).
std::string never_holds(const Condition &c, const Stage &stage, bool first)
{
  const double v = c.value;
  switch (c.quantity) {
  case Quantity::GammaMax:
  case Quantity::TauMax:
  case Quantity::ServoError:
  case Quantity::PeakDrop:
  case Quantity::Time:
  case Quantity::StageTime:
    if (!c.at_least && v < 0.0)
      return "this quantity is never negative";
    if (c.quantity == Quantity::PeakDrop && c.at_least && v > 1.0)
      return "peak_drop is at most 1 (tau_max back to zero)";
    if (c.quantity == Quantity::StageTime && c.at_least && v > stage.max_duration)
      return "the stage ends on its max duration (" + std::to_string(stage.max_duration) + " s) before";
    if (c.quantity == Quantity::Time && first && c.at_least && v > stage.max_duration)
      return "the first stage ends on its max duration (" + std::to_string(stage.max_duration) + " s) before";
    return "";
  default:
    break;
  }
  if (!first)
    return "";
  // The first stage: strains start at 0 and a kinematic axis moves one way.
  int axis = -1;
  if (c.quantity == Quantity::EpsXX)
    axis = 0;
  else if (c.quantity == Quantity::EpsYY)
    axis = 1;
  else if (c.quantity == Quantity::EpsZZ)
    axis = 2;
  const bool away_from_zero = (c.at_least && v > 0.0) || (!c.at_least && v < 0.0);
  if (c.quantity == Quantity::VolumetricStrain && stage.isochoric && away_from_zero)
    return "the isochoric program keeps the volume (eps_vol = 0)";
  if (axis < 0 || !stage.kinematic(axis))
    return "";
  StageControl control;
  control.stage = &stage;
  const double rate = control.strain_rate(axis, 0.0);
  // The strain moves from 0 in the direction of its rate (S0 eq. (3): z lengthens).
  const bool moves_up = rate > 0.0 || (stage.isochoric && axis == 2);
  const bool moves_down = rate < 0.0;
  if (c.at_least && v > 0.0 && !moves_up)
    return "the strain starts at 0 and this axis does not lengthen";
  if (!c.at_least && v < 0.0 && !moves_down)
    return "the strain starts at 0 and this axis does not shorten";
  const double reached = control.strain(axis, stage.max_duration);
  if ((c.at_least && v > reached) || (!c.at_least && v < reached))
    return "the axis reaches only " + std::to_string(reached) + " within the stage's max duration (" +
           std::to_string(stage.max_duration) + " s)";
  return "";
}
} // namespace

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
    for (const Condition &c : s.stop_any) {
      const std::string why = never_holds(c, s, i == 0);
      if (!why.empty())
        throw ProgramError(w + "/stop when", "the stop condition '" + c.text + "' can never hold: " + why +
                                                 "; the stage would end only on its max duration");
    }
    if (!s.unload_to_start && !(s.unload_to_tau >= 0.0))
      throw ProgramError(w + "/unload to", "expected 'start' or a non-negative tau_max in Pa");
    if (!(s.peak_tolerance > 0.0 && s.peak_tolerance < 1.0))
      throw ProgramError(w + "/peak tolerance", "expected a fraction in (0, 1)");
    if (s.locate_elastic_limit && s.unload_at.empty())
      throw ProgramError(w + "/locate elastic limit",
                         "needs unloading branches ('unload at') whose residuals straddle 1 % to bisect between");
    if (s.locate_elastic_limit && !(s.elastic_limit_tolerance > 0.0))
      throw ProgramError(w + "/elastic limit tolerance", "expected a positive strain");
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
