#include "compare/Report.h"

#include "common/AtomicFile.h"
#include "common/Subprocess.h"
#include "compare/GnuplotString.h"
#include "compare/HtmlString.h"
#include "compare/JsonString.h"
#include "compare/StateMapsReport.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace geocomp::compare {

namespace fs = std::filesystem;

std::string format_number(double v)
{
  if (!std::isfinite(v))
    return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

double shown_difference(double a, double b)
{
  const double d = a - b, scale = std::max(std::abs(a), std::abs(b));
  if (!std::isfinite(d) || !(scale > 0.0))
    return d;
  const double unit = std::pow(10.0, std::floor(std::log10(scale)) - 5.0);
  return std::round(d / unit) * unit;
}

namespace {


/// RFC 6901 escaping of one pointer token.
std::string pointer_token(const std::string &s)
{
  std::string out;
  for (char c : s)
    out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return out;
}

/// A numeric table cell bound to its JSON location.
std::string num_cell(double v, const std::string &path)
{
  return "<td class=\"num\" data-path=\"" + html_text(path) + "\">" +
         (std::isfinite(v) ? format_number(v) : std::string("&mdash;")) + "</td>";
}

/// The cross-engine section (CrossEngine.h): the engines' rms beside the specimens'.
std::string cross_engine_html(const CrossEngineTable &t)
{
  std::ostringstream h;
  h << "<h2>Cross-engine: " << html_text(t.reference) << " and " << html_text(t.other) << "</h2>\n<p id=\"cross-engine-verdict\">"
    << html_text(t.verdict) << (t.scatter_note.empty() ? "" : "; " + html_text(t.scatter_note)) << ".</p>\n<p>Both "
    << "engines play the same specimen; their curves are overlaid above. RMS of the difference over "
    << t.common_samples << " common strain samples (the " << html_text(t.reference) << " samples inside "
    << html_text(t.other) << "' strain range, " << html_text(t.other) << " interpolated linearly in strain), "
    << "relative to the scale of the " << html_text(t.reference) << " curve: its largest |q/p'|, its largest "
    << "|eps_v| (at least 0.1 %), its largest |y| [Pa]; instantaneous wall stresses of both engines.</p>\n"
    << "<table id=\"cross-engine\"><tr><th>curve</th><th>scale (1, 1, Pa)</th><th>rms " << html_text(t.other) << " &minus; "
    << html_text(t.reference) << " [%]</th>";
  for (const auto &s : t.specimens)
    h << "<th>rms " << html_text(s) << " &minus; " << html_text(t.reference) << " [%]</th>";
  h << "</tr>\n";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const CrossEngineRow &row = t.rows[r];
    const std::string path = "cross_engine/rows/" + std::to_string(r) + "/";
    h << "<tr><td>" << html_text(row.label) << "</td>" << num_cell(row.scale, path + "scale")
      << num_cell(row.engines * 100, path + "engines_pct");
    for (std::size_t k = 0; k < row.specimens.size(); ++k)
      h << num_cell(row.specimens[k] * 100, path + "specimens_pct/" + std::to_string(k));
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

std::string cross_engine_json(const CrossEngineTable &t)
{
  std::ostringstream j;
  j << "{\n    \"reference\": " << json_string(t.reference) << ",\n    \"other\": " << json_string(t.other)
    << ",\n    \"common_samples\": " << t.common_samples << ",\n    \"agreement_pct\": "
    << format_number(t.agreement * 100) << ",\n    \"verdict\": " << json_string(t.verdict)
    << ",\n    \"scatter_note\": " << json_string(t.scatter_note) << ",\n    \"specimens\": [";
  for (std::size_t k = 0; k < t.specimens.size(); ++k)
    j << (k ? ", " : "") << json_string(t.specimens[k]);
  j << "],\n    \"rows\": [";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const CrossEngineRow &row = t.rows[r];
    j << (r ? "," : "") << "\n      {\"key\": " << json_string(row.key) << ", \"label\": " << json_string(row.label)
      << ", \"scale\": " << format_number(row.scale) << ", \"engines_pct\": " << format_number(row.engines * 100)
      << ", \"specimens_pct\": [";
    for (std::size_t k = 0; k < row.specimens.size(); ++k)
      j << (k ? ", " : "") << format_number(row.specimens[k] * 100);
    j << "]}";
  }
  j << "\n    ]\n  }";
  return j.str();
}

std::string difference_label(const ReportInput &in, std::size_t k)
{
  return in.metrics[k].label + " - " + in.metrics[0].label;
}

double difference(const MetricValue &a, const MetricValue &ref) { return shown_difference(a.value, ref.value); }

/// Onset fields shown for a source, in display units.
struct OnsetDisplay {
  double strain_pct, angle_deg;
};
OnsetDisplay display(const OnsetEstimate &e)
{
  return {e.found ? e.strain * 100.0 : NAN, e.found && e.has_angle ? e.angle_deg : NAN};
}

std::string slug(std::size_t k) { return "r" + std::to_string(k); }

CurveKind report_kind(const ReportInput &in)
{
  if (in.kind != CurveKind::Auto)
    return in.kind;
  if (!in.metrics.empty())
    return in.metrics.front().metrics.kind;
  if (!in.responses.empty())
    return guess_curve_kind(in.responses.front().response);
  return CurveKind::ShearIsochoric;
}

const char *colour(std::size_t k)
{
  static const char *c[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  return c[k % 6];
}

/// Line of response k: the first solid and widest, each later one narrower and dashed, so
/// curves that coincide (the material point on the FE cube, to round-off) all stay visible.
std::string line_style(std::size_t k)
{
  static const char *style[] = {"lw 3.5 dt 1", "lw 2.2 dt 2", "lw 1.4 dt 3", "lw 1.2 dt 4"};
  return style[std::min<std::size_t>(k, 3)];
}

void write_text(const fs::path &p, const std::string &text)
{
  std::ofstream f(p);
  f << text;
  if (!f)
    throw std::runtime_error("cannot write " + p.string());
}

/// Vertical dotted lines at the localization onsets found (Rudnicki-Rice's prediction and
/// each engine's), labelled with their source, in the curves' strain measure.
std::string onset_lines(const ReportInput &in)
{
  if (!in.verdict)
    return "";
  std::vector<OnsetEstimate> onsets{in.verdict->predicted};
  for (const VerdictRow &r : in.verdict->rows)
    onsets.push_back(r.onset);
  std::ostringstream g;
  int n = 0;
  for (const OnsetEstimate &o : onsets) {
    if (!o.found || !std::isfinite(o.strain))
      continue;
    const std::string x = format_number(o.strain * 100.0);
    ++n;
    g << "set arrow " << n << " from " << x << ", graph 0 to " << x << ", graph 1 nohead dt 3 lw 1.5 lc rgb '#555555'\n"
      << "set label " << n << " " << gnuplot_quoted("onset: " + o.source) << " at " << x
      << ", graph 0.03 rotate by 90 left offset -0.8, 0"
      << " font ',10' tc rgb '#555555'\n";
  }
  return g.str();
}

/// Data files and the gnuplot script; returns the PNG names the script makes.
std::vector<std::string> write_plot_inputs(const ReportInput &in, const fs::path &dir, std::string &script)
{
  const CurveKind kind = report_kind(in);
  const bool shear = kind == CurveKind::ShearIsochoric;
  fs::create_directories(dir / "data");
  std::vector<std::string> curves_ok;
  std::vector<std::pair<std::size_t, Curve>> curves;
  for (std::size_t k = 0; k < in.responses.size(); ++k) {
    try {
      curves.emplace_back(k, extract_curve(in.responses[k].response, kind, in.stage, in.axial));
    } catch (const std::exception &) {
      continue; // a response without that stage gets no curve
    }
  }
  for (const auto &[k, c] : curves) {
    std::ostringstream main, br;
    main << "# x[%] y[MPa] gamma_max[%] eps_v[%](dilation+) p[MPa](compression+) q[MPa] p-p0[MPa](compression+)"
         << " broken_bonds(S3; nan without)\n";
    const bool bonds = c.broken_bonds.size() == c.x.size();
    for (std::size_t i = 0; i < c.x.size(); ++i)
      main << c.x[i] * 100 << ' ' << c.y[i] * 1e-6 << ' ' << c.gamma[i] * 100 << ' ' << c.eps_v[i] * 100 << ' '
           << -c.p[i] * 1e-6 << ' ' << c.q[i] * 1e-6 << ' ' << -(c.p[i] - c.p.front()) * 1e-6 << ' '
           << (bonds ? std::to_string(c.broken_bonds[i]) : std::string("nan")) << '\n';
    br << "# unloading branches, one block each: x[%] y[MPa]\n";
    for (const auto &b : c.branches) {
      for (std::size_t i = 0; i < b.x.size(); ++i)
        br << b.x[i] * 100 << ' ' << b.y[i] * 1e-6 << '\n';
      br << "\n";
    }
    if (c.branches.empty())
      br << "nan nan\n";
    write_text(dir / "data" / (slug(k) + "_main.dat"), main.str());
    write_text(dir / "data" / (slug(k) + "_branches.dat"), br.str());
  }
  // Elastic limit and peak markers of each metric set whose label matches a response.
  std::ostringstream marks;
  marks << "# x[%] y[MPa] per response label, block per label\n";
  std::vector<std::size_t> with_marks;
  for (const auto &[k, c] : curves)
    for (const auto &nm : in.metrics)
      if (nm.label == in.responses[k].label) {
        marks << nm.metrics.elastic_limit_strain * 100 << ' ' << nm.metrics.elastic_limit_stress * 1e-6 << '\n'
              << nm.metrics.peak_strain * 100 << ' ' << nm.metrics.peak_stress * 1e-6 << "\n\n\n";
        with_marks.push_back(k);
        break;
      }
  write_text(dir / "data" / "marks.dat", marks.str());

  std::vector<std::string> pngs;
  std::ostringstream gp;
  gp << "# Generated by geocomp compare: run `gnuplot report.gp` in this folder.\n"
     << "set terminal pngcairo size 960,680 enhanced font 'DejaVu Sans,12' linewidth 1.5\n"
     << "set grid lc rgb '#dddddd'\nset key top left box opaque\nset datafile missing 'nan'\n";
  // Log strain and Cauchy stress (Metrics.h); the axial curve on its axis and sense.
  const AxialAxis axis = curves.empty() ? in.axial.value_or(AxialAxis{}) : curves.front().second.axial;
  const std::string a = std::string(1, "xyz"[axis.axis]), minus = axis.sense < 0 ? "-" : "";
  const std::string sense = axis.sense < 0 ? " (compression +)" : " (extension +)";
  const std::string xl = shear ? "{/Symbol g}_{max} of the log strain [%]"
                               : "axial log strain " + minus + "{/Symbol e}_" + a + " [%]" + sense;
  const std::string yl = shear ? "{/Symbol t}_{max} [MPa]" : "axial Cauchy stress " + minus + "{/Symbol s}_" + a + " [MPa]" + sense;
  auto plot_list = [&](const std::string &using_main, bool branches, bool marks_too) {
    std::ostringstream p;
    bool first = true;
    for (const auto &[k, c] : curves) {
      const std::string lab = in.responses[k].label;
      p << (first ? "plot " : ", \\\n     ") << "'data/" << slug(k) << "_main.dat' using " << using_main
        << " with lines " << line_style(k) << " lc rgb '" << colour(k) << "' title '" << lab << "'";
      first = false;
      if (branches && !c.branches.empty())
        p << ", \\\n     'data/" << slug(k) << "_branches.dat' using 1:2 with lines dt 2 lw 1 lc rgb '"
          << colour(k) << "' title '" << lab << " unloading'";
    }
    if (marks_too && !with_marks.empty()) {
      // The key shows each mark's shape in black; the marks on the curves take their colours.
      p << ", \\\n     NaN with points pt 7 ps 1.6 lc rgb 'black' title 'elastic limit'"
        << ", \\\n     NaN with points pt 9 ps 1.8 lc rgb 'black' title 'peak'";
      for (std::size_t m = 0; m < with_marks.size(); ++m)
        p << ", \\\n     'data/marks.dat' index " << m << " every ::0::0 using 1:2 with points pt 7 ps 1.6 lc rgb '"
          << colour(with_marks[m]) << "' notitle"
          << ", \\\n     'data/marks.dat' index " << m << " every ::1::1 using 1:2 with points pt 9 ps 1.8 lc rgb '"
          << colour(with_marks[m]) << "' notitle";
    }
    return p.str() + "\n";
  };
  if (!curves.empty()) {
    gp << "\nset output 'stress_strain.png'\nset title '" << (shear ? "Shear at constant volume: " : "Constant lateral pressure: ")
       << "stress-strain with unloading branches'\nset xlabel '" << xl << "'\nset ylabel '" << yl << "'\n"
       << onset_lines(in) << plot_list("1:2", true, true) << "unset arrow\nunset label\n";
    pngs.push_back("stress_strain.png");
    if (shear) { // the volume is held: its change is round-off; the mean stress shows the dilatancy
      gp << "\nset output 'mean_stress.png'\nset title 'Mean stress change at constant volume'\nset xlabel '" << xl
         << "'\nset ylabel 'p - p_0 [MPa] (compression +)'\n" << plot_list("1:7", false, false);
      pngs.push_back("mean_stress.png");
    } else {
      gp << "\nset output 'volumetric.png'\nset title 'Volumetric strain'\nset xlabel '" << xl
         << "'\nset ylabel 'volumetric strain {/Symbol e}_v [%] (dilation +)'\n" << plot_list("1:4", false, false);
      pngs.push_back("volumetric.png");
    }
    gp << "\nset output 'stress_path.png'\nset title 'Stress path'\nset key top left box opaque\n"
       << "set xlabel 'mean stress p [MPa] (compression +)'\nset ylabel 'deviator q = {/Symbol \\326}(3J_2) [MPa]'\n"
       << "set xrange [0:*]\nset yrange [0:*]\nset offsets 0, graph 0.08, graph 0.05, 0\n"
       << plot_list("5:6", false, false) << "set autoscale\nset offsets 0, 0, 0, 0\nset key top right box opaque\n";
    pngs.push_back("stress_path.png");
    // S3's bonds (DEM extra `broken_bonds`): plotted when some response broke one.
    const bool any_broken = std::any_of(curves.begin(), curves.end(), [](const auto &kc) {
      return std::any_of(kc.second.broken_bonds.begin(), kc.second.broken_bonds.end(), [](double b) { return b > 0.0; });
    });
    if (any_broken) {
      gp << "\nset output 'broken_bonds.png'\nset title 'S3 bonds broken for good'\nset xlabel '" << xl
         << "'\nset ylabel 'broken bonds'\n" << plot_list("1:8", false, false);
      pngs.push_back("broken_bonds.png");
    }
  }
  gp << state_maps_script(in.state_maps, dir, pngs);
  script = gp.str();
  return pngs;
}

/// The unloading branches of each curve: the elastic limit's bracket (the neighbouring
/// branches whose residuals straddle S0's 1 %) and, for every branch, where it started, its
/// residual and whether it was planned in the case or placed by bisection (ProgramRunner).
std::string branch_section(const ReportInput &in)
{
  std::ostringstream h;
  bool any = false;
  for (const auto &m : in.metrics)
    any = any || !m.metrics.branches.empty();
  if (!any)
    return "";
  h << "<h2>Unloading branches</h2>\n<p>Each branch: the strain at which it left the main path, the stress "
       "there and its residual strain (what unloading did not recover; the elastic limit is where it reaches "
       "1 %, S0). Bisection branches were placed by the runner between the neighbouring branches whose "
       "residuals straddle 1 % (<code>locate elastic limit</code>, docs/metrics.md).</p>\n";
  for (const auto &nm : in.metrics) {
    const MetricSet &m = nm.metrics;
    if (m.branches.empty())
      continue;
    const bool shear = m.kind == CurveKind::ShearIsochoric;
    const std::string e = shear ? "gamma_max" : m.axial.strain_label();
    const std::string s = shear ? "tau_max" : m.axial.stress_label();
    const std::string path = "metrics/" + pointer_token(nm.label) + "/";
    h << "<p><b>" << html_text(nm.label) << "</b>: ";
    if (std::isfinite(m.elastic_limit_lower))
      h << "elastic limit bracket " << html_text(e) << " in [" << format_number(m.elastic_limit_lower * 100) << ", "
        << format_number(m.elastic_limit_upper * 100) << "] % (width "
        << format_number((m.elastic_limit_upper - m.elastic_limit_lower) * 100) << " %), "
        << html_text(m.elastic_limit_method) << ".</p>\n";
    else
      h << "no two neighbouring branches straddle the 1 % residual: no bracket.</p>\n";
    h << "<table class=\"branches\"><tr><th>branch</th><th>start " << html_text(e) << " [%]</th><th>start "
      << html_text(s) << " [MPa]</th><th>residual [%]</th><th>placed</th></tr>\n";
    for (std::size_t k = 0; k < m.branches.size(); ++k) {
      const BranchResidual &b = m.branches[k];
      const std::string at = path + "branches/" + std::to_string(k) + "/";
      h << "<tr><td>" << b.id << "</td>" << num_cell(b.x_start * 100, at + "start_pct")
        << num_cell(b.y_start * 1e-6, at + "start_stress_MPa") << num_cell(b.residual * 100, at + "residual_pct")
        << "<td>" << (b.bisection ? "bisection" : "planned") << "</td></tr>\n";
    }
    h << "</table>\n";
  }
  return h.str();
}

/// The same as JSON members of one metric set (after its table's keys).
std::string branch_json(const MetricSet &m)
{
  std::ostringstream j;
  j << ",\n      \"elastic_limit_lower_pct\": " << format_number(m.elastic_limit_lower * 100)
    << ",\n      \"elastic_limit_upper_pct\": " << format_number(m.elastic_limit_upper * 100)
    << ",\n      \"branches\": [";
  for (std::size_t k = 0; k < m.branches.size(); ++k) {
    const BranchResidual &b = m.branches[k];
    j << (k ? "," : "") << "\n        {\"id\": " << b.id << ", \"start_pct\": " << format_number(b.x_start * 100)
      << ", \"start_stress_MPa\": " << format_number(b.y_start * 1e-6)
      << ", \"residual_pct\": " << format_number(b.residual * 100)
      << ", \"placed\": " << json_string(b.bisection ? "bisection" : "planned") << "}";
  }
  j << "]";
  return j.str();
}

std::string build_html(const ReportInput &in, const std::vector<std::string> &pngs, const std::string &plot_message)
{
  const CurveKind kind = report_kind(in);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html_text(in.title)
    << "</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
       "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:4px 8px}"
       "td.num{text-align:right;font-family:monospace}th{background:#eee}img{max-width:49%;margin:2px}"
       ".note{color:#a33}td.outside{color:#a33;font-weight:bold}.maprow{display:flex;flex-wrap:wrap;gap:4px}"
       ".maprow p{width:100%;margin:0.4em 0 0}.panel{flex:1}.panel img{max-width:100%}</style></head><body>\n";
  h << "<h1>" << html_text(in.title) << "</h1>\n";
  if (!in.case_name.empty())
    h << "<p>Case: <code>" << html_text(in.case_name) << "</code></p>\n";
  h << "<p>Curve: " << (kind == CurveKind::ShearIsochoric
                          ? "&tau;<sub>max</sub> &ndash; &gamma;<sub>max</sub> (isochoric shear, S0 program 1)"
                          : "&sigma;<sub>a</sub> &ndash; &epsilon;<sub>a</sub> on the axial axis a = " +
                              html_text(in.axial.value_or(AxialAxis{}).describe()) + " (S0 program 2)")
    << ". Logarithmic strains ln(L/L<sub>0</sub>) of the box edges from the start of the analysed stage and "
       "Cauchy stresses (force over current area), the same measures for every engine; units MPa, %, degrees. Computed tension positive "
       "inside geocomp; volumetric strain is shown dilation positive, p compression positive. "
       "Definitions: docs/metrics.md. Numbers also in <a href=\"metrics.json\">metrics.json</a>.</p>\n";
  for (const auto &n : in.notes)
    h << "<p class=\"note\">" << html_text(n) << "</p>\n";

  h << "<h2>Plots</h2>\n";
  if (!plot_message.empty())
    h << "<p class=\"note\">" << html_text(plot_message) << "</p>\n";
  for (const auto &p : pngs)
    if (!(p.rfind("state", 0) == 0 && p.size() > 5 && std::isdigit(static_cast<unsigned char>(p[5])))) // own section
      h << "<a href=\"" << html_text(p) << "\"><img src=\"" << html_text(p) << "\" alt=\"" << html_text(p) << "\"></a>\n";
  h << state_maps_html(in.state_maps, in.state_maps_note, pngs);

  if (!in.metrics.empty()) {
    h << "<h2>Metrics</h2>\n<table id=\"metrics\"><tr><th>metric</th><th>units</th>";
    for (const auto &m : in.metrics)
      h << "<th>" << html_text(m.label) << "</th>";
    for (std::size_t k = 1; k < in.metrics.size(); ++k)
      h << "<th>" << html_text(difference_label(in, k)) << "</th>";
    h << "</tr>\n";
    std::vector<std::vector<MetricValue>> tables;
    for (const auto &m : in.metrics)
      tables.push_back(metric_table(m.metrics));
    for (std::size_t r = 0; r < tables[0].size(); ++r) {
      h << "<tr><td>" << html_text(tables[0][r].label) << "</td><td>" << html_text(tables[0][r].units) << "</td>";
      for (std::size_t k = 0; k < tables.size(); ++k)
        h << num_cell(tables[k][r].value,
                      "metrics/" + pointer_token(in.metrics[k].label) + "/" + pointer_token(tables[k][r].key));
      for (std::size_t k = 1; k < tables.size(); ++k)
        h << num_cell(difference(tables[k][r], tables[0][r]),
                      "differences/" + pointer_token(difference_label(in, k)) + "/" + pointer_token(tables[0][r].key));
      h << "</tr>\n";
    }
    h << "<tr><td>elastic limit method</td><td></td>";
    for (const auto &m : in.metrics)
      h << "<td>" << html_text(m.metrics.elastic_limit_method.empty() ? "none" : m.metrics.elastic_limit_method) << "</td>";
    h << "</tr>\n</table>\n";
    for (const auto &m : in.metrics) {
      if (m.metrics.notes.empty())
        continue;
      h << "<p><b>" << html_text(m.label) << "</b> notes:</p><ul>";
      for (const auto &n : m.metrics.notes)
        h << "<li>" << html_text(n) << "</li>";
      h << "</ul>\n";
    }
    h << branch_section(in);
  }

  if (in.verdict) {
    const RrVerdict &v = *in.verdict;
    h << "<h2>Rudnicki&ndash;Rice verdict</h2>\n<p>" << html_text(v.summary)
      << " Angle: band normal from the most compressive principal axis. Tolerances: onset within max("
      << format_number(v.tolerances.strain_relative * 100) << " % of the prediction, "
      << format_number(v.tolerances.strain_absolute * 100) << " % strain), angle within "
      << format_number(v.tolerances.angle_deg) << "&deg;.</p>\n"
      << "<table id=\"verdict\"><tr><th>source</th><th>onset strain [%]</th><th>angle [deg]</th>"
         "<th>&Delta; strain [%]</th><th>&Delta; strain rel. [%]</th><th>&Delta; angle [deg]</th><th>verdict</th>"
         "<th>how it was found</th></tr>\n";
    const OnsetDisplay p = display(v.predicted);
    h << "<tr><td>" << html_text(v.predicted.source) << " (prediction)</td>" << num_cell(p.strain_pct, "rudnicki_rice/predicted/onset_strain_pct")
      << num_cell(p.angle_deg, "rudnicki_rice/predicted/angle_deg") << "<td></td><td></td><td></td><td></td><td>"
      << html_text(v.predicted.found ? v.predicted.note : "no onset predicted") << "</td></tr>\n";
    for (std::size_t k = 0; k < v.rows.size(); ++k) {
      const auto &r = v.rows[k];
      const OnsetDisplay d = display(r.onset);
      const std::string base = "rudnicki_rice/rows/" + std::to_string(k) + "/";
      h << "<tr><td>" << html_text(r.onset.source) << "</td>" << num_cell(d.strain_pct, base + "onset_strain_pct")
        << num_cell(d.angle_deg, base + "angle_deg")
        << num_cell(r.comparable ? r.strain_difference * 100 : NAN, base + "strain_difference_pct")
        << num_cell(r.comparable ? r.strain_relative * 100 : NAN, base + "strain_relative_pct")
        << num_cell(r.comparable ? r.angle_difference_deg : NAN, base + "angle_difference_deg") << "<td>"
        << html_text(r.verdict) << "</td><td class=\"onset-note\">" << html_text(r.onset.note) << "</td></tr>\n";
    }
    h << "</table>\n";
  }

  if (!in.calibrated_parameters.empty()) {
    h << "<h2>Calibrated continuum parameters</h2>\n<table id=\"calibration\"><tr><th>parameter</th><th>value</th></tr>\n";
    for (const auto &[k, val] : in.calibrated_parameters)
      h << "<tr><td>" << html_text(k) << "</td><td>" << html_text(val) << "</td></tr>\n";
    h << "</table>\n";
  }
  if (in.cross_engine)
    h << cross_engine_html(*in.cross_engine);
  if (in.scatter) {
    const ScatterTable &t = *in.scatter;
    h << "<h2>Specimen scatter</h2>\n<p>The band of each metric over " << t.specimens.size()
      << " specimen(s) of the same program (";
    for (std::size_t k = 0; k < t.specimens.size(); ++k)
      h << (k ? ", " : "") << html_text(t.specimens[k]);
    h << "), and whether each engine's value lies inside it (within 1e-6 of its width).</p>\n"
         "<table id=\"scatter\"><tr><th>metric</th><th>units</th><th>lowest</th><th>highest</th>";
    for (const auto &e : t.engines)
      h << "<th>" << html_text(e) << "</th>";
    h << "</tr>\n";
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const ScatterRow &row = t.rows[r];
      const std::string path = "scatter/rows/" + std::to_string(r) + "/";
      h << "<tr><td>" << html_text(row.label) << "</td><td>" << html_text(row.units) << "</td>" << num_cell(row.low, path + "low")
        << num_cell(row.high, path + "high");
      for (const auto &v : row.verdicts)
        h << "<td class=\"" << (v == "outside" ? "outside" : "within") << "\">" << html_text(v) << "</td>";
      h << "</tr>\n";
    }
    h << "</table>\n";
  }
  if (!in.calibration_curves.empty()) {
    h << "<h2>Calibrated on, and predicted</h2>\n<p>The material point with the calibrated section against each "
         "curve: rms difference relative to the curve's largest q (q, p) and to its volumetric range, at least "
         "0.1 % (eps_v). A curve calibrated on shows the fit; a predicted one was held out of the fit.</p>\n"
         "<table id=\"calibration-curves\"><tr><th>curve</th><th>role</th><th>rms q</th><th>rms p</th>"
         "<th>rms eps_v</th></tr>\n";
    for (std::size_t k = 0; k < in.calibration_curves.size(); ++k) {
      const CalibrationCurve &c = in.calibration_curves[k];
      const std::string path = "calibration_curves/" + std::to_string(k) + "/";
      h << "<tr><td>" << html_text(c.curve) << "</td><td>" << html_text(c.role) << "</td>" << num_cell(c.rms_q, path + "rms_q")
        << num_cell(c.rms_p, path + "rms_p") << num_cell(c.rms_eps_v, path + "rms_eps_v") << "</tr>\n";
    }
    h << "</table>\n";
  }
  h << ladder_html(in.ladder);
  h << "<h2>Definitions</h2>\n<ul>"
       "<li>Initial modulus: least-squares slope over y &minus; y<sub>0</sub> &le; 25 % of the peak rise.</li>"
       "<li>Elastic limit: where the residual strain after unloading reaches 1 % (S0): the midpoint of the "
       "bracket when bisection branches located it, otherwise interpolated between branches; without branches, "
       "where the curve leaves the initial line by 2 % of the peak rise.</li>"
       "<li>Softening modulus: least-squares slope over 20&ndash;80 % of the drop from peak to residual; "
       "residual: mean over the last 10 % of the post-peak strain.</li>"
       "<li>Dilatancy: sin &psi; = d&epsilon;<sub>v</sub><sup>p</sup>/d&gamma;<sup>p</sup> around the peak; "
       "friction: sin &phi; = (&sigma;<sub>1</sub>&minus;&sigma;<sub>3</sub>)/(&sigma;<sub>1</sub>+&sigma;<sub>3</sub>), c = 0.</li>"
       "</ul>\n</body></html>\n";
  return h.str();
}

} // namespace

std::string metrics_json(const ReportInput &in)
{
  std::ostringstream j;
  j << "{\n  \"format\": \"geocomp-metrics-1\",\n  \"title\": " << json_string(in.title)
    << ",\n  \"case\": " << json_string(in.case_name) << ",\n  \"curve\": " << json_string(to_string(report_kind(in)))
    << ",\n  \"convention\": "
    << json_string("units MPa, %, deg; logarithmic strains of the box from the stage start, Cauchy stresses; "
                   "axial curve on axis " + in.axial.value_or(AxialAxis{}).describe() +
                   "; volumetric strain ln(V/V0), dilation positive")
    << ",\n  \"metrics\": {";
  for (std::size_t k = 0; k < in.metrics.size(); ++k) {
    const auto &m = in.metrics[k];
    j << (k ? "," : "") << "\n    " << json_string(m.label) << ": {\n      \"engine\": " << json_string(m.metrics.engine)
      << ",\n      \"curve\": " << json_string(to_string(m.metrics.kind)) << ",\n      \"elastic_limit_method\": "
      << json_string(m.metrics.elastic_limit_method);
    for (const auto &v : metric_table(m.metrics))
      j << ",\n      " << json_string(v.key) << ": " << format_number(v.value);
    j << branch_json(m.metrics);
    j << ",\n      \"notes\": [";
    for (std::size_t n = 0; n < m.metrics.notes.size(); ++n)
      j << (n ? ", " : "") << json_string(m.metrics.notes[n]);
    j << "]\n    }";
  }
  j << "\n  },\n  \"differences\": {";
  for (std::size_t k = 1; k < in.metrics.size(); ++k) {
    const auto a = metric_table(in.metrics[k].metrics), ref = metric_table(in.metrics[0].metrics);
    j << (k > 1 ? "," : "") << "\n    " << json_string(difference_label(in, k)) << ": {";
    for (std::size_t r = 0; r < a.size(); ++r)
      j << (r ? "," : "") << "\n      " << json_string(a[r].key) << ": " << format_number(difference(a[r], ref[r]));
    j << "\n    }";
  }
  j << "\n  }";
  if (in.verdict) {
    const RrVerdict &v = *in.verdict;
    const OnsetDisplay p = display(v.predicted);
    j << ",\n  \"rudnicki_rice\": {\n    \"summary\": " << json_string(v.summary)
      << ",\n    \"predicted\": {\"source\": " << json_string(v.predicted.source)
      << ", \"found\": " << (v.predicted.found ? "true" : "false") << ", \"onset_strain_pct\": " << format_number(p.strain_pct)
      << ", \"angle_deg\": " << format_number(p.angle_deg) << ", \"note\": " << json_string(v.predicted.note)
      << "},\n    \"rows\": [";
    for (std::size_t k = 0; k < v.rows.size(); ++k) {
      const auto &r = v.rows[k];
      const OnsetDisplay d = display(r.onset);
      j << (k ? "," : "") << "\n      {\"source\": " << json_string(r.onset.source)
        << ", \"found\": " << (r.onset.found ? "true" : "false") << ", \"onset_strain_pct\": " << format_number(d.strain_pct)
        << ", \"angle_deg\": " << format_number(d.angle_deg)
        << ", \"strain_difference_pct\": " << format_number(r.comparable ? r.strain_difference * 100 : NAN)
        << ", \"strain_relative_pct\": " << format_number(r.comparable ? r.strain_relative * 100 : NAN)
        << ", \"angle_difference_deg\": " << format_number(r.comparable ? r.angle_difference_deg : NAN)
        << ", \"verdict\": " << json_string(r.verdict) << ", \"note\": " << json_string(r.onset.note) << "}";
    }
    j << "\n    ]\n  }";
  }
  j << ",\n  \"calibrated_parameters\": {";
  for (std::size_t k = 0; k < in.calibrated_parameters.size(); ++k)
    j << (k ? "," : "") << "\n    " << json_string(in.calibrated_parameters[k].first) << ": "
      << json_string(in.calibrated_parameters[k].second);
  j << (in.calibrated_parameters.empty() ? "}" : "\n  }");
  j << ",\n  \"calibration_curves\": [";
  for (std::size_t k = 0; k < in.calibration_curves.size(); ++k) {
    const CalibrationCurve &c = in.calibration_curves[k];
    j << (k ? "," : "") << "\n    {\"curve\": " << json_string(c.curve) << ", \"role\": " << json_string(c.role)
      << ", \"rms_q\": " << format_number(c.rms_q) << ", \"rms_p\": " << format_number(c.rms_p)
      << ", \"rms_eps_v\": " << format_number(c.rms_eps_v) << "}";
  }
  j << (in.calibration_curves.empty() ? "]" : "\n  ]");
  if (!in.ladder.empty())
    j << ",\n  \"ladder\": " << ladder_json(in.ladder, "  ");
  if (in.scatter) {
    const ScatterTable &t = *in.scatter;
    j << ",\n  \"scatter\": {\n    \"specimens\": [";
    for (std::size_t k = 0; k < t.specimens.size(); ++k)
      j << (k ? ", " : "") << json_string(t.specimens[k]);
    j << "],\n    \"rows\": [";
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const ScatterRow &row = t.rows[r];
      j << (r ? "," : "") << "\n      {\"key\": " << json_string(row.key) << ", \"low\": " << format_number(row.low)
        << ", \"high\": " << format_number(row.high) << ", \"verdicts\": {";
      for (std::size_t e = 0; e < t.engines.size(); ++e)
        j << (e ? ", " : "") << json_string(t.engines[e]) << ": " << json_string(row.verdicts[e]);
      j << "}}";
    }
    j << "\n    ]\n  }";
  }
  if (in.cross_engine)
    j << ",\n  \"cross_engine\": " << cross_engine_json(*in.cross_engine);
  if (!in.state_maps.empty())
    j << ",\n  \"named_states\": " << state_maps_json(in.state_maps);
  j << "\n}\n";
  return j.str();
}

