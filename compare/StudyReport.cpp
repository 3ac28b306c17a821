#include "compare/StudyReport.h"

#include "common/AtomicFile.h"
#include "common/Subprocess.h"
#include "compare/GnuplotString.h"
#include "compare/HtmlString.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace geocomp::compare {

namespace fs = std::filesystem;

double relative_volume_change(double eps_v) { return std::expm1(eps_v); } // S0 Fig. 4b

StudySummary study_summary(const Response &response, CurveKind kind, const std::optional<AxialAxis> &axial)
{
  StudySummary s;
  try {
    MetricOptions options;
    options.kind = kind;
    options.axial = axial;
    s.metrics = compute_metrics(response, options);
    const Curve curve = extract_curve(response, kind, options.stage, axial);
    if (!curve.eps_v.empty()) {
      s.v_r_min = relative_volume_change(*std::min_element(curve.eps_v.begin(), curve.eps_v.end()));
      s.v_r_final = relative_volume_change(curve.eps_v.back());
    }
  } catch (const std::exception &e) {
    s.error = e.what();
  }
  return s;
}

namespace {

void write_text(const fs::path &p, const std::string &text)
{
  std::ofstream out(p, std::ios::binary);
  out << text;
  if (!out)
    throw std::runtime_error("cannot write " + p.string());
}

std::string fmt(double v, const char *format = "%.6g")
{
  if (!std::isfinite(v))
    return "?"; // gnuplot's missing value; "&mdash;" in the tables
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

const char *colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};

/// The engines of the study in order of first appearance.
std::vector<std::string> engines_of(const StudyReportInput &in)
{
  std::vector<std::string> engines;
  for (const auto &c : in.cases)
    for (const auto &r : c.runs)
      if (std::find(engines.begin(), engines.end(), r.engine) == engines.end())
        engines.push_back(r.engine);
  return engines;
}

std::size_t engine_index(const std::vector<std::string> &engines, const std::string &engine)
{
  return static_cast<std::size_t>(std::find(engines.begin(), engines.end(), engine) - engines.begin());
}

/// Every case's curve per engine: data/case<k>_e<j>.dat (strain %, stress MPa, V_r %), and
/// the plot commands, one column per engine (stress on top, V_r below).
void curves_figure(const StudyReportInput &in, const std::vector<std::string> &engines, const fs::path &dir,
                   std::ostringstream &gp)
{
  std::vector<std::ostringstream> stress(engines.size()), volume(engines.size());
  std::string x_name = "strain", y_name = "stress";
  for (std::size_t k = 0; k < in.cases.size(); ++k)
    for (const auto &run : in.cases[k].runs) {
      const std::size_t j = engine_index(engines, run.engine);
      Curve curve;
      try {
        curve = extract_curve(run.response, in.cases[k].kind, -1, in.cases[k].axial);
      } catch (const std::exception &) {
        continue; // too short to draw; the table says why
      }
      x_name = curve.x_name, y_name = curve.y_name;
      std::ostringstream d;
      d << "# " << curve.x_name << "_percent " << curve.y_name << "_MPa V_r_percent\n";
      for (std::size_t i = 0; i < curve.x.size(); ++i)
        d << 100.0 * curve.x[i] << ' ' << 1e-6 * curve.y[i] << ' ' << 100.0 * relative_volume_change(curve.eps_v[i])
          << '\n';
      const std::string file = "data/case" + std::to_string(k) + "_e" + std::to_string(j) + ".dat";
      write_text(dir / file, d.str());
      const std::string style = " w l lw 2 dt " + std::to_string(1 + (k / 8) % 4) + " lc rgb '" + colours[k % 8] +
                                "' t " + gnuplot_quoted(in.cases[k].label) + " noenhanced";
      const bool first = stress[j].tellp() == 0;
      stress[j] << (first ? "plot " : ", ") << "'" << file << "' u 1:2" << style;
      volume[j] << (first ? "plot " : ", ") << "'" << file << "' u 1:3" << style;
    }
  gp << "set output 'curves.png'\nset multiplot layout 2," << std::max<std::size_t>(1, engines.size())
     << " columnsfirst title " << gnuplot_quoted(in.title + ": every case") << " noenhanced\n";
  for (std::size_t j = 0; j < engines.size(); ++j) {
    gp << "set title " << gnuplot_quoted(engines[j]) << " noenhanced\nset xlabel " << gnuplot_quoted(x_name + " [%]")
       << " noenhanced\nset ylabel " << gnuplot_quoted(y_name + " [MPa]") << " noenhanced\n"
       << (stress[j].tellp() > 0 ? stress[j].str() : "plot NaN notitle") << "\nset title "
       << gnuplot_quoted(engines[j] + ": relative volume change V_r = V/V_start - 1 (dilation +)") << " noenhanced\n"
       << "set ylabel 'V_r [%]' noenhanced\n" << (volume[j].tellp() > 0 ? volume[j].str() : "plot NaN notitle") << "\n";
  }
  gp << "unset multiplot\n";
}

/// The summary's columns: JSON key, label, display factor.
struct SummaryColumn {
  const char *key, *label;
  double factor;
};
const SummaryColumn summary_columns[] = {
  {"peak_stress_Pa", "peak stress [MPa]", 1e-6},         {"secant_modulus_Pa", "secant modulus [MPa]", 1e-6},
  {"elastic_limit_stress_Pa", "elastic limit stress [MPa]", 1e-6}, {"dilatancy_angle_deg", "dilatancy angle [deg]", 1.0},
  {"V_r_min", "V_r, smallest (largest compaction) [%]", 100.0},    {"V_r_final", "V_r at the end [%]", 100.0}};

std::vector<double> summary_values(const StudySummary &s)
{
  const MetricSet &m = s.metrics;
  return {m.peak_stress, m.secant_modulus, m.elastic_limit_stress, m.dilatancy_angle_deg, s.v_r_min, s.v_r_final};
}

/// The summary of every case and engine, [case][run].
using Summaries = std::vector<std::vector<StudySummary>>;
Summaries summaries_of(const StudyReportInput &in)
{
  Summaries all;
  for (const auto &c : in.cases) {
    all.emplace_back();
    for (const auto &r : c.runs)
      all.back().push_back(study_summary(r.response, c.kind, c.axial));
  }
  return all;
}

/// data/summary_e<j>.dat (by increasing abscissa) and a 2 x 3 panel figure, a series per engine.
void summary_figure(const StudyReportInput &in, const Summaries &all, const std::vector<std::string> &engines,
                    const fs::path &dir, std::ostringstream &gp)
{
  std::vector<std::multimap<double, std::string>> rows(engines.size());
  for (std::size_t k = 0; k < in.cases.size(); ++k)
    for (std::size_t r = 0; r < in.cases[k].runs.size(); ++r) {
      std::string row = fmt(in.cases[k].x, "%.17g");
      for (std::size_t col = 0; col < 6; ++col)
        row += ' ' + fmt(summary_columns[col].factor * summary_values(all[k][r])[col], "%.10g");
      rows[engine_index(engines, in.cases[k].runs[r].engine)].emplace(in.cases[k].x, row + "\n");
    }
  for (std::size_t j = 0; j < engines.size(); ++j) {
    std::string d = "# " + in.against + " peak_MPa secant_MPa elastic_limit_MPa dilatancy_deg V_r_min_% V_r_final_%\n";
    for (const auto &[x, row] : rows[j])
      d += row;
    write_text(dir / ("data/summary_e" + std::to_string(j) + ".dat"), d);
  }
  gp << "set output 'summary.png'\nset multiplot layout 2,3 title "
     << gnuplot_quoted(in.title + ": summary against " + in.against) << " noenhanced\nset xlabel "
     << gnuplot_quoted(in.against) << " noenhanced\nset format x '%g'\nset offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1\n";
  for (std::size_t col = 0; col < 6; ++col) {
    gp << "set title " << gnuplot_quoted(summary_columns[col].label) << " noenhanced\nset ylabel "
       << gnuplot_quoted(summary_columns[col].label) << " noenhanced\nplot ";
    for (std::size_t j = 0; j < engines.size(); ++j)
      gp << (j ? ", " : "") << "'data/summary_e" << j << ".dat' u 1:" << col + 2 << " w lp pt 7 ps 1.2 lw 2 lc rgb '"
         << colours[j % 8] << "' t " << gnuplot_quoted(engines[j]) << " noenhanced";
    gp << "\n";
  }
  gp << "unset multiplot\n";
}

std::string cell(double v) { return std::isfinite(v) ? fmt(v, "%.4g") : std::string("&mdash;"); }

std::string summary_table(const StudyReportInput &in, const Summaries &all)
{
  std::ostringstream h;
  h << "<table><tr><th>case</th><th>" << html_text(in.against) << "</th><th>engine</th><th>status</th>"
    << "<th>peak strain [%]</th>";
  for (const auto &col : summary_columns)
    h << "<th>" << html_text(col.label) << "</th>";
  h << "<th>elastic limit from</th></tr>\n";
  for (std::size_t k = 0; k < in.cases.size(); ++k) {
    const StudyReportCase &c = in.cases[k];
    const std::string status = c.failure.empty() ? "complete" : "FAILED: " + c.failure;
    if (c.runs.empty())
      h << "<tr><td>" << html_text(c.name) << "</td><td>" << cell(c.x) << "</td><td>&mdash;</td><td>"
        << html_text(status) << "</td></tr>\n";
    for (std::size_t r = 0; r < c.runs.size(); ++r) {
      const StudySummary &s = all[k][r];
      h << "<tr><td>" << html_text(c.name) << "</td><td>" << cell(c.x) << "</td><td>" << html_text(c.runs[r].engine)
        << "</td><td>" << html_text(s.error.empty() ? status : status + "; metrics: " + s.error) << "</td><td>"
        << cell(100.0 * s.metrics.peak_strain) << "</td>";
      for (std::size_t col = 0; col < 6; ++col)
        h << "<td>" << cell(summary_columns[col].factor * summary_values(s)[col]) << "</td>";
      h << "<td>" << html_text(s.metrics.elastic_limit_method) << "</td></tr>\n";
    }
  }
  return h.str() + "</table>\n";
}

std::string build_html(const StudyReportInput &in, const Summaries &all, const StudyReportOutcome &out)
{
  std::ostringstream h;
  h << "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>" << html_text(in.title) << "</title><style>"
    << "body{font-family:sans-serif;max-width:1300px;margin:auto}table{border-collapse:collapse}"
       "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}img{max-width:100%}</style></head><body>\n"
    << "<h1>" << html_text(in.title) << "</h1>\n<p>Study file: " << html_text(in.study_file) << "; "
    << in.cases.size() << " case(s), summary against <b>" << html_text(in.against) << "</b>.</p>\n";
  std::string failed;
  for (const auto &c : in.cases)
    if (!c.failure.empty())
      failed += "<li>" + html_text(c.label + " (" + c.file + "): " + c.failure) + "</li>\n";
  if (!failed.empty())
    h << "<h2>Failed cases</h2>\n<ul>\n" << failed << "</ul>\n";
  h << "<p>Metrics as in each case's pair report (docs/metrics.md): strains are logarithmic, from the start of the "
       "analysed stage; stresses are Cauchy, absolute; an axial curve is <b>compression positive</b>. "
       "V<sub>r</sub> = V/V<sub>start</sub> - 1 is S0's relative volume change (Fig. 4b), dilation positive.</p>\n"
    << "<h2>Summary</h2>\n" << summary_table(in, all);
  if (!out.message.empty())
    h << "<p><b>" << html_text(out.message) << "</b></p>\n";
  if (out.plots_made)
    h << "<h2>Summary against " << html_text(in.against) << "</h2>\n<img src=\"summary.png\" alt=\"summary\">\n"
      << "<h2>Curves</h2>\n<img src=\"curves.png\" alt=\"curves\">\n";
  h << "</body></html>\n";
  return h.str();
}

nlohmann::ordered_json number(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; }

} // namespace

