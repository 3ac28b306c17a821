#include "dem/program/ContactPolarOutput.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace geocomp::dem {

namespace {
using CPD = ContactPolarDistribution;
constexpr CPD::Plane kPlanes[] = {CPD::horizontal, CPD::vertical};
constexpr CPD::Variant kVariants[] = {CPD::all, CPD::mechanical};

std::ofstream open(const std::string& path)
{
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

void close(std::ofstream& out, const std::string& path)
{
  out.flush();
  if (!out) throw std::runtime_error("write failed: " + path);
}

std::string xml_escaped(const std::string& text)
{
  std::string s;
  for (char c : text) s += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
  return s;
}

/// The smallest of 1, 2, 2.5, 5 x 10^k not below v (v > 0).
double nice_ceil(double v)
{
  if (!(v > 0.0)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= v * (1.0 - 1e-12)) return m * p;
  return 10.0 * p;
}

/// One polar panel centred at (cx, cy) with outer radius R.
void panel(std::ostream& out, double cx, double cy, double R, const std::string& title, const std::string& unit,
           CPD::Plane plane, const CPD& d, bool force)
{
  auto value = [&](const PolarRose& r, std::size_t k) { return force ? r.mean_force(k) : r.contacts[k]; };
  double vmax = 0.0;
  for (CPD::Variant v : kVariants)
    for (std::size_t k = 0; k < std::size_t(d.bins()); ++k) vmax = std::max(vmax, value(d.rose(plane, v), k));
  const double scale = nice_ceil(vmax);
  // Horizontal: 0 deg to the right, counter-clockwise. Vertical: 0 deg (z) up, clockwise.
  auto point = [&](double angle_deg, double r) {
    const double a = angle_deg * M_PI / 180.0;
    return plane == CPD::horizontal ? std::pair{cx + r * std::cos(a), cy - r * std::sin(a)}
                                    : std::pair{cx + r * std::sin(a), cy - r * std::cos(a)};
  };
  out << "<text x=\"" << cx << "\" y=\"" << cy - R - 34 << "\" text-anchor=\"middle\" font-size=\"13\">" << title
      << "</text>\n";
  for (int ring = 1; ring <= 4; ++ring)
    out << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << R * ring / 4.0 << "\" fill=\"none\" stroke=\""
        << (ring == 4 ? "#999" : "#ddd") << "\"/>\n";
  for (int a = 0; a < 360; a += 30) {
    const auto [x, y] = point(a, R);
    const auto [lx, ly] = point(a, R + 14);
    out << "<line x1=\"" << cx << "\" y1=\"" << cy << "\" x2=\"" << x << "\" y2=\"" << y << "\" stroke=\"#ddd\"/>"
        << "<text x=\"" << lx << "\" y=\"" << ly + 4 << "\" text-anchor=\"middle\" font-size=\"10\">" << a
        << "</text>\n";
  }
  out << "<text x=\"" << cx + 4 << "\" y=\"" << cy - R + 12 << "\" font-size=\"10\" fill=\"#555\">" << scale << ' '
      << unit << "</text>\n";
  for (CPD::Variant v : kVariants) {
    const PolarRose& r = d.rose(plane, v);
    out << "<polygon fill=\"none\" stroke=\"" << (v == CPD::all ? "#c0392b\" stroke-width=\"1.8\""
                                                                  : "#2c3e50\" stroke-width=\"1.4\" stroke-dasharray=\"5,3\"")
        << " points=\"";
    for (std::size_t k = 0; k < r.bins(); ++k) {
      const auto [x, y] = point(r.angle_deg(k), R * value(r, k) / scale);
      out << x << ',' << y << ' ';
    }
    out << "\"/>\n";
  }
}
}  // namespace

void write_polar_tsv(const std::string& path, const std::vector<PolarState>& states)
{
  std::ofstream out = open(path);
  out << "state\tplane\tvariant\tangle_deg\tcontacts\tmean_force_N\n" << std::setprecision(10);
  for (const auto& [state, d] : states)
    for (CPD::Plane p : kPlanes)
      for (CPD::Variant v : kVariants) {
        const PolarRose& r = d.rose(p, v);
        for (std::size_t k = 0; k < r.bins(); ++k)
          out << state << '\t' << to_string(p) << '\t' << to_string(v) << '\t' << r.angle_deg(k) << '\t'
              << r.contacts[k] << '\t' << r.mean_force(k) << '\n';
      }
  close(out, path);
}

void write_polar_summary_tsv(const std::string& path, const std::vector<PolarState>& states)
{
  std::ofstream out = open(path);
  out << "state\tplane\tvariant\tcontacts\tsingle_contact_particles\tfree_particles\ta_c\ta_s\ta\ta_f\t"
         "axial_contacts\tlateral_contacts\taxial_mean_force_N\tlateral_mean_force_N\tmean_force_N\n"
      << std::setprecision(6);
  for (const auto& [state, d] : states)
    for (CPD::Plane p : kPlanes)
      for (CPD::Variant v : kVariants) {
        const PolarRose& r = d.rose(p, v);
        const PolarRose::Sector axial = r.sector(0.0, kPolarSectorHalfWidth);
        const PolarRose::Sector lateral = r.sector(90.0, kPolarSectorHalfWidth);
        const PolarRose::Sector whole = r.sector(0.0, 180.0);
        out << state << '\t' << to_string(p) << '\t' << to_string(v) << '\t' << d.contacts(v) << '\t'
            << d.single_contact_particles() << '\t' << d.free_particles() << '\t' << r.contact_cos2() << '\t'
            << r.contact_sin2() << '\t' << r.contact_anisotropy() << '\t' << r.force_cos2() << '\t'
            << axial.contacts << '\t' << lateral.contacts << '\t' << axial.mean_force << '\t'
            << lateral.mean_force << '\t' << whole.mean_force << '\n';
      }
  close(out, path);
}

void write_polar_svg(const std::string& path, const std::string& title, const ContactPolarDistribution& d)
{
  const double W = 760, H = 820, R = 130;
  std::ofstream out = open(path);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"" << W / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"14\">" << xml_escaped(title) << "</text>\n";
  const double c1 = W / 4, c2 = 3 * W / 4, r1 = 230, r2 = 600;
  panel(out, c1, r1, R, "contact number, horizontal plane x-y (S2 Fig. 8)", "", CPD::horizontal, d, false);
  panel(out, c2, r1, R, "contact number, vertical planes x-z, y-z (S2 Fig. 9)", "", CPD::vertical, d, false);
  panel(out, c1, r2, R, "mean normal force, horizontal (S2 Fig. 10)", "N", CPD::horizontal, d, true);
  panel(out, c2, r2, R, "mean normal force, vertical (S2 Fig. 11)", "N", CPD::vertical, d, true);
  const double ly = H - 24;
  out << "<line x1=\"" << W / 2 - 250 << "\" y1=\"" << ly << "\" x2=\"" << W / 2 - 220 << "\" y2=\"" << ly
      << "\" stroke=\"#c0392b\" stroke-width=\"1.8\"/><text x=\"" << W / 2 - 212 << "\" y=\"" << ly + 4
      << "\">all contacts (" << d.contacts(CPD::all) << ")</text>\n"
      << "<line x1=\"" << W / 2 + 10 << "\" y1=\"" << ly << "\" x2=\"" << W / 2 + 40 << "\" y2=\"" << ly
      << "\" stroke=\"#2c3e50\" stroke-width=\"1.4\" stroke-dasharray=\"5,3\"/><text x=\"" << W / 2 + 48
      << "\" y=\"" << ly + 4 << "\">without particles of 0 or 1 contacts (" << d.contacts(CPD::mechanical)
      << ")</text>\n</svg>\n";
  close(out, path);
}

}  // namespace geocomp::dem
