#include "compare/ShearBoxReport.h"

#include "common/AtomicFile.h"
#include "common/Subprocess.h"
#include "compare/GnuplotString.h"
#include "compare/HtmlString.h"
#include "compare/RunFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace geocomp::compare {

namespace {


std::string fmt(double v, const char* f = "%.4g") { return format_number(v, f); }
void write_text(const fs::path& p, const std::string& text) { write_text_file(p, text); }

std::string box_label(double L) { return L > 0.0 ? "L = " + fmt(100.0 * L, "%.3g") + " cm" : "L = ?"; }

double mean(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

// Runs grouped by (box length, `key`), points by `x` (both rounded to 6 digits).
std::vector<MuBSeries> group(const std::vector<ShearBoxRun>& runs, double (*key)(const ShearBoxRun&),
                             double (*x)(const ShearBoxRun&), const std::string& key_name)
{
  auto r6 = [](double v) { return std::stod(fmt(v, "%.6g")); };
  std::map<std::pair<double, double>, std::map<double, MuBPoint>> g;
  for (const ShearBoxRun& r : runs) {
    MuBPoint& p = g[{r6(r.box_length), r6(key(r))}][r6(x(r))];
    p.x = r6(x(r));
    p.peak.push_back(r.peak_mu_b);
    p.residual.push_back(r.residual_mu_b);
  }
  std::vector<MuBSeries> out;
  for (const auto& [k, points] : g) {
    MuBSeries s;
    s.label = box_label(k.first) + ", " + key_name + " = " + fmt(k.second, "%.3g");
    for (const auto& [xv, p] : points) s.points.push_back(p);
    out.push_back(std::move(s));
  }
  return out;
}

const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};

// Fig. 5: (a) lid rise, (b) tau_x against U, one curve per run.
void fig5(const std::vector<ShearBoxRun>& runs, const fs::path& dir, std::ostringstream& gp)
{
  gp << "set output 'fig5.png'\nset multiplot layout 3,1 title 'S4 Fig. 5: direct shear of clumped rubble'\n"
     << "set xlabel 'shear displacement U [mm]'\nset ylabel 'vertical displacement of the lid [mm] (up: dilation)'\n"
     << "set title '(a) vertical displacement'\n";
  std::ostringstream plot_a, plot_b, plot_c;
  double c_um = 1.0;  // (c) spans 1.5 x the largest contraction down and 3 x up [um]
  for (const ShearBoxRun& r : runs) c_um = std::max(c_um, 1e6 * r.max_contraction);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const ShearBoxRun& r = runs[k];
    std::ostringstream d;
    d << "# U_mm lid_rise_mm tau_x_kPa mu_b\n";
    for (const ShearBoxCurvePoint& p : r.curve)
      d << 1e3 * p.shear << ' ' << 1e3 * p.lid_rise << ' ' << 1e-3 * p.tau_x << ' ' << p.mu_b << '\n';
    const std::string file = "data/run" + std::to_string(k) + ".dat";
    write_text(dir / file, d.str());
    const std::string title = fmt(1e-3 * r.normal_stress, "%.0f") + " kPa, mu " + fmt(r.contact_friction, "%.2g") +
                              ", seed " + std::to_string(r.seed) + ", " + box_label(r.box_length);
    const std::string style = " w l lw 2 dt " + std::to_string(1 + (k / 8) % 4) + " lc rgb '" + std::string(colours[k % 8]) +
                              "' t " + gnuplot_quoted(title) + " noenhanced";
    plot_a << (k ? ", " : "plot ") << "'" << file << "' u 1:2" << style;
    plot_b << (k ? ", " : "plot ") << "'" << file << "' u 1:3" << style;
    plot_c << (k ? ", " : "plot [0:" + fmt(0.2 * 1e3 * r.curve.back().shear, "%.3g") + "] [" + fmt(-1.5 * c_um, "%.3g") +
                            ":" + fmt(3.0 * c_um, "%.3g") + "] ") << "'" << file
           << "' u 1:($2*1000)" << style;
  }
  gp << plot_a.str() << "\nset title '(b) shear stress {/Symbol t}_x = F_S / (B (L - U)) (S4 eq. 23)'\n"
     << "set ylabel 'shear stress [kPa]'\n" << plot_b.str()
     << "\nset title '(c) the start of (a): contraction, then dilation'\nset ylabel 'vertical displacement of the lid [um]'\n"
     << plot_c.str() << "\nunset multiplot\n";
}

