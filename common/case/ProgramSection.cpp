// The `program` section: the LoadingProgram both engines run.
#include "common/case/SectionReader.h"
#include "common/case/CanonicalText.h"

#include <cmath>
#include <sstream>

namespace geocomp::sections {

using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Selection;

namespace {
std::vector<std::string> split(const std::string &text, char sep)
{
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, sep)) {
    const auto b = item.find_first_not_of(" \t");
    if (b == std::string::npos)
      continue;
    out.push_back(item.substr(b, item.find_last_not_of(" \t") - b + 1));
  }
  return out;
}

AxisDrive parse_axis(const std::string &text, const std::string &parameter, const Reader &r)
{
  std::stringstream ss(text);
  std::string kind, value, extra;
  ss >> kind >> value;
  if (ss >> extra)
    r.fail(parameter, "expected one drive per axis, 'rate <1/s>' or 'stress <Pa>' (not both), got '" + text + "'");
  if (kind != "rate" && kind != "stress")
    r.fail(parameter, "expected 'rate <strain rate in 1/s>' or 'stress <Pa, tension positive>', got '" + text + "'");
  double v = 0;
  try {
    std::size_t used = 0;
    v = std::stod(value, &used);
    if (used != value.size())
      throw std::invalid_argument(value);
  } catch (const std::exception &) {
    r.fail(parameter, "expected a number after '" + kind + "', got '" + value + "'");
  }
  if (!std::isfinite(v))
    r.fail(parameter, "expected a finite number, got '" + value + "'");
  return kind == "rate" ? AxisDrive::rate(v) : AxisDrive::stress(v);
}
} // namespace

