#include "compare/calibrate/FitReport.h"

#include "common/AtomicFile.h"
#include "common/Subprocess.h"
#include "common/Tensor.h"
#include "compare/GnuplotString.h"
#include "compare/HtmlString.h"
#include "compare/JsonString.h"
#include "compare/Metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace geocomp::calibration {

namespace fs = std::filesystem;

namespace {
using compare::html_text;
using compare::json_string;

/// What the report shows beside the fit: the FE-cube verification, the model ladder.
struct FitEvidence {
  const std::vector<Verification> &verification;
  const std::vector<compare::LadderRung> &ladder;
};

std::string num(double v, int digits = 10)
{
  if (!std::isfinite(v))
    return "null";
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string table_text(const HardeningTable &t)
{
  std::string s;
  for (const auto &[k, v] : t.points)
    s += (s.empty() ? "" : ", ") + num(k) + ":" + num(v);
  return s;
}

void write_text(const fs::path &p, const std::string &text)
{
  std::ofstream out(p);
  out << text;
  if (!out)
    throw std::runtime_error("cannot write " + p.string());
}

/// x of a curve: gamma_max on isochoric programs, -eps_zz otherwise (percent).
double abscissa(const ResponseSample &s, compare::CurveKind kind)
{
  return 100.0 * (kind == compare::CurveKind::AxialLateral ? -s.strain(2, 2) : gamma_max(s.strain));
}


std::string fitted_names(const CalibrationResult &r)
{
  std::string s;
  for (const auto &q : r.quantities)
    s += (s.empty() ? "" : ", ") + q.name + (q.weight != 1.0 ? " (weight " + num(q.weight, 4) + ")" : "");
  return s;
}

/// fit.json: everything in the HTML tables, machine-readable.
std::string fit_json(const CalibrationResult &r, const std::vector<FitTarget> &targets, const std::string &case_file,
                     const FitEvidence &evidence)
{
  const std::vector<Verification> &verification = evidence.verification;
  const std::size_t n = r.parameters.size();
  std::ostringstream json;
  json << "{\n  \"format\": \"geocomp-calibration-2\",\n  \"case\": " << json_string(case_file) << ",\n"
       << "  \"units\": \"Pa and degrees; residuals relative to the target's largest q (q, p) or eps_v range\",\n"
       << "  \"quantities\": [";
  for (std::size_t j = 0; j < r.quantities.size(); ++j)
    json << (j ? ", " : "") << "{\"name\": " << json_string(r.quantities[j].name)
         << ", \"weight\": " << num(r.quantities[j].weight) << "}";
  json << "],\n  \"parameters\": [\n";
  for (std::size_t i = 0; i < n; ++i)
    json << "    {\"name\": " << json_string(r.parameters[i].name) << ", \"start\": " << num(r.start[i])
         << ", \"value\": " << num(r.value[i]) << ", \"standard_error\": " << num(r.standard_error[i])
         << ", \"lower\": " << num(r.parameters[i].lower) << ", \"upper\": " << num(r.parameters[i].upper) << "}"
         << (i + 1 < n ? ",\n" : "\n");
  json << "  ],\n  \"fixed\": [";
  for (std::size_t i = 0; i < r.fixed.size(); ++i)
    json << (i ? ", " : "") << "{\"name\": " << json_string(r.fixed[i].name) << ", \"value\": " << num(r.fixed[i].value)
         << "}";
  json << "],\n  \"correlation\": [";
  for (std::size_t i = 0; i < n; ++i) {
    json << (i ? ", " : "") << "[";
    for (std::size_t j = 0; j < n; ++j)
      json << (j ? ", " : "") << num(r.correlation(i, j), 6);
    json << "]";
  }
  json << "],\n  \"initial_cost\": " << num(r.initial_cost) << ",\n  \"final_cost\": " << num(r.final_cost)
       << ",\n  \"residuals\": " << r.residuals << ",\n  \"iterations\": " << r.iterations
       << ",\n  \"seconds\": " << num(r.seconds, 4) << ",\n  \"targets\": [\n";
  for (std::size_t k = 0; k < targets.size(); ++k) {
    json << "    {\"file\": " << json_string(targets[k].name) << ", \"weight\": " << num(targets[k].weight)
         << ", \"samples\": " << targets[k].samples.size() << ", \"q_scale\": " << num(targets[k].q_scale)
         << ", \"eps_v_scale\": " << num(targets[k].volume_scale) << ", \"residuals\": {";
    const auto &rows = r.residual_summary[k];
    for (std::size_t j = 0; j < rows.size(); ++j)
      json << (j ? ", " : "") << json_string(rows[j].quantity) << ": {\"fitted\": " << (rows[j].fitted ? "true" : "false")
           << ", \"rms\": " << num(rows[j].rms, 6) << ", \"max\": " << num(rows[j].max_abs, 6) << "}";
    json << "}}" << (k + 1 < targets.size() ? ",\n" : "\n");
  }
  json << "  ],\n  \"verification\": [";
  for (std::size_t k = 0; k < verification.size(); ++k)
    json << (k ? "," : "") << "\n    {\"file\": " << json_string(verification[k].target)
         << ", \"max_q_cube_vs_point\": " << num(verification[k].cube_vs_point, 6)
         << ", \"max_q_cube_vs_target\": " << num(verification[k].cube_vs_target, 6)
         << ", \"max_q_point_vs_target\": " << num(verification[k].point_vs_target, 6)
         << ", \"cube_seconds\": " << num(verification[k].seconds, 4) << "}";
  json << (verification.empty() ? "" : "\n  ") << "],\n  \"warnings\": [";
  for (std::size_t k = 0; k < r.warnings.size(); ++k)
    json << (k ? ", " : "") << json_string(r.warnings[k]);
  json << "],\n  \"notes\": [";
  for (std::size_t k = 0; k < r.notes.size(); ++k)
    json << (k ? ", " : "") << json_string(r.notes[k]);
  json << "],\n  \"ladder\": " << compare::ladder_json(evidence.ladder, "  ") << "\n}\n";
  return json.str();
}

/// Data files and the gnuplot script for fit_k.png and residuals_k.png; true if gnuplot ran.
bool write_plots(const fs::path &dir, const CalibrationResult &r, const std::vector<FitTarget> &targets)
{
  fs::create_directories(dir / "data");
  std::ostringstream gp;
  gp << "set terminal pngcairo size 800,560 font 'sans,10'\nset grid lc rgb '#dddddd'\nset key top left box opaque\n";
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const compare::CurveKind kind = compare::curve_kind_for(targets[k].program);
    const bool axial = kind == compare::CurveKind::AxialLateral;
    // Columns: x [%], q [MPa], -p [MPa] (compression positive), eps_v [%] (dilation +).
    auto row = [&](const ResponseSample &s) {
      std::ostringstream o;
      o << abscissa(s, kind) << ' ' << deviator(s.stress) * 1e-6 << ' ' << -mean_stress(s.stress) * 1e-6 << ' '
        << 100 * volumetric_strain(s.strain) << '\n';
      return o.str();
    };
    std::ostringstream t, f, res;
    for (std::size_t i = 0; i < targets[k].samples.size(); ++i) {
      const ResponseSample &s = targets[k].response.samples[targets[k].samples[i]];
      t << row(s);
      res << abscissa(s, kind);
      for (const auto &q : r.residual_summary[k])
        res << ' ' << 100 * q.values[i];
      res << '\n';
    }
    for (const auto &s : r.fitted[k].samples)
      f << row(s);
    const std::string id = std::to_string(k);
    write_text(dir / "data" / ("target" + id + ".dat"), t.str());
    write_text(dir / "data" / ("fit" + id + ".dat"), f.str());
    write_text(dir / "data" / ("residuals" + id + ".dat"), res.str());
    const std::string x = axial ? "-{/Symbol e}_{zz} [%]" : "{/Symbol g}_{max} [%]";
    // Folder and file (results/<case>/dem.h5 -> <case>/dem.h5): the file names alone repeat.
    const fs::path file(targets[k].name);
    const std::string name = (file.parent_path().filename() / file.filename()).string();
    const std::string target = "target " + std::to_string(k + 1) + " (" + name + ")";
    gp << "set output 'fit" << id << ".png'\nset title "
       << compare::gnuplot_quoted(target + " and the calibrated material point") << " noenhanced\nset xlabel '" << x << "'\nset ylabel '" << (axial ? "q" : "q, -p") << " [MPa]'\n"
       << (axial ? "set y2label '{/Symbol e}_v [%] (dilation +)'\nset y2tics\n" : "")
       << "plot 'data/target" << id << ".dat' u 1:2 w p pt 7 ps 0.5 lc rgb '#2ca02c' t 'target q', "
       << "'data/fit" << id << ".dat' u 1:2 w l lw 2 lc rgb '#d62728' t 'fit q'";
    if (axial)
      gp << ", 'data/target" << id << ".dat' u 1:4 axes x1y2 w p pt 6 ps 0.5 lc rgb '#1f77b4' t 'target {/Symbol e}_v', "
         << "'data/fit" << id << ".dat' u 1:4 axes x1y2 w l lw 1 dt 2 lc rgb '#1f77b4' t 'fit {/Symbol e}_v'";
    else
      gp << ", 'data/target" << id << ".dat' u 1:3 w p pt 6 ps 0.5 lc rgb '#9467bd' t 'target -p', "
         << "'data/fit" << id << ".dat' u 1:3 w l lw 1 dt 2 lc rgb '#9467bd' t 'fit -p'";
    gp << "\n";
    if (axial)
      gp << "unset y2tics\nunset y2label\n";
    gp << "set output 'residuals" << id << ".png'\nset title "
       << compare::gnuplot_quoted("residuals along " + target + ", model - target") << " noenhanced\nset ylabel 'residual [% of scale]'\nplot ";
    const auto &rows = r.residual_summary[k];
    for (std::size_t j = 0; j < rows.size(); ++j)
      gp << (j ? ", " : "") << "'data/residuals" << id << ".dat' u 1:" << j + 2 << " w lp ps 0.4 "
         << (rows[j].fitted ? "lw 2" : "dt 2") << " t '" << rows[j].quantity << (rows[j].fitted ? " (fitted)" : "")
         << "' noenhanced";
    gp << "\n";
  }
  write_text(dir / "fit.gp", gp.str());
  // No shell: the folder arrives as it is, whatever characters it holds.
  return run_subprocess({"gnuplot", "fit.gp"}, {dir, dir / "gnuplot.log", dir / "gnuplot.log"}).succeeded();
}

std::string fit_html(const CalibrationResult &r, const std::vector<FitTarget> &targets, const std::string &case_file,
                     const std::string &fragment_name, const FitEvidence &evidence, bool plots)
{
  const std::vector<Verification> &verification = evidence.verification;
  const std::size_t n = r.parameters.size();
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Calibration: " << html_text(case_file)
       << "</title><style>body{font-family:sans-serif;max-width:1100px;margin:2em auto}table{border-collapse:collapse}"
          "td,th{border:1px solid #bbb;padding:3px 8px}td{text-align:right;font-family:monospace}img{max-width:49%}"
          "</style></head><body>\n<h1>Calibration of the continuum parameters</h1>\n<p>Case <code>"
       << html_text(case_file) << "</code>; " << targets.size() << " target curves, fitted quantities "
       << fitted_names(r) << ", " << r.residuals << " residuals, " << r.iterations
       << " Levenberg-Marquardt iterations, " << num(r.seconds, 3) << " s. Cost " << num(r.initial_cost, 6)
       << " &rarr; " << num(r.final_cost, 6) << ". Units: Pa and degrees. "
       << "Standard errors from the Jacobian covariance scaled by the residual variance; the parameters the "
          "calibration does not free keep the case's values (fixed). Numbers also in "
          "<a href=\"fit.json\">fit.json</a>.</p>\n"
       << "<table><tr><th>parameter</th><th>start</th><th>calibrated</th><th>standard error</th><th>bounds</th></tr>\n";
  for (std::size_t i = 0; i < n; ++i)
    html << "<tr><th>" << r.parameters[i].name << "</th><td>" << num(r.start[i], 6) << "</td><td>"
         << num(r.value[i], 6) << "</td><td>" << num(r.standard_error[i], 3) << "</td><td>["
         << num(r.parameters[i].lower, 3) << ", " << num(r.parameters[i].upper, 3) << "]</td></tr>\n";
  for (const FixedParameter &f : r.fixed)
    html << "<tr><th>" << f.name << "</th><td>" << num(f.value, 6) << "</td><td>" << num(f.value, 6)
         << "</td><td>fixed</td><td>&mdash;</td></tr>\n";
  html << "</table>\n";
  if (!r.warnings.empty()) {
    html << "<h2>Warnings</h2>\n";
    for (const auto &w : r.warnings)
      html << "<p><strong>" << html_text(w) << "</strong></p>\n";
  }
  html << "<h2>Correlations</h2>\n<table><tr><th></th>";
  for (std::size_t j = 0; j < n; ++j)
    html << "<th>" << r.parameters[j].name << "</th>";
  html << "</tr>\n";
  for (std::size_t i = 0; i < n; ++i) {
    html << "<tr><th>" << r.parameters[i].name << "</th>";
    for (std::size_t j = 0; j < n; ++j)
      html << "<td>" << num(r.correlation(i, j), 3) << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n<h2>Residuals</h2>\n<p>Model minus target at the target's samples, relative to the target's "
          "largest q (q, p) or its eps_v range (eps_v), without weights; * marks the fitted quantities.</p>\n"
          "<table><tr><th>target</th><th>weight</th>";
  const std::vector<ResidualQuantity> all = all_quantities();
  for (const auto &q : all)
    html << "<th>rms " << q.name << "</th><th>max " << q.name << "</th>";
  html << "</tr>\n";
  for (std::size_t k = 0; k < targets.size(); ++k) {
    html << "<tr><th>" << html_text(targets[k].name) << "</th><td>" << num(targets[k].weight, 4) << "</td>";
    for (const auto &row : r.residual_summary[k])
      html << "<td>" << num(row.rms, 4) << (row.fitted ? "*" : "") << "</td><td>" << num(row.max_abs, 4) << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n";
  if (!verification.empty()) {
    html << "<h2>Verification on the deal.II cube</h2>\n<p>The calibrated section rerun on the finite-element cube "
            "for each target's program; largest differences of q along the path, relative to the target's largest q."
            "</p>\n<table><tr><th>target</th><th>cube vs material point</th><th>cube vs target</th>"
            "<th>material point vs target</th><th>cube run [s]</th></tr>\n";
    for (const auto &v : verification)
      html << "<tr><th>" << html_text(v.target) << "</th><td>" << num(v.cube_vs_point, 3) << "</td><td>"
           << num(v.cube_vs_target, 3) << "</td><td>" << num(v.point_vs_target, 3) << "</td><td>"
           << num(v.seconds, 3) << "</td></tr>\n";
    html << "</table>\n";
  }
  html << compare::ladder_html(evidence.ladder) << "<h2>Curves</h2>\n";
  if (plots)
    for (std::size_t k = 0; k < targets.size(); ++k)
      html << "<img src=\"fit" << k << ".png\" alt=\"fit " << k << "\"><img src=\"residuals" << k
           << ".png\" alt=\"residuals " << k << "\">\n";
  else
    html << "<p>(no plots: gnuplot failed, see gnuplot.log)</p>\n";
  for (const auto &note : r.notes)
    html << "<p>" << html_text(note) << "</p>\n";
  html << "<p>Calibrated section: <code>" << html_text(fragment_name)
       << "</code> (pull it into a case file with <code>include &lt;path&gt;</code> after its own continuum "
          "section).</p>\n</body></html>\n";
  return html.str();
}

void write_folder(const fs::path &dir, const std::string &fragment_name, const CalibrationResult &r,
                  const std::vector<FitTarget> &targets, const std::string &case_file,
                  const FitEvidence &evidence)
{
  write_text(dir / fragment_name, calibrated_fragment(r, fragment_comment(case_file, targets.size())));
  std::ostringstream tsv;
  tsv << "# name\tstart\tvalue\tstandard_error (\"fixed\": not calibrated, the case's value)\n";
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    tsv << r.parameters[i].name << '\t' << num(r.start[i]) << '\t' << num(r.value[i]) << '\t'
        << num(r.standard_error[i]) << '\n';
  for (const FixedParameter &f : r.fixed)
    tsv << f.name << '\t' << num(f.value) << '\t' << num(f.value) << "\tfixed\n";
  write_text(dir / "parameters.tsv", tsv.str());
  write_text(dir / "fit.json", fit_json(r, targets, case_file, evidence));
  const bool plots = write_plots(dir, r, targets);
  write_text(dir / "index.html", fit_html(r, targets, case_file, fragment_name, evidence, plots));
}
} // namespace

namespace {
/// The entries of `p` whose family is in `families` ("E", "nu", "cohesion", "friction",
/// "dilatancy") as a continuum subsection, after one comment line per `comments` (a line
/// break in one, from a file name, would end the comment and start a statement: written
/// as a space).
std::string fragment(const ContinuumParameters &p, const std::vector<std::string> &comments,
                     const std::vector<std::string> &families)
{
  auto has = [&](const char *f) { return std::find(families.begin(), families.end(), f) != families.end(); };
  std::ostringstream o;
  for (std::string line : comments) {
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::replace(line.begin(), line.end(), '\r', ' ');
    o << "# " << line << "\n";
  }
  o << "subsection continuum\n";
  if (has("E"))
    o << "  set youngs modulus  = " << num(p.youngs_modulus) << "\n";
  if (has("nu"))
    o << "  set poisson ratio   = " << num(p.poisson_ratio) << "\n";
  if (has("cohesion"))
    o << "  set cohesion        = " << table_text(p.cohesion) << "\n";
  if (has("friction"))
    o << "  set friction angle  = " << table_text(p.friction_angle) << "\n";
  if (has("dilatancy"))
    o << "  set dilatancy angle = " << table_text(p.dilatancy_angle) << "\n";
  o << "end\n";
  return o.str();
}

/// The family of a parameter name: "friction[1]" -> "friction".
std::string family_of(const std::string &name) { return name.substr(0, name.find('[')); }
} // namespace

std::string continuum_fragment(const ContinuumParameters &p, const std::string &comment)
{
  return fragment(p, {comment}, {"E", "nu", "cohesion", "friction", "dilatancy"});
}

std::string fragment_comment(const std::string &case_file, std::size_t targets)
{
  return "calibrated from " + case_file + " (" + std::to_string(targets) + " target curves)";
}

std::string calibrated_fragment(const CalibrationResult &r, const std::string &comment)
{
  std::vector<std::string> families;
  for (const FreeParameter &p : r.parameters)
    if (std::find(families.begin(), families.end(), family_of(p.name)) == families.end())
      families.push_back(family_of(p.name));
  std::string kept;
  for (const FixedParameter &f : r.fixed)
    if (std::find(families.begin(), families.end(), family_of(f.name)) != families.end())
      kept += (kept.empty() ? "" : ", ") + f.name;
  return fragment(r.calibrated,
                  {comment, "only the entries that hold a calibrated parameter" +
                              (kept.empty() ? std::string() : " (" + kept + " in them: the case's values, not calibrated)")},
                  families);
}

void write_fit_report(const fs::path &dir, const std::string &fragment_name, const CalibrationResult &r,
                      const std::vector<FitTarget> &targets, const std::string &case_file,
                      const std::vector<Verification> &verification,
                      const std::vector<compare::LadderRung> &ladder)
{
  write_atomically(dir, [&](const fs::path &tmp) {
    try {
      fs::create_directories(tmp);
      write_folder(tmp, fragment_name, r, targets, case_file, FitEvidence{verification, ladder});
      fs::remove_all(dir); // the previous report, replaced as a whole
    } catch (...) {
      std::error_code ec;
      fs::remove_all(tmp, ec);
      throw;
    }
  });
}

std::vector<std::pair<std::string, std::string>> read_parameter_table(const fs::path &dir)
{
  std::vector<std::pair<std::string, std::string>> rows;
  std::ifstream in(dir / "parameters.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream s(line);
    std::string name, start, value, error;
    if (std::getline(s, name, '\t') && std::getline(s, start, '\t') && std::getline(s, value, '\t') &&
        std::getline(s, error, '\t'))
      rows.emplace_back(name, value + (error == "null" ? "" : error == "fixed" ? " (fixed)" : " +- " + error));
  }
  return rows;
}

} // namespace geocomp::calibration
