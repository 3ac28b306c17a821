#include "continuum/dynamics/RateSweepOutput.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace geocomp::dynamics {

namespace {
std::ofstream open(const std::string &path)
{
  std::ofstream out(path);
  if (!out)
    throw std::runtime_error("cannot write " + path);
  return out;
}
const char *fit_name(LoadingMode mode) { return mode == LoadingMode::compression ? "S1 eq. (14)" : "S1 eq. (15)"; }
} // namespace

void write_rate_sweep_tsv(const std::string &path, const RateSweepSetup &setup, const std::vector<RateSweepRow> &rows)
{
  std::ofstream out = open(path);
  out << "# " << setup.title << "\n# material " << setup.material.name << ", " << kinetic::to_string(setup.mode)
      << ", specimen " << setup.geometry.width * 1e3 << " x " << setup.geometry.height * 1e3 << " mm, "
      << setup.geometry.cells_x << " x " << setup.geometry.cells_y << " Q1 cells, plane stress\n"
      << "# normalized = peak end stress / static strength; s1_fit = " << fit_name(setup.mode)
      << "; point = homogeneous point without inertia\n"
      << "kinetic\tstrain_rate\tnormalized\ts1_fit\trelative_error\tpoint_normalized\tpeak_stress_Pa\t"
         "strain_at_peak\tdensity_scale\ttime_step_s\tsteps\tfractured_points\tpoints\n";
  out.precision(6);
  for (const auto &r : rows)
    out << (r.kinetic ? "on" : "off") << "\t" << r.strain_rate << "\t" << r.normalized_strength << "\t" << r.s1_fit
        << "\t" << r.relative_error() << "\t" << r.point_normalized_strength << "\t" << r.run.peak_stress << "\t"
        << r.run.strain_at_peak << "\t" << r.run.density_scale << "\t" << r.run.time_step << "\t" << r.run.steps
        << "\t" << r.run.fractured_points << "\t" << r.run.points << "\n";
}

void write_rate_sweep_svg(const std::string &path, const RateSweepSetup &setup, const std::vector<RateSweepRow> &rows)
{
  if (rows.empty())
    throw std::invalid_argument("write_rate_sweep_svg: no rows");
  double x0 = 1e300, x1 = -1e300, y1 = 1.0;
  for (const auto &r : rows) {
    x0 = std::min(x0, std::floor(std::log10(r.strain_rate)));
    x1 = std::max(x1, std::ceil(std::log10(r.strain_rate)));
    y1 = std::max({y1, r.normalized_strength, r.s1_fit});
  }
  if (x1 <= x0)
    x1 = x0 + 1;
  const double y0 = 0.0;
  y1 = std::ceil(y1 * 1.1 * 2.0) / 2.0;
  const double W = 640, H = 440, L = 70, R = 20, T = 40, B = 60;
  auto px = [&](double rate) { return L + (std::log10(rate) - x0) / (x1 - x0) * (W - L - R); };
  auto py = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  std::ofstream out = open(path);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">" << setup.title << "</text>\n";
  // axes and ticks
  out << "<polyline fill=\"none\" stroke=\"black\" points=\"" << L << "," << T << " " << L << "," << H - B << " "
      << W - R << "," << H - B << "\"/>\n";
  for (int e = static_cast<int>(x0); e <= static_cast<int>(x1); ++e) {
    const double x = px(std::pow(10.0, e));
    out << "<line x1=\"" << x << "\" y1=\"" << H - B << "\" x2=\"" << x << "\" y2=\"" << T
        << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << H - B + 18 << "\" text-anchor=\"middle\">1e" << e
        << "</text>\n";
  }
  const double ystep = y1 > 4 ? 1.0 : 0.5;
  for (double y = y0; y <= y1 + 1e-9; y += ystep)
    out << "<line x1=\"" << L << "\" y1=\"" << py(y) << "\" x2=\"" << W - R << "\" y2=\"" << py(y)
        << "\" stroke=\"#ddd\"/><text x=\"" << L - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">" << y
        << "</text>\n";
  out << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 18 << "\" text-anchor=\"middle\">strain rate [1/s]</text>\n"
      << "<text transform=\"translate(18," << (T + H - B) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
      << "peak stress / static strength</text>\n";
  // S1's fit
  out << "<polyline fill=\"none\" stroke=\"black\" stroke-dasharray=\"6,4\" points=\"";
  for (int i = 0; i <= 120; ++i) {
    const double rate = std::pow(10.0, x0 + (x1 - x0) * i / 120.0);
    out << px(rate) << "," << py(s1_strength_factor(setup.mode, rate)) << " ";
  }
  out << "\"/>\n";
  for (const auto &r : rows) {
    const double x = px(r.strain_rate), y = py(r.normalized_strength);
    if (r.kinetic)
      out << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" fill=\"#c0392b\"/>\n";
    else
      out << "<rect x=\"" << x - 5 << "\" y=\"" << y - 5 << "\" width=\"10\" height=\"10\" fill=\"none\" "
          << "stroke=\"#2c3e50\" stroke-width=\"1.5\"/>\n";
  }
  // legend
  const double lx = L + 15, ly = T + 15;
  out << "<line x1=\"" << lx << "\" y1=\"" << ly << "\" x2=\"" << lx + 30 << "\" y2=\"" << ly
      << "\" stroke=\"black\" stroke-dasharray=\"6,4\"/><text x=\"" << lx + 38 << "\" y=\"" << ly + 4 << "\">"
      << fit_name(setup.mode) << "</text>\n"
      << "<circle cx=\"" << lx + 15 << "\" cy=\"" << ly + 20 << "\" r=\"5\" fill=\"#c0392b\"/><text x=\"" << lx + 38
      << "\" y=\"" << ly + 24 << "\">kinetic model</text>\n"
      << "<rect x=\"" << lx + 10 << "\" y=\"" << ly + 35 << "\" width=\"10\" height=\"10\" fill=\"none\" "
      << "stroke=\"#2c3e50\" stroke-width=\"1.5\"/><text x=\"" << lx + 38 << "\" y=\"" << ly + 44
      << "\">kinetic extension off (inertia only)</text>\n</svg>\n";
}

void write_rate_sweep_gnuplot(const std::string &path, const std::string &tsv_name, const RateSweepSetup &setup)
{
  std::ofstream out = open(path);
  const bool c = setup.mode == LoadingMode::compression;
  out << "# gnuplot " << path << "  (run from its folder)\nset terminal svg size 640,440\nset output '"
      << tsv_name.substr(0, tsv_name.rfind('.')) << "-gnuplot.svg'\nset logscale x\nset format x '1e%L'\n"
      << "set xlabel 'strain rate [1/s]'\nset ylabel 'peak stress / static strength'\nset key top left\n"
      << "set title '" << setup.title << "'\n"
      << (c ? "f(x) = 1 + 0.238 * x**0.348\n" : "f(x) = 1 + 0.093 * x**0.617\n")
      << "plot [1e-3:1e3] f(x) dt 2 lc 'black' title '" << fit_name(setup.mode) << "', \\\n"
      << "  '" << tsv_name << "' using (strcol(1) eq 'on' ? $2 : 1/0):3 skip 4 with points pt 7 title 'kinetic model', \\\n"
      << "  '" << tsv_name << "' using (strcol(1) eq 'off' ? $2 : 1/0):3 skip 4 with points pt 4 title 'kinetic off "
         "(inertia only)'\n";
}

} // namespace geocomp::dynamics
