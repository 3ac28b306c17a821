#include "compare/CrushReport.h"

#include "common/AtomicFile.h"
#include "common/Subprocess.h"
#include "compare/GnuplotString.h"
#include "compare/HtmlString.h"
#include "compare/RunFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace geocomp::compare {

namespace {

std::string fmt(double v, const char* f = "%.4g") { return format_number(v, f); }
void write_text(const fs::path& p, const std::string& text) { write_text_file(p, text); }

const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};

std::string style(std::size_t k, const std::string& title)
{
  return " w l lw 2 dt " + std::to_string(1 + (k / 8) % 4) + " lc rgb '" + colours[k % 8] + "' t " +
         gnuplot_quoted(title) + " noenhanced";
}

std::string label(const CrushRun& r)
{
  return r.name + " (" + r.breakage_mode + (r.breakage_mode == "cube" ? ", " + r.cut_point : "") + ")";
}

// Uniaxial: lid stress [MPa] against strain [%], one curve per run.
void stress_strain(const std::vector<CrushRun>& runs, const fs::path& dir, std::ostringstream& gp)
{
  std::ostringstream plot;
  std::size_t k = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].single()) continue;
    const fs::path f = runs[i].name + "_curve.tsv";
    const std::size_t ce = runs[i].curve.column("strain", f), cs = runs[i].curve.column("vertical_stress_kPa", f);
    std::ostringstream d;
    d << "# strain_percent lid_stress_MPa\n";
    for (const auto& row : runs[i].curve.rows) d << 100.0 * row[ce] << ' ' << 1e-3 * row[cs] << '\n';
    const std::string file = "data/curve" + std::to_string(i) + ".dat";
    write_text(dir / file, d.str());
    plot << (k ? ", " : "plot ") << "'" << file << "' u 1:2" << style(k, label(runs[i]));
    ++k;
  }
  gp << "set output 'stress_strain.png'\nset title 'Uniaxial compression with breakage (S2 sec. 2.4)'\n"
     << "set xlabel 'vertical strain [%]'\nset ylabel 'lid stress [MPa]'\nunset logscale x\n" << plot.str() << "\n";
}

// Single particle: platen force [kN] against approach [mm], every particle of the first seed.
void force_approach(const std::vector<CrushRun>& runs, const fs::path& dir, std::ostringstream& gp)
{
  std::ostringstream plot;
  std::size_t k = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].single()) continue;
    const fs::path f = runs[i].name + "_curve.tsv";
    const std::size_t cp = runs[i].curve.column("particle", f), ca = runs[i].curve.column("approach_mm", f),
                      cf = runs[i].curve.column("force_N", f);
    const double per_seed = runs[i].number("particles", 1e300);
    std::ostringstream d;
    d << "# approach_mm force_kN (a blank line between particles of the first seed)\n";
    double last = -1.0;
    for (const auto& row : runs[i].curve.rows) {
      if (row[cp] >= per_seed) break;
      if (row[cp] != last && last >= 0.0) d << '\n';
      last = row[cp];
      d << row[ca] << ' ' << 1e-3 * row[cf] << '\n';
    }
    const std::string file = "data/force" + std::to_string(i) + ".dat";
    write_text(dir / file, d.str());
    plot << (k ? ", " : "plot ") << "'" << file << "' u 1:2 w l lw 1 lc rgb '" << colours[k % 8] << "' t "
         << gnuplot_quoted(label(runs[i]) + ", first seed") << " noenhanced";
    ++k;
  }
  gp << "set output 'force_approach.png'\nset title 'Single-particle crushing: platen force (S2 sec. 1.2)'\n"
     << "set xlabel 'approach of the platens [mm]'\nset ylabel 'platen force [kN]'\nunset logscale x\n"
     << plot.str() << "\n";
}