// One panel of Fig. 7: each series' runs (peak filled, residual open) and the means.
void fig7_panel(const std::vector<MuBSeries>& series, const fs::path& dir, const std::string& tag,
                std::ostringstream& gp)
{
  std::ostringstream plot;
  for (std::size_t k = 0; k < series.size(); ++k) {
    std::ostringstream pts, means;
    pts << "# x peak_mu_b residual_mu_b (one row per run)\n";
    means << "# x mean_peak_mu_b mean_residual_mu_b runs\n";
    for (const MuBPoint& p : series[k].points) {
      for (std::size_t j = 0; j < p.peak.size(); ++j) pts << p.x << ' ' << p.peak[j] << ' ' << p.residual[j] << '\n';
      means << p.x << ' ' << p.mean_peak() << ' ' << p.mean_residual() << ' ' << p.peak.size() << '\n';
    }
    const std::string base = "data/fig7" + tag + "_" + std::to_string(k);
    write_text(dir / (base + "_runs.dat"), pts.str());
    write_text(dir / (base + "_mean.dat"), means.str());
    const std::string c = std::string(" lc rgb '") + colours[k % 8] + "'";
    plot << (k ? ", " : "plot ") << "'" << base << "_mean.dat' u 1:2 w lp pt 7 ps 1.2 lw 2" << c << " t "
         << gnuplot_quoted(series[k].label + ": peak") << " noenhanced, '" << base << "_mean.dat' u 1:3 w lp pt 6 ps 1.2 dt 2"
         << c << " t " << gnuplot_quoted(series[k].label + ": residual") << " noenhanced, '" << base
         << "_runs.dat' u 1:2 w p pt 7 ps 0.5" << c << " notitle, '" << base << "_runs.dat' u 1:3 w p pt 6 ps 0.5" << c
         << " notitle";
  }
  gp << plot.str() << "\n";
}

void fig7(const std::vector<ShearBoxRun>& runs, const fs::path& dir, std::ostringstream& gp)
{
  gp << "set output 'fig7.png'\nset multiplot layout 1,2 title 'S4 Fig. 7: effective friction {/Symbol m}_b = F_S / F_N (S4 eq. 24)'\n"
     << "set ylabel '{/Symbol m}_b'\nset key below box font ',8'\nset offsets graph 0.08, graph 0.08, graph 0.1, graph 0.1\n"
     << "set title '(a) against the normal stress'\nset xlabel 'normal stress {/Symbol s}_n [kPa]'\n";
  std::vector<MuBSeries> a = mu_b_against_normal_stress(runs);
  for (MuBSeries& s : a)
    for (MuBPoint& p : s.points) p.x *= 1e-3;  // kPa
  fig7_panel(a, dir, "a", gp);
  gp << "set title '(b) against the contact friction'\nset xlabel 'contact friction {/Symbol m}_p'\n";
  fig7_panel(mu_b_against_contact_friction(runs), dir, "b", gp);
  gp << "unset multiplot\n";
}

std::string run_table(const std::vector<ShearBoxRun>& runs)
{
  std::ostringstream h;
  h << "<table><tr><th>run</th><th>box</th><th>clumps</th><th>&sigma;<sub>n</sub> [kPa]</th><th>contact &mu;</th>"
       "<th>seed</th><th>e at shear start</th><th>shear speed [m/s]</th><th>I</th><th>peak &mu;<sub>b</sub> (at U mm)</th>"
       "<th>residual &mu;<sub>b</sub></th><th>max contraction [mm]</th><th>final lid rise [mm]</th><th>wall time [s]</th></tr>\n";
  for (const ShearBoxRun& r : runs)
    h << "<tr><td>" << html_text(r.name) << "</td><td>" << box_label(r.box_length) << "</td><td>" << r.clumps << "</td><td>"
      << fmt(1e-3 * r.normal_stress, "%.0f") << "</td><td>" << fmt(r.contact_friction, "%.3g") << "</td><td>" << r.seed
      << "</td><td>" << fmt(r.void_ratio, "%.3f") << "</td><td>" << fmt(r.shear_speed, "%.3g") << "</td><td>"
      << fmt(r.inertial_number, "%.2e") << "</td><td>" << fmt(r.peak_mu_b, "%.3f") << " (" << fmt(1e3 * r.shear_at_peak, "%.1f")
      << ")</td><td>" << fmt(r.residual_mu_b, "%.3f") << "</td><td>" << fmt(1e3 * r.max_contraction, "%.3f") << "</td><td>"
      << fmt(1e3 * r.final_dilation, "%+.2f") << "</td><td>" << fmt(r.seconds, "%.0f") << "</td></tr>\n";
  h << "</table>\n";
  return h.str();
}

std::string series_table(const std::vector<MuBSeries>& series, const std::string& x_name, double x_scale)
{
  std::ostringstream h;
  h << "<table><tr><th>series</th><th>" << x_name << "</th><th>runs</th><th>mean peak &mu;<sub>b</sub> (min-max)</th>"
       "<th>mean residual &mu;<sub>b</sub></th></tr>\n";
  for (const MuBSeries& s : series)
    for (const MuBPoint& p : s.points)
      h << "<tr><td>" << html_text(s.label) << "</td><td>" << fmt(x_scale * p.x, "%.3g") << "</td><td>" << p.peak.size()
        << "</td><td>" << fmt(p.mean_peak(), "%.3f") << " (" << fmt(*std::min_element(p.peak.begin(), p.peak.end()), "%.3f")
        << "-" << fmt(*std::max_element(p.peak.begin(), p.peak.end()), "%.3f") << ")</td><td>"
        << fmt(p.mean_residual(), "%.3f") << "</td></tr>\n";
  h << "</table>\n";
  return h.str();
}