ReportOutcome write_report(const ReportInput &in, const fs::path &dir, const ReportOptions &options)
{
  ReportOutcome out;
  out.dir = fs::absolute(dir);
  replace_folder_atomically(dir, [&](const fs::path &tmp) {
    std::string script;
    const std::vector<std::string> pngs = write_plot_inputs(in, tmp, script);
    write_text(tmp / "report.gp", script);
    if (pngs.empty()) {
      out.message = "nothing to plot";
    } else if (!program_available(options.gnuplot)) {
      out.message = "gnuplot not found ('" + options.gnuplot +
                    "'; Debian package gnuplot-nox): plots skipped, tables and metrics.json written; "
                    "run `gnuplot report.gp` in the report folder once it is installed";
      std::cerr << "geocomp report: " << out.message << "\n";
    } else {
      // No shell: the folder and the program arrive as they are, whatever they hold.
      const SubprocessResult run = run_subprocess({options.gnuplot, "report.gp"}, {tmp, tmp / "gnuplot.log", tmp / "gnuplot.log"});
      const int rc = run.exit_code;
      for (const auto &p : pngs)
        if (fs::exists(tmp / p) && fs::file_size(tmp / p) > 0)
          out.plots.push_back(p);
      out.plots_made = rc == 0 && out.plots.size() == pngs.size();
      if (!out.plots_made) {
        out.message = "gnuplot failed (exit " + std::to_string(rc) + "); see gnuplot.log";
        std::cerr << "geocomp report: " << out.message << "\n";
      }
    }
    write_text(tmp / "metrics.json", metrics_json(in));
    write_text(tmp / "index.html", build_html(in, out.plots, out.message));
  });
  return out;
}

} // namespace geocomp::compare