// Percent passing against sieve size (log axis), one curve per run (S2 Fig. 7).
void gradation(const std::vector<CrushRun>& runs, const fs::path& dir, std::ostringstream& gp)
{
  std::ostringstream plot;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const fs::path f = runs[i].name + "_gradation.tsv";
    const std::size_t cs = runs[i].gradation.column("size_mm", f), cp = runs[i].gradation.column("percent_passing", f);
    std::ostringstream d;
    d.precision(10);
    d << "# sieve_mm percent_passing_by_mass\n";
    for (const auto& row : runs[i].gradation.rows) d << row[cs] << ' ' << row[cp] << '\n';
    const std::string file = "data/gradation" + std::to_string(i) + ".dat";
    write_text(dir / file, d.str());
    plot << (i ? ", " : "plot ") << "'" << file << "' u 1:2" << style(i, label(runs[i])) << ", '' u 1:2 w p pt 7 ps 0.5 lc rgb '"
         << colours[i % 8] << "' notitle";
  }
  gp << "set output 'gradation.png'\nset title 'Gradation after the test (S2 Fig. 7: sieves every 2 mm)'\n"
     << "set xlabel 'sieve size [mm]'\nset ylabel 'percent passing by mass [%]'\nset logscale x\nset yrange [0:100]\n"
     << plot.str() << "\nunset logscale x\nset yrange [*:*]\n";
}

// Fig. 3: the fragment size distribution of every seed of every single-particle run.
void fig3(const std::vector<CrushRun>& runs, double bin, const fs::path& dir, std::ostringstream& gp)
{
  std::ostringstream plot;
  std::size_t k = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    for (const SeedFragments& s : fragments_by_seed(runs[i], bin)) {
      std::ostringstream d;
      d.precision(10);
      d << "# bin_centre_mm percent_of_fragments\n";
      for (std::size_t b = 0; b < s.percent.size(); ++b) d << (double(b) + 0.5) * bin << ' ' << s.percent[b] << '\n';
      const std::string file = "data/fig3_" + std::to_string(i) + "_" + std::to_string(s.run) + ".dat";
      write_text(dir / file, d.str());
      plot << (k ? ", " : "plot ") << "'" << file << "' u 1:2 w lp pt 7 ps 0.4 lw 1 lc rgb '" << colours[k % 8] << "' t "
           << gnuplot_quoted(runs[i].name + " seed " + std::to_string(s.run)) << " noenhanced";
      ++k;
    }
  }
  gp << "set output 'fig3.png'\nset title 'S2 Fig. 3: fragment sizes of the single-particle test, one curve per seed'\n"
     << "set xlabel 'fragment diameter [mm] (bins of " << fmt(bin, "%.3g") << " mm)'\nset ylabel 'fragments [%]'\n"
     << "set key top right box opaque font ',8'\n" << plot.str() << "\n";
}

