#include "compare/calibrate/FitReport.h"

#include "common/Tensor.h"
#include "compare/Metrics.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace geocomp::calibration {

namespace fs = std::filesystem;

namespace {
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
} // namespace

std::string continuum_fragment(const ContinuumParameters &p, const std::string &comment)
{
  std::ostringstream o;
  o << "# " << comment << "\n"
    << "subsection continuum\n"
    << "  set youngs modulus  = " << num(p.youngs_modulus) << "\n"
    << "  set poisson ratio   = " << num(p.poisson_ratio) << "\n"
    << "  set cohesion        = " << table_text(p.cohesion) << "\n"
    << "  set friction angle  = " << table_text(p.friction_angle) << "\n"
    << "  set dilatancy angle = " << table_text(p.dilatancy_angle) << "\n"
    << "end\n";
  return o.str();
}

void write_fit_report(const fs::path &dir, const std::string &fragment_name, const CalibrationResult &r,
                      const std::vector<FitTarget> &targets, const std::string &case_file)
{
  const fs::path tmp = dir.string() + ".tmp";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const std::size_t n = r.parameters.size();

  write_text(tmp / fragment_name,
             continuum_fragment(r.calibrated, "calibrated by `geocomp calibrate " + case_file + "` (" +
                                                std::to_string(targets.size()) + " target curves)"));
  std::ostringstream tsv, json, html, gp;
  tsv << "# name\tstart\tvalue\tstandard_error\n";
  for (std::size_t i = 0; i < n; ++i)
    tsv << r.parameters[i].name << '\t' << num(r.start[i]) << '\t' << num(r.value[i]) << '\t'
        << num(r.standard_error[i]) << '\n';
  write_text(tmp / "parameters.tsv", tsv.str());

  json << "{\n  \"format\": \"geocomp-calibration-1\",\n  \"case\": \"" << case_file << "\",\n"
       << "  \"units\": \"Pa and degrees\",\n  \"parameters\": [\n";
  for (std::size_t i = 0; i < n; ++i)
    json << "    {\"name\": \"" << r.parameters[i].name << "\", \"start\": " << num(r.start[i])
         << ", \"value\": " << num(r.value[i]) << ", \"standard_error\": " << num(r.standard_error[i])
         << ", \"lower\": " << num(r.parameters[i].lower) << ", \"upper\": " << num(r.parameters[i].upper) << "}"
         << (i + 1 < n ? ",\n" : "\n");
  json << "  ],\n  \"correlation\": [";
  for (std::size_t i = 0; i < n; ++i) {
    json << (i ? ", " : "") << "[";
    for (std::size_t j = 0; j < n; ++j)
      json << (j ? ", " : "") << num(r.correlation(i, j), 6);
    json << "]";
  }
  json << "],\n  \"initial_cost\": " << num(r.initial_cost) << ",\n  \"final_cost\": " << num(r.final_cost)
       << ",\n  \"residuals\": " << r.residuals << ",\n  \"iterations\": " << r.iterations
       << ",\n  \"seconds\": " << num(r.seconds, 4) << ",\n  \"targets\": [\n";
  for (std::size_t k = 0; k < targets.size(); ++k)
    json << "    {\"file\": \"" << targets[k].name << "\", \"weight\": " << num(targets[k].weight)
         << ", \"rms_deviator_relative\": " << num(r.rms_deviator[k], 6) << "}" << (k + 1 < targets.size() ? ",\n" : "\n");
  json << "  ],\n  \"notes\": [";
  for (std::size_t k = 0; k < r.notes.size(); ++k)
    json << (k ? ", " : "") << "\"" << r.notes[k] << "\"";
  json << "]\n}\n";
  write_text(tmp / "fit.json", json.str());

  // Curves: target points and fitted line, deviator q [MPa] against the curve's strain [%].
  fs::create_directories(tmp / "data");
  gp << "set terminal pngcairo size 800,560 font 'sans,10'\nset grid lc rgb '#dddddd'\nset key top left box opaque\n";
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const compare::CurveKind kind = compare::curve_kind_for(targets[k].program);
    std::ostringstream t, f;
    for (std::size_t i : targets[k].samples) {
      const ResponseSample &s = targets[k].response.samples[i];
      t << abscissa(s, kind) << ' ' << deviator(s.stress) * 1e-6 << ' ' << 100 * volumetric_strain(s.strain) << '\n';
    }
    for (const auto &s : r.fitted[k].samples)
      f << abscissa(s, kind) << ' ' << deviator(s.stress) * 1e-6 << ' ' << 100 * volumetric_strain(s.strain) << '\n';
    write_text(tmp / "data" / ("target" + std::to_string(k) + ".dat"), t.str());
    write_text(tmp / "data" / ("fit" + std::to_string(k) + ".dat"), f.str());
    const std::string x = kind == compare::CurveKind::AxialLateral ? "-{/Symbol e}_{zz} [%]" : "{/Symbol g}_{max} [%]";
    gp << "set output 'fit" << k << ".png'\nset title 'target " << k + 1 << " (" << fs::path(targets[k].name).filename().string()
       << ") and the calibrated material point'\nset xlabel '" << x << "'\nset ylabel 'q [MPa]'\n"
       << "set y2label '{/Symbol e}_v [%] (dilation +)'\nset y2tics\n"
       << "plot 'data/target" << k << ".dat' u 1:2 w p pt 7 ps 0.5 lc rgb '#2ca02c' t 'target q', "
       << "'data/fit" << k << ".dat' u 1:2 w l lw 2 lc rgb '#d62728' t 'fit q', "
       << "'data/target" << k << ".dat' u 1:3 axes x1y2 w p pt 6 ps 0.5 lc rgb '#1f77b4' t 'target {/Symbol e}_v', "
       << "'data/fit" << k << ".dat' u 1:3 axes x1y2 w l lw 1 dt 2 lc rgb '#1f77b4' t 'fit {/Symbol e}_v'\n"
       << "unset y2tics\nunset y2label\n";
  }
  write_text(tmp / "fit.gp", gp.str());
  const std::string cmd = "cd '" + tmp.string() + "' && gnuplot fit.gp > gnuplot.log 2>&1";
  const bool plots = std::system(cmd.c_str()) == 0;

  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Calibration: " << case_file
       << "</title><style>body{font-family:sans-serif;max-width:1100px;margin:2em auto}table{border-collapse:collapse}"
          "td,th{border:1px solid #bbb;padding:3px 8px}td{text-align:right;font-family:monospace}img{max-width:49%}"
          "</style></head><body>\n<h1>Calibration of the continuum parameters</h1>\n<p>Case <code>"
       << case_file << "</code>; " << targets.size() << " target curves, " << r.residuals << " residuals, "
       << r.iterations << " Levenberg-Marquardt iterations, " << num(r.seconds, 3) << " s. Cost "
       << num(r.initial_cost, 6) << " &rarr; " << num(r.final_cost, 6) << ". Units: Pa and degrees. "
       << "Standard errors from the Jacobian covariance scaled by the residual variance.</p>\n"
       << "<table><tr><th>parameter</th><th>start</th><th>calibrated</th><th>standard error</th><th>bounds</th></tr>\n";
  for (std::size_t i = 0; i < n; ++i)
    html << "<tr><th>" << r.parameters[i].name << "</th><td>" << num(r.start[i], 6) << "</td><td>"
         << num(r.value[i], 6) << "</td><td>" << num(r.standard_error[i], 3) << "</td><td>["
         << num(r.parameters[i].lower, 3) << ", " << num(r.parameters[i].upper, 3) << "]</td></tr>\n";
  html << "</table>\n<h2>Correlations</h2>\n<table><tr><th></th>";
  for (std::size_t j = 0; j < n; ++j)
    html << "<th>" << r.parameters[j].name << "</th>";
  html << "</tr>\n";
  for (std::size_t i = 0; i < n; ++i) {
    html << "<tr><th>" << r.parameters[i].name << "</th>";
    for (std::size_t j = 0; j < n; ++j)
      html << "<td>" << num(r.correlation(i, j), 3) << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n<h2>Curves</h2>\n<table><tr><th>target</th><th>weight</th><th>rms of q residual / max q</th></tr>\n";
  for (std::size_t k = 0; k < targets.size(); ++k)
    html << "<tr><th>" << targets[k].name << "</th><td>" << num(targets[k].weight, 4) << "</td><td>"
         << num(r.rms_deviator[k], 4) << "</td></tr>\n";
  html << "</table>\n";
  if (plots)
    for (std::size_t k = 0; k < targets.size(); ++k)
      html << "<img src=\"fit" << k << ".png\" alt=\"fit " << k << "\">\n";
  else
    html << "<p>(no plots: gnuplot failed, see gnuplot.log)</p>\n";
  for (const auto &note : r.notes)
    html << "<p>" << note << "</p>\n";
  html << "<p>Calibrated section: <code>" << fragment_name << "</code> (use it with <code>include</code>).</p>\n</body></html>\n";
  write_text(tmp / "index.html", html.str());

  fs::remove_all(dir);
  fs::rename(tmp, dir);
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
      rows.emplace_back(name, value + (error == "null" ? "" : " +- " + error));
  }
  return rows;
}

} // namespace geocomp::calibration
