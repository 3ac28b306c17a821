#include "compare/StateMapsReport.h"
#include "compare/GnuplotString.h"
#include "compare/HtmlString.h"
#include "compare/JsonString.h"
#include "compare/Report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace geocomp::compare {

namespace fs = std::filesystem;

namespace {
std::string percent(double fraction) { return format_number(fraction * 100.0) + " %"; }

std::string state_heading(const NamedState &s)
{
  return s.name + " (" + s.definition + (s.found ? ") at " + percent(s.strain) : ")");
}

/// The x and z ranges of every panel of a row (their points and markers), so that the panels
/// frame the same extent.
std::string row_extent(const MapRow &row)
{
  double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  for (const MapPanel &p : row.panels)
    for (std::size_t i = 0; p.present && i < p.x.size(); ++i) {
      x0 = std::min(x0, p.x[i] - p.marker), x1 = std::max(x1, p.x[i] + p.marker);
      z0 = std::min(z0, p.z[i] - p.half_height()), z1 = std::max(z1, p.z[i] + p.half_height());
    }
  if (!(x0 < x1 && z0 < z1))
    return "";
  return "set xrange [" + format_number(x0) + ":" + format_number(x1) + "]\nset yrange [" + format_number(z0) + ":" +
         format_number(z1) + "]\n";
}

/// One panel's gnuplot commands: particles as discs of their radius, FE points as tiles.
std::string panel_script(const NamedState &state, const MapRow &row, const MapPanel &p, const std::string &name)
{
  std::ostringstream g;
  const std::string what = row.quantity == "gamma (local)" ? "local {/Symbol g} (in-plane)" : row.quantity + " from the box centre";
  g << "\nset output '" << name << ".png'\nset title "
    << gnuplot_quoted(p.engine + ", " + state.name + ", strain " + percent(p.strain) + ": " + what)
    << "\nset size ratio -1\nunset key\nset xlabel 'x [m]'\nset ylabel 'z [m]'\nset cblabel "
    << gnuplot_quoted(row.quantity + " [" + row.unit + "]")
    << "\nset palette defined (0 '#313695', 1 '#74add1', 2 '#ffffbf', 3 '#f46d43', 4 '#a50026')\n"
    << "set cbrange [" << format_number(row.range.low) << ":" << format_number(row.range.high) << "]\n"
    << "set style fill solid noborder\n" << row_extent(row);
  if (p.tiles)
    g << "plot 'data/" << name << ".dat' using 1:2:(" << format_number(p.marker) << "):("
      << format_number(p.marker_z) << "):3 with boxxyerror lc palette\n";
  else
    g << "plot 'data/" << name << ".dat' using 1:2:(" << format_number(p.marker) << "):3 with circles lc palette\n";
  g << "set size noratio\nunset cblabel\nset autoscale\nset style fill empty\nset key top left box opaque\n";
  return g.str();
}

void write_panel_data(const MapRow &row, const MapPanel &p, const fs::path &file)
{
  std::ofstream d(file);
  d << "# x[m] z[m] " << row.quantity << "[" << row.unit << "]; " << p.engine << " at strain " << percent(p.strain)
    << "\n";
  d.precision(9);
  for (std::size_t i = 0; i < p.v.size(); ++i)
    if (std::isfinite(p.v[i]))
      d << p.x[i] << ' ' << p.z[i] << ' ' << p.v[i] << '\n';
  if (!d)
    throw std::runtime_error("cannot write " + file.string());
}

std::string panel_html(const MapPanel &p, const std::string &png, const std::vector<std::string> &made)
{
  if (!p.present)
    return "<div class=\"panel missing\"><p class=\"note\">" + html_text(p.missing) + "</p></div>";
  if (std::find(made.begin(), made.end(), png) == made.end())
    return "<div class=\"panel missing\"><p class=\"note\">" + html_text(p.engine) +
           ": map not drawn (no plots; see the note above)</p></div>";
  return "<div class=\"panel\"><a href=\"" + html_text(png) + "\"><img src=\"" + html_text(png) + "\" alt=\"" +
         html_text(png) + "\"></a></div>";
}
} // namespace