std::string run_table(const std::vector<CrushRun>& runs)
{
  std::ostringstream h;
  h << "<table><tr><th>run</th><th>title</th><th>program</th><th>mode</th><th>particles at start</th>"
       "<th>broken</th><th>particles / fragments at end</th><th>peak lid stress [MPa]</th><th>lost mass</th>"
       "<th>wall time [s]</th></tr>\n";
  for (const CrushRun& r : runs) {
    const double start = r.single() ? r.number("particles") * r.number("runs", 1.0) : r.number("initial_particles");
    const double end = r.single() ? r.number("fragments") : r.number("final_particles");
    h << "<tr><td>" << html_text(r.name) << "</td><td>" << html_text(r.title) << "</td><td>" << html_text(r.program)
      << "</td><td>" << html_text(label(r).substr(r.name.size() + 2, label(r).size() - r.name.size() - 3)) << "</td><td>" << fmt(start, "%.0f") << "</td><td>"
      << fmt(r.number("broken"), "%.0f") << "</td><td>" << fmt(end, "%.0f") << "</td><td>"
      << (r.single() ? std::string("-") : fmt(1e-3 * r.number("peak_vertical_stress_kPa"), "%.3g")) << "</td><td>"
      << fmt(100.0 * r.number("lost_mass_fraction"), "%.2g") << " %</td><td>" << fmt(r.number("wall_seconds"), "%.1f")
      << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

std::string fig3_table(const std::vector<CrushRun>& runs, double bin)
{
  std::ostringstream h;
  for (const CrushRun& r : runs) {
    const std::vector<SeedFragments> seeds = fragments_by_seed(r, bin);
    if (seeds.empty()) continue;
    std::vector<double> m;
    h << "<h3>" << html_text(r.name) << ": " << seeds.size() << " seed(s)</h3>\n<table><tr><th>seed</th>"
      << "<th>fragments</th><th>mean d/D</th></tr>\n";
    for (const SeedFragments& s : seeds) {
      h << "<tr><td>" << s.run << "</td><td>" << s.fragments << "</td><td>" << fmt(s.mean_relative_size, "%.4f")
        << "</td></tr>\n";
      m.push_back(s.mean_relative_size);
    }
    const double mean = std::accumulate(m.begin(), m.end(), 0.0) / double(m.size());
    double var = 0.0;
    for (double x : m) var += (x - mean) * (x - mean);
    const double sd = m.size() > 1 ? std::sqrt(var / double(m.size() - 1)) : 0.0;
    h << "</table>\n<p>Mean d/D over the seeds " << fmt(mean, "%.4f") << ", standard deviation between seeds "
      << fmt(sd, "%.4f") << ", range " << fmt(*std::min_element(m.begin(), m.end()), "%.4f") << "-"
      << fmt(*std::max_element(m.begin(), m.end()), "%.4f") << ".";
    const int power = r.cut_point == "plain" ? 1 : r.cut_point == "squared" ? 2 : r.cut_point == "cubed" ? 3 : 0;
    if (r.breakage_mode == "cube" && power > 0)
      h << " Closed form for the " << html_text(r.cut_point) << " cut point without d<sub>M</sub> (CrushRuns.h): "
        << fmt(expected_mean_relative_size(power), "%.4f") << " (d<sub>M</sub> moves the mass of dropped children to "
        << "the smallest kept one, which raises the mean a little).";
    h << "</p>\n";
  }
  return h.str();
}

std::string build_html(const std::vector<CrushRun>& runs, const CrushReportOutcome& out, double bin)
{
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>S2 particle breakage</title><style>"
       "body{font-family:sans-serif;max-width:1200px;margin:2em auto}table{border-collapse:collapse;margin:1em 0}"
       "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}img{max-width:100%}</style></head><body>\n"
    << "<h1>S2 particle breakage: cube replacement (Zhao &amp; Chi 2022)</h1>\n"
    << "<p>Criterion F<sub>max</sub>/d<sup>2</sup> &ge; &sigma;<sub>c</sub> (S2 eq. 3); cube mode children r<sub>i</sub> = "
       "R k<sub>i</sub><sup>1/3</sup> from a random cut point (eqs. 1-2); 4-ball and 18-ball for comparison. "
       "See docs/s2-breakage.md.</p>\n<h2>Runs</h2>\n" << run_table(runs);
  if (!out.message.empty()) h << "<p><b>" << html_text(out.message) << "</b></p>\n";
  auto figure = [&](const std::string& png, const std::string& heading, const std::string& text) {
    if (std::find(out.plots.begin(), out.plots.end(), png) == out.plots.end()) return;
    h << "<h2>" << heading << "</h2>\n<p>" << text << "</p>\n";
    if (out.plots_made) h << "<img src=\"" << png << "\" alt=\"" << heading << "\">\n";
  };
  figure("stress_strain.png", "Stress-strain (uniaxial)", "Lid stress against vertical strain from seating on.");
  figure("force_approach.png", "Force-approach (single particle)",
         "Platen force against approach for every particle of the first seed; each curve ends at its crushing force.");
  figure("gradation.png", "Gradation (S2 Fig. 7)",
         "Percent passing by mass against sieve size; S2: the cube mode continuous, the 4- and 18-ball modes stepped.");
  figure("fig3.png", "Fragment sizes over seeds (S2 Fig. 3)",
         "Percent of each seed's fragments by number per size bin: the spread is the randomness of the cut point.");
  const std::string seeds = fig3_table(runs, bin);
  if (!seeds.empty()) h << "<h2>Fig. 3 per seed</h2>\n" << seeds;
  bool roses = false;
  for (const CrushRun& r : runs)
    for (const fs::path& svg : r.roses) {
      if (!roses) h << "<h2>Contact-number and mean-force roses (S2 Figs. 8-11)</h2>\n";
      roses = true;
      h << "<h3>" << html_text(svg.filename().string()) << "</h3>\n<img src=\"" << html_text(svg.filename().string())
        << "\" alt=\"" << html_text(svg.filename().string()) << "\">\n";
    }
  h << "</body></html>\n";
  return h.str();
}

/// The bin of Fig. 3: the single runs' gradation spacing (their sieve step), 1 mm without.
double fig3_bin(const std::vector<CrushRun>& runs)
{
  for (const CrushRun& r : runs)
    if (r.single() && r.gradation.rows.size() > 1) return r.gradation.rows[1][0] - r.gradation.rows[0][0];
  return 1.0;
}

}  // namespace

CrushReportOutcome write_crush_report(const std::vector<CrushRun>& runs, const fs::path& dir, const std::string& gnuplot)
{
  if (runs.empty()) throw std::invalid_argument("write_crush_report: no runs");
  CrushReportOutcome out;
  out.dir = fs::absolute(dir);
  const bool any_single = std::any_of(runs.begin(), runs.end(), [](const CrushRun& r) { return r.single(); });
  const bool any_uniaxial = std::any_of(runs.begin(), runs.end(), [](const CrushRun& r) { return !r.single(); });
  const double bin = fig3_bin(runs);
  replace_folder_atomically(dir, [&](const fs::path& tmp) {
    fs::create_directories(tmp / "data");
    std::ostringstream gp;
    gp << "# Generated by geocomp crush: run `gnuplot report.gp` in this folder.\n"
       << "set terminal pngcairo size 1000,650 font 'sans,10'\nset grid lc rgb '#dddddd'\nset key top left box opaque font ',8'\n";
    if (any_uniaxial) {
      stress_strain(runs, tmp, gp);
      out.plots.push_back("stress_strain.png");
    }
    if (any_single) {
      force_approach(runs, tmp, gp);
      fig3(runs, bin, tmp, gp);
      out.plots.push_back("force_approach.png");
      out.plots.push_back("fig3.png");
    }
    gp << "set key top left box opaque font ',8'\n";
    gradation(runs, tmp, gp);
    out.plots.push_back("gradation.png");
    write_text(tmp / "report.gp", gp.str());
    for (const CrushRun& r : runs)
      for (const fs::path& svg : r.roses) fs::copy_file(svg, tmp / svg.filename(), fs::copy_options::overwrite_existing);
    if (!program_available(gnuplot)) {
      out.message = "gnuplot not found ('" + gnuplot + "'): plots skipped; run `gnuplot report.gp` in the report folder";
    } else {
      const SubprocessResult run = run_subprocess({gnuplot, "report.gp"}, {tmp, tmp / "gnuplot.log", tmp / "gnuplot.log"});
      out.plots_made = run.succeeded() && std::all_of(out.plots.begin(), out.plots.end(), [&](const std::string& p) {
                         return fs::exists(tmp / p);
                       });
      if (!out.plots_made) out.message = "gnuplot failed (exit " + std::to_string(run.exit_code) + "); see gnuplot.log";
    }
    write_text(tmp / "index.html", build_html(runs, out, bin));
  });
  return out;
}

}  // namespace geocomp::compare