std::vector<std::pair<std::string, double>> study_summary_entries(const StudySummary &s)
{
  std::vector<std::pair<std::string, double>> entries{{"peak_strain", s.metrics.peak_strain}};
  const std::vector<double> values = summary_values(s);
  for (std::size_t col = 0; col < values.size(); ++col)
    entries.emplace_back(summary_columns[col].key, values[col]);
  return entries;
}

std::string study_json(const StudyReportInput &in)
{
  nlohmann::ordered_json j;
  j["title"] = in.title;
  j["study_file"] = in.study_file;
  j["against"] = in.against;
  j["cases"] = nlohmann::ordered_json::array();
  for (const auto &c : in.cases) {
    nlohmann::ordered_json jc;
    jc["name"] = c.name;
    jc["label"] = c.label;
    jc["case_file"] = c.file;
    jc["x"] = number(c.x);
    jc["status"] = c.failure.empty() ? "complete" : "failed: " + c.failure;
    jc["engines"] = nlohmann::ordered_json::array();
    for (const auto &r : c.runs) {
      const StudySummary s = study_summary(r.response, c.kind, c.axial);
      nlohmann::ordered_json je;
      je["engine"] = r.engine;
      for (const auto &[key, value] : study_summary_entries(s))
        je[key] = number(value);
      je["elastic_limit_method"] = s.metrics.elastic_limit_method;
      if (!s.error.empty())
        je["error"] = s.error;
      jc["engines"].push_back(je);
    }
    j["cases"].push_back(jc);
  }
  return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

StudyReportOutcome write_study_report(const StudyReportInput &in, const fs::path &dir, const std::string &gnuplot)
{
  StudyReportOutcome out;
  out.dir = fs::absolute(dir);
  const Summaries all = summaries_of(in);
  const std::vector<std::string> engines = engines_of(in);
  replace_folder_atomically(dir, [&](const fs::path &tmp) {
    fs::create_directories(tmp / "data");
    std::ostringstream gp;
    gp << "# Generated by geocomp study: run `gnuplot report.gp` in this folder.\n"
       << "set terminal pngcairo size " << 640 * std::max<std::size_t>(1, engines.size()) << ",1100 font 'sans,10'\n"
       << "set datafile missing '?'\nset grid lc rgb '#dddddd'\nset key below box font ',8'\n";
    curves_figure(in, engines, tmp, gp);
    gp << "set terminal pngcairo size 1400,850 font 'sans,10'\nset key top left box opaque font ',8'\n";
    summary_figure(in, all, engines, tmp, gp);
    write_text(tmp / "report.gp", gp.str());
    if (!program_available(gnuplot)) {
      out.message = "gnuplot not found ('" + gnuplot + "'): plots skipped; run `gnuplot report.gp` in the report folder";
    } else {
      const SubprocessResult run = run_subprocess({gnuplot, "report.gp"}, {tmp, tmp / "gnuplot.log", tmp / "gnuplot.log"});
      out.plots_made = run.succeeded() && fs::exists(tmp / "curves.png") && fs::exists(tmp / "summary.png");
      if (!out.plots_made)
        out.message = "gnuplot failed (exit " + std::to_string(run.exit_code) + "); see gnuplot.log";
    }
    write_text(tmp / "study.json", study_json(in));
    write_text(tmp / "index.html", build_html(in, all, out));
  });
  return out;
}

} // namespace geocomp::compare