std::string state_map_png(std::size_t s, std::size_t r, const std::string &engine)
{
  std::string name = "state" + std::to_string(s) + "_" + std::to_string(r) + "_";
  bool dash = false;
  for (char c : engine)
    if (std::isalnum(static_cast<unsigned char>(c))) {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      dash = false;
    } else if (!dash && name.back() != '_') {
      name += '-';
      dash = true;
    }
  if (dash)
    name.pop_back();
  return name;
}

std::string state_maps_script(const std::vector<StateMaps> &maps, const fs::path &dir, std::vector<std::string> &pngs)
{
  std::ostringstream g;
  for (std::size_t s = 0; s < maps.size(); ++s)
    for (std::size_t r = 0; r < maps[s].rows.size(); ++r) {
      const MapRow &row = maps[s].rows[r];
      for (const MapPanel &p : row.panels) {
        if (!p.present)
          continue;
        const std::string name = state_map_png(s, r, p.engine);
        write_panel_data(row, p, dir / "data" / (name + ".dat"));
        g << panel_script(maps[s].state, row, p, name);
        pngs.push_back(name + ".png");
      }
    }
  return g.str();
}

std::string state_maps_html(const std::vector<StateMaps> &maps, const std::string &note,
                            const std::vector<std::string> &made)
{
  if (maps.empty())
    return "";
  std::ostringstream h;
  h << "<h2 id=\"named-states\">Maps at named states</h2>\n<p>" << html_text(note) << "</p>\n";
  for (std::size_t s = 0; s < maps.size(); ++s) {
    const StateMaps &m = maps[s];
    h << "<h3 class=\"state\" data-state=\"" << html_text(m.state.name) << "\">" << html_text(state_heading(m.state))
      << "</h3>\n";
    if (!m.state.found) {
      h << "<p class=\"note\">" << html_text(m.state.name) << ": not found, no maps: " << html_text(m.state.missing)
        << ".</p>\n";
      continue;
    }
    for (std::size_t r = 0; r < m.rows.size(); ++r) {
      const MapRow &row = m.rows[r];
      h << "<div class=\"maprow\"><p>" << html_text(row.quantity) << " [" << html_text(row.unit)
        << "], one colour scale [" << format_number(row.range.low) << ", " << format_number(row.range.high)
        << "]</p>\n";
      for (const MapPanel &p : row.panels)
        h << panel_html(p, state_map_png(s, r, p.engine) + ".png", made);
      h << "</div>\n";
    }
  }
  return h.str();
}

std::string state_maps_json(const std::vector<StateMaps> &maps)
{
  std::ostringstream j;
  j << "[";
  for (std::size_t s = 0; s < maps.size(); ++s) {
    const StateMaps &m = maps[s];
    j << (s ? "," : "") << "\n    {\"name\": " << json_string(m.state.name)
      << ", \"definition\": " << json_string(m.state.definition) << ", \"found\": " << (m.state.found ? "true" : "false")
      << ", \"strain_pct\": " << format_number(m.state.strain * 100) << ", \"missing\": " << json_string(m.state.missing)
      << ", \"panels\": [";
    if (!m.rows.empty()) // every row shows the same recorded states
      for (std::size_t e = 0; e < m.rows.front().panels.size(); ++e) {
        const MapPanel &p = m.rows.front().panels[e];
        j << (e ? ", " : "") << "{\"engine\": " << json_string(p.engine) << ", \"present\": "
          << (p.present ? "true" : "false") << ", \"strain_pct\": " << format_number(p.strain * 100)
          << ", \"missing\": " << json_string(p.missing) << "}";
      }
    j << "]}";
  }
  j << (maps.empty() ? "]" : "\n  ]");
  return j.str();
}

} // namespace geocomp::compare