std::string build_html(const std::vector<ShearBoxRun>& runs, bool plots, const std::string& message)
{
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>S4 direct shear box</title><style>"
       "body{font-family:sans-serif;max-width:1200px;margin:2em auto}table{border-collapse:collapse;margin:1em 0}"
       "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}img{max-width:100%}</style></head><body>\n"
    << "<h1>S4 direct shear box of clumped rubble (Yan &amp; Ji 2009)</h1>\n"
    << "<p>F<sub>N</sub> = P + W<sub>P</sub> + W<sub>B</sub>, F<sub>S</sub> = the x force on the lid and the four upper "
       "sides (S4 eq. 22); &sigma;<sub>z</sub>, &tau;<sub>x</sub> on B (L - U) (eq. 23); &mu;<sub>b</sub> = F<sub>S</sub> / "
       "F<sub>N</sub> (eq. 24). Lid displacement from the start of shear, up = dilation. Inertial number I = "
       "&gamma;&#775; d sqrt(&rho;/&sigma;<sub>n</sub>) with &gamma;&#775; = v / (10 d): quasi-static below 1e-3. Residual "
       "&mu;<sub>b</sub>: mean over the last tenth of the shear.</p>\n"
    << "<p>S4 (section 3.3; Fig. 5 and 7 are not tabulated in the text): the lid first goes down (contraction &lt; 2 mm, "
       "larger at higher load) then up (dilation, larger at lower load); &mu;<sub>b</sub> falls with the normal stress and "
       "rises with the contact friction at a decreasing rate. See docs/s4-direct-shear.md.</p>\n";
  h << "<h2>Runs</h2>\n" << run_table(runs);
  h << "<h2>Fig. 7 series (means over seeds)</h2>\n"
    << series_table(mu_b_against_normal_stress(runs), "&sigma;<sub>n</sub> [kPa]", 1e-3)
    << series_table(mu_b_against_contact_friction(runs), "contact &mu;", 1.0);
  if (!message.empty()) h << "<p><b>" << html_text(message) << "</b></p>\n";
  if (plots)
    h << "<h2>Fig. 5</h2>\n<img src=\"fig5.png\" alt=\"Fig. 5\">\n<h2>Fig. 7</h2>\n<img src=\"fig7.png\" alt=\"Fig. 7\">\n";
  h << "</body></html>\n";
  return h.str();
}

}  // namespace

double MuBPoint::mean_peak() const { return mean(peak); }
double MuBPoint::mean_residual() const { return mean(residual); }

std::vector<MuBSeries> mu_b_against_normal_stress(const std::vector<ShearBoxRun>& runs)
{
  return group(runs, [](const ShearBoxRun& r) { return r.contact_friction; },
               [](const ShearBoxRun& r) { return r.normal_stress; }, "contact mu");
}

std::vector<MuBSeries> mu_b_against_contact_friction(const std::vector<ShearBoxRun>& runs)
{
  auto kpa = [](const ShearBoxRun& r) { return 1e-3 * r.normal_stress; };
  return group(runs, kpa, [](const ShearBoxRun& r) { return r.contact_friction; }, "sigma_n [kPa]");
}

ShearBoxReportOutcome write_shear_box_report(const std::vector<ShearBoxRun>& runs, const fs::path& dir,
                                             const std::string& gnuplot)
{
  if (runs.empty()) throw std::invalid_argument("write_shear_box_report: no runs");
  ShearBoxReportOutcome out;
  out.dir = fs::absolute(dir);
  replace_folder_atomically(dir, [&](const fs::path& tmp) {
    fs::create_directories(tmp / "data");
    std::ostringstream gp;
    gp << "# Generated by geocomp shear-box: run `gnuplot report.gp` in this folder.\n"
       << "set terminal pngcairo size 1000,1250 font 'sans,10'\nset grid lc rgb '#dddddd'\nset key top left box opaque font ',8'\n";
    fig5(runs, tmp, gp);
    // Fig. 7's keys go below the panels: with a series per box and friction (a) and per box
    // and sigma_n (b) they would cover the low residual points.
    gp << "set terminal pngcairo size 1200,680 font 'sans,10'\n";
    fig7(runs, tmp, gp);
    write_text(tmp / "report.gp", gp.str());
    if (!program_available(gnuplot)) {
      out.message = "gnuplot not found ('" + gnuplot + "'): plots skipped; run `gnuplot report.gp` in the report folder";
    } else {
      const SubprocessResult run = run_subprocess({gnuplot, "report.gp"}, {tmp, tmp / "gnuplot.log", tmp / "gnuplot.log"});
      out.plots_made = run.succeeded() && fs::exists(tmp / "fig5.png") && fs::exists(tmp / "fig7.png");
      if (!out.plots_made) out.message = "gnuplot failed (exit " + std::to_string(run.exit_code) + "); see gnuplot.log";
    }
    write_text(tmp / "index.html", build_html(runs, out.plots_made, out.message));
  });
  return out;
}

}  // namespace geocomp::compare