void declare_program(dealii::ParameterHandler &prm, unsigned int stages)
{
  prm.enter_subsection("program");
  prm.declare_entry("sampling interval", "0.01", Double(0, 1e12),
                    "Time [s] between recorded samples (the same for both engines).");
  for (unsigned int i = 1; i <= stages; ++i) {
    prm.enter_subsection("stage " + std::to_string(i));
    prm.declare_entry("name", "", Anything(), "Stage name shown in results and reports.");
    prm.declare_entry("mode", "axes", Selection("axes|isochoric"),
                      "'axes': each axis driven by x, y, z; 'isochoric': S0 eq. (3) with lambda and rate.");
    for (const char *axis : {"x", "y", "z"})
      prm.declare_entry(axis, "rate 0", Anything(),
                        "Drive of this axis: 'rate R' (engineering strain rate [1/s], tension positive; "
                        "platens move symmetrically) or 'stress S' (target stress [Pa], tension positive, "
                        "held by servo walls / tractions).");
    prm.declare_entry("lambda", "0", Double(-1, 1), "S0 eq. (3): v_y = lambda v_x, in [-1, 1].");
    prm.declare_entry("isochoric rate", "0", Double(0, 1e6),
                      "S0 eq. (3): 2 v0 / L0 [1/s], the rate at which the x walls close in.");
    prm.declare_entry("stop when", "", Anything(),
                      "Conditions separated by ';', the stage ends when any holds: 'QUANTITY >= V' or "
                      "'QUANTITY <= V' with QUANTITY one of " + condition_quantity_names() + ".");
    prm.declare_entry("max duration", "1e3", Double(0, 1e12), "Safety limit on the stage time [s].");
    prm.declare_entry("unload at", "", Anything(),
                      "Unloading branches (S0 Fig. 2), separated by ';': a condition ('gamma_max >= 0.02', "
                      "'peak_drop >= 0.1') or 'peak'. Empty: none.");
    prm.declare_entry("unload to", "start", Anything(),
                      "Where a branch stops: 'start' (the shear stress at the start of the stage) or a tau_max [Pa].");
    prm.declare_entry("peak tolerance", "0.01", Double(1e-6, 0.5),
                      "Relative drop of tau_max that confirms a peak (for 'peak' branches).");
    prm.declare_entry("locate elastic limit", "false", Bool(),
                      "After the main path, bisect between the neighbouring 'unload at' branches whose "
                      "residual gamma_max straddles S0's 1 % with extra unloading branches, until their "
                      "start strains are closer than the elastic limit tolerance (docs/metrics.md).");
    prm.declare_entry("elastic limit tolerance", "0.001", Double(1e-9, 1),
                      "Width [strain, gamma_max] below which the located elastic limit's bracket stops.");
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

LoadingProgram parse_program(dealii::ParameterHandler &prm, unsigned int stages, const Reader &r)
{
  LoadingProgram p;
  try {
  prm.enter_subsection("program");
  p.sample_interval = prm.get_double("sampling interval");
  for (unsigned int i = 1; i <= stages; ++i) {
    const std::string where = "program/stage " + std::to_string(i) + "/";
    prm.enter_subsection("stage " + std::to_string(i));
    Stage s;
    s.name = prm.get("name");
    if (s.name.empty())
      s.name = "stage " + std::to_string(i);
    s.isochoric = prm.get("mode") == "isochoric";
    const char *axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
      s.axes[a] = parse_axis(prm.get(axes[a]), where + axes[a], r);
    s.lambda = prm.get_double("lambda");
    s.isochoric_rate = prm.get_double("isochoric rate");
    for (const auto &c : split(prm.get("stop when"), ';'))
      s.stop_any.push_back(parse_condition(c, where + "stop when"));
    s.max_duration = prm.get_double("max duration");
    for (const auto &t : split(prm.get("unload at"), ';'))
      s.unload_at.push_back(parse_trigger(t, where + "unload at"));
    const std::string to = prm.get("unload to");
    if (to == "start")
      s.unload_to_start = true;
    else {
      s.unload_to_start = false;
      try {
        std::size_t used = 0;
        s.unload_to_tau = std::stod(to, &used);
        if (used != to.size())
          throw std::invalid_argument(to);
      } catch (const std::exception &) {
        r.fail(where + "unload to", "expected 'start' or a shear stress in Pa, got '" + to + "'");
      }
    }
    s.peak_tolerance = prm.get_double("peak tolerance");
    s.locate_elastic_limit = prm.get_bool("locate elastic limit");
    s.elastic_limit_tolerance = prm.get_double("elastic limit tolerance");
    if (s.isochoric)
      for (int a = 0; a < 3; ++a)
        if (s.axes[a].is_stress() || s.axes[a].value != 0.0)
          r.fail(where + axes[a], "mode = isochoric drives all three axes by S0 eq. (3); leave x, y, z unset");
    prm.leave_subsection();
    p.stages.push_back(s);
  }
  prm.leave_subsection();
    p.validate();
  } catch (const ProgramError &e) {
    r.fail(e.where, e.what());
  }
  return p;
}

std::string program_text(const LoadingProgram &p)
{
  CanonicalText t("program");
  t("sampling interval", p.sample_interval);
  for (std::size_t i = 0; i < p.stages.size(); ++i) {
    const Stage &s = p.stages[i];
    t.section("program/stage " + std::to_string(i + 1));
    t("name", s.name);
    t("mode", std::string(s.isochoric ? "isochoric" : "axes"));
    const char *axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
      t(axes[a], std::string(s.axes[a].is_stress() ? "stress " : "rate ") + canonical_number(s.axes[a].value));
    t("lambda", s.lambda);
    t("isochoric rate", s.isochoric_rate);
    std::vector<std::string> stops, triggers;
    for (const Condition &c : s.stop_any)
      stops.push_back(c.text);
    for (const BranchTrigger &b : s.unload_at)
      triggers.push_back(b.text);
    t("stop when", stops);
    t("max duration", s.max_duration);
    t("unload at", triggers);
    t("unload to", s.unload_to_start ? std::string("start") : canonical_number(s.unload_to_tau));
    t("peak tolerance", s.peak_tolerance);
    if (s.locate_elastic_limit) { // written only when used: older cases keep their text
      t("locate elastic limit", true);
      t("elastic limit tolerance", s.elastic_limit_tolerance);
    }
  }
  return t.text();
}

} // namespace geocomp::sections
