// The report folder: every number in the HTML tables is the one in metrics.json (parsed
// with a strict little JSON reader), plots exist as PNGs when gnuplot is there, and the
// folder appears whole (atomic) with or without gnuplot.
#include "compare/Report.h"
#include "compare/StateMapsReport.h"
#include "common/Subprocess.h"
#include "Synthetic.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

using namespace geocomp;
using namespace geocomp::compare;
namespace fs = std::filesystem;

namespace {

/// Strict JSON reader; numbers keep their source text so equality is textual.
struct Json {
  enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
  std::string text; ///< number text or string value
  std::vector<Json> items;
  std::map<std::string, Json> members;
};

class JsonReader {
public:
  explicit JsonReader(const std::string &s) : s_(s) {}
  Json parse()
  {
    Json j = value();
    ws();
    if (i_ != s_.size())
      throw std::runtime_error("trailing text at " + std::to_string(i_));
    return j;
  }

private:
  void ws()
  {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_])))
      ++i_;
  }
  void expect(char c)
  {
    ws();
    if (i_ >= s_.size() || s_[i_] != c)
      throw std::runtime_error(std::string("expected '") + c + "' at " + std::to_string(i_));
    ++i_;
  }
  std::string string()
  {
    expect('"');
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] == '\\') {
        ++i_;
        const char c = s_.at(i_);
        if (c == 'u') {
          out += static_cast<char>(std::stoi(s_.substr(i_ + 1, 4), nullptr, 16));
          i_ += 4;
        } else
          out += c == 'n' ? '\n' : c;
      } else {
        if (static_cast<unsigned char>(s_[i_]) < 0x20)
          throw std::runtime_error("control character in string");
        out += s_[i_];
      }
      ++i_;
    }
    expect('"');
    return out;
  }
  Json value()
  {
    ws();
    Json j;
    if (i_ >= s_.size())
      throw std::runtime_error("unexpected end");
    const char c = s_[i_];
    if (c == '{') {
      j.kind = Json::Object;
      ++i_;
      ws();
      if (s_[i_] == '}') {
        ++i_;
        return j;
      }
      for (;;) {
        const std::string k = string();
        expect(':');
        if (!j.members.emplace(k, value()).second)
          throw std::runtime_error("duplicate key " + k);
        ws();
        if (s_[i_] == ',') {
          ++i_;
          continue;
        }
        expect('}');
        return j;
      }
    }
    if (c == '[') {
      j.kind = Json::Array;
      ++i_;
      ws();
      if (s_[i_] == ']') {
        ++i_;
        return j;
      }
      for (;;) {
        j.items.push_back(value());
        ws();
        if (s_[i_] == ',') {
          ++i_;
          continue;
        }
        expect(']');
        return j;
      }
    }
    if (c == '"') {
      j.kind = Json::String;
      j.text = string();
      return j;
    }
    for (const char *lit : {"null", "true", "false"})
      if (s_.compare(i_, std::strlen(lit), lit) == 0) {
        i_ += std::strlen(lit);
        j.kind = lit[0] == 'n' ? Json::Null : Json::Bool;
        j.text = lit;
        return j;
      }
    static const std::regex number(R"(^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
    std::smatch m;
    const std::string rest = s_.substr(i_, 40);
    if (!std::regex_search(rest, m, number))
      throw std::runtime_error("bad value at " + std::to_string(i_));
    j.kind = Json::Number;
    j.text = m.str();
    i_ += j.text.size();
    return j;
  }
  const std::string &s_;
  std::size_t i_ = 0;
};

const Json *lookup(const Json &root, const std::string &path)
{
  const Json *j = &root;
  std::stringstream ss(path);
  std::string token;
  while (std::getline(ss, token, '/')) {
    std::string t; // RFC 6901 unescape
    for (std::size_t i = 0; i < token.size(); ++i)
      if (token[i] == '~' && i + 1 < token.size()) {
        t += token[i + 1] == '1' ? '/' : '~';
        ++i;
      } else
        t += token[i];
    if (j->kind == Json::Object) {
      auto it = j->members.find(t);
      if (it == j->members.end())
        return nullptr;
      j = &it->second;
    } else if (j->kind == Json::Array) {
      const std::size_t k = std::stoul(t);
      if (k >= j->items.size())
        return nullptr;
      j = &j->items[k];
    } else
      return nullptr;
  }
  return j;
}

std::string read(const fs::path &p)
{
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Two responses (a noisy "DEM" with branches, a smooth "continuum" with a softer
/// backbone), their metrics, a verdict, a map and calibrated parameters.
ReportInput sample_input()
{
  using geocomp::compare::testing::Backbone;
  using geocomp::compare::testing::shear_response;
  Backbone dem, fe;
  fe.tau_p = 4.6e6;
  fe.H = 60e6;
  ReportInput in;
  in.case_name = "cases/demo.prm";
  in.responses.push_back({"DEM", shear_response(dem, 2e-4, 20e3, {0.004, 0.012, 0.02, 0.03}, dem.E)});
  in.responses.push_back({"continuum/FE", shear_response(fe, 2e-4, 0.0, {0.004, 0.012, 0.02}, fe.E)});
  MetricOptions o;
  o.kind = CurveKind::ShearIsochoric;
  for (const auto &r : in.responses)
    in.metrics.push_back({r.label, compute_metrics(r.response, o)});
  in.verdict = rudnicki_rice_verdict({"Rudnicki-Rice", true, 0.020, 56.48, true, ""},
                                     {{"FE acoustic tensor", true, 0.0215, 55.2, true, ""},
                                      {"DEM", true, 0.031, 61.0, true, ""}});
  in.calibrated_parameters = {{"E", "512 MPa"}, {"phi", "38.2 deg"}};
  return in;
}

fs::path scratch(const std::string &name)
{
  const fs::path base =
    fs::temp_directory_path() / ("geocomp_compare_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(base);
  fs::create_directories(base);
  return base / name;
}

/// Checks every data-path cell of the HTML against metrics.json; returns the cell count.
int check_html_against_json(const fs::path &dir)
{
  const std::string html = read(dir / "index.html");
  const std::string json = read(dir / "metrics.json");
  Json root;
  EXPECT_NO_THROW(root = JsonReader(json).parse()) << json;
  static const std::regex cell(R"re(<td class="num" data-path="([^"]*)">([^<]*)</td>)re");
  int cells = 0;
  for (std::sregex_iterator it(html.begin(), html.end(), cell), end; it != end; ++it) {
    std::string path = (*it)[1];
    for (std::size_t p; (p = path.find("&quot;")) != std::string::npos;)
      path.replace(p, 6, "\"");
    for (std::size_t p; (p = path.find("&amp;")) != std::string::npos;)
      path.replace(p, 5, "&");
    const std::string shown = (*it)[2];
    const Json *j = lookup(root, path);
    ++cells;
    if (!j) {
      ADD_FAILURE() << "no JSON value at " << path;
      continue;
    }
    if (shown == "&mdash;")
      EXPECT_EQ(j->kind, Json::Null) << path;
    else {
      EXPECT_EQ(j->kind, Json::Number) << path;
      EXPECT_EQ(j->text, shown) << path;
    }
  }
  return cells;
}
} // namespace

TEST(Report, HtmlNumbersEqualMetricsJsonAndPlotsArePngs)
{
  if (!geocomp::program_available("gnuplot"))
    GTEST_SKIP() << "gnuplot not installed";
  const ReportInput in = sample_input();
  const fs::path dir = scratch("report");
  const ReportOutcome out = write_report(in, dir);
  EXPECT_TRUE(out.plots_made) << out.message;
  EXPECT_EQ(out.plots.size(), 3u); // stress-strain, volumetric, stress path
  for (const auto &p : out.plots) {
    const std::string bytes = read(dir / p);
    ASSERT_GT(bytes.size(), 1000u) << p;
    EXPECT_EQ(bytes.substr(1, 3), "PNG") << p;
    EXPECT_NE(read(dir / "index.html").find("src=\"" + p + "\""), std::string::npos);
  }
  // 11 metrics x (2 labels + 1 difference) + predicted (2) + 2 rows x 5 + the branch table's
  // start, start stress and residual of 4 DEM and 3 FE branches.
  EXPECT_EQ(check_html_against_json(dir), 11 * 3 + 2 + 2 * 5 + 3 * (4 + 3));
  // Spot-check that the JSON holds the metric itself, not just a consistent copy.
  const Json root = JsonReader(read(dir / "metrics.json")).parse();
  const Json *peak = lookup(root, "metrics/continuum~1FE/peak_stress_MPa");
  ASSERT_NE(peak, nullptr);
  EXPECT_EQ(peak->text, format_number(in.metrics[1].metrics.peak_stress * 1e-6));
  EXPECT_NEAR(std::stod(peak->text), 4.6, 0.02);
  const Json *diff = lookup(root, "differences/continuum~1FE - DEM/peak_stress_MPa");
  ASSERT_NE(diff, nullptr);
  EXPECT_NEAR(std::stod(diff->text), -0.4, 0.05);
  EXPECT_EQ(lookup(root, "calibrated_parameters/phi")->text, "38.2 deg");
  // Each onset found is a labelled vertical line on the stress-strain plot, at its strain.
  const std::string gp = read(dir / "report.gp");
  for (const auto *o : {&in.verdict->predicted, &in.verdict->rows[0].onset, &in.verdict->rows[1].onset})
    if (o->found)
      EXPECT_NE(gp.find("from " + format_number(o->strain * 100) + ", graph 0"), std::string::npos) << o->source;
  EXPECT_NE(gp.find("'onset: " + in.verdict->predicted.source + "'"), std::string::npos);
  if (!std::getenv("GEOCOMP_TEST_KEEP")) // set it to look at the report
    fs::remove_all(dir.parent_path());
  else
    std::cout << "report kept in " << dir << "\n";
}

TEST(Report, DifferencesAreShownToTheDigitsOfTheValuesNotAsRoundOff)
{
  EXPECT_EQ(shown_difference(1.0 + 3e-15, 1.0), 0.0); // equal to the shown digits
  EXPECT_EQ(format_number(shown_difference(0.1 + 0.2, 0.3)), "0");
  EXPECT_EQ(format_number(shown_difference(4.6, 5.0)), "-0.4");
  EXPECT_EQ(format_number(shown_difference(1234567.0, 1234560.0)), "10"); // shown 1.23457e+06, 1.23456e+06
  EXPECT_TRUE(std::isnan(shown_difference(NAN, 1.0)));
}

namespace {
/// Headless chromium on `page` (a file); its standard output (the DOM with --dump-dom) and
/// standard error (the console with --enable-logging) in files of `dir`.
SubprocessResult chromium(const std::vector<std::string> &flags, const fs::path &page, const fs::path &dir)
{
  std::vector<std::string> argv{"chromium", "--headless", "--no-sandbox", "--disable-gpu",
                                "--allow-file-access-from-files", "--virtual-time-budget=5000"};
  argv.insert(argv.end(), flags.begin(), flags.end());
  argv.push_back("file://" + fs::absolute(page).string());
  SubprocessOptions o;
  o.stdout_file = dir / "chromium.out";
  o.stderr_file = dir / "chromium.err";
  o.timeout_seconds = 120;
  return run_subprocess(argv, o);
}

/// What report-check.html found in `report` ("images N, links M: ok" or the problems).
std::string browser_check(const fs::path &report, const fs::path &work)
{
  fs::copy_file(fs::path(std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : ".") /
                  "tests/compare/report-check.html",
                report / "geocomp-check.html", fs::copy_options::overwrite_existing);
  const SubprocessResult r = chromium({"--dump-dom"}, report / "geocomp-check.html", work);
  fs::remove(report / "geocomp-check.html");
  EXPECT_TRUE(r.succeeded()) << r.error << " exit " << r.exit_code;
  const std::string dom = read(work / "chromium.out");
  const std::size_t at = dom.find("<pre id=\"result\">");
  return at == std::string::npos ? "no result: " + dom.substr(0, 200) : dom.substr(at + 17, dom.find('<', at + 17) - at - 17);
}

/// The uncaught script errors chromium's console printed while loading `page`.
std::string script_errors(const fs::path &page, const fs::path &work)
{
  chromium({"--enable-logging=stderr", "--v=0", "--dump-dom"}, page, work);
  std::istringstream log(read(work / "chromium.err"));
  std::string errors;
  for (std::string line; std::getline(log, line);)
    if (line.find("CONSOLE") != std::string::npos && line.find("Uncaught") != std::string::npos)
      errors += line + "\n";
  return errors;
}
} // namespace

/// The cbrange of the panel that writes `png` in a gnuplot script ("" when it has none).
std::string panel_range(const std::string &gp, const std::string &png)
{
  const std::size_t at = gp.find("set output '" + png + "'");
  const std::size_t range = gp.find("set cbrange [", at);
  if (at == std::string::npos || range == std::string::npos)
    return "";
  return gp.substr(range + 13, gp.find(']', range) - range - 13);
}

TEST(Report, NamesEveryStateAndGivesEveryEnginesPanelOfARowOneColourScale)
{
  // A DEM section of scattered points, an FE cube grid and a FEM x DEM grid of rectangular
  // tiles, sheared differently (the DEM twice the FE cube, the FEM x DEM 1.5 times): the three
  // panels of a row, in that order, on the DEM's wider range; the onset not found is said so.
  SectionSeries dem, fe, femdem;
  dem.engine = "DEM";
  fe.engine = "FE cube";
  femdem.engine = "FEM x DEM";
  for (int i = 0; i < 15; ++i)
    for (int k = 0; k < 15; ++k) {
      dem.x.push_back(-0.1 + (i + 0.3 * (k % 2)) * 0.2 / 15);
      dem.z.push_back(-0.1 + k * 0.2 / 15);
      fe.x.push_back((i + 0.5) * 0.2 / 15);
      fe.z.push_back((k + 0.5) * 0.2 / 15);
      femdem.x.push_back((i + 0.5) * 0.1 / 15);
      femdem.z.push_back((k + 0.5) * 0.2 / 15);
    }
  fe.centre_x = fe.centre_z = 0.1;
  femdem.centre_x = 0.05;
  femdem.centre_z = 0.1;
  dem.strain_radius = fe.strain_radius = femdem.strain_radius = 0.025;
  dem.marker = 0.006;
  fe.marker = fe.marker_z = 0.2 / 30;
  femdem.marker = 0.1 / 30;
  femdem.marker_z = 0.2 / 30;
  fe.tiles = femdem.tiles = true;
  for (SectionSeries *s : {&dem, &fe, &femdem}) {
    const double a = s == &dem ? 0.02 : s == &fe ? 0.01 : 0.015;
    s->times = {0.0, 1.0, 2.0};
    for (int t = 0; t < 3; ++t) {
      s->ux.emplace_back();
      s->uz.emplace_back();
      for (std::size_t i = 0; i < s->x.size(); ++i) {
        s->ux.back().push_back(-0.5 * t * a * (s->x[i] - s->centre_x) + 1e-3 * t);
        s->uz.back().push_back(0.5 * t * a * (s->z[i] - s->centre_z));
      }
    }
  }
  const std::vector<NamedState> states{{"B", "elastic limit", true, 0.01, 2e6, ""},
                                       {"peak", "maximum", true, 0.02, 5e6, ""},
                                       {"D", "past the peak", true, 0.02, 4.7e6, ""},
                                       {"DEM onset", "onset", false, NAN, NAN, "no onset found (DEM)"}};
  ReportInput in = sample_input();
  const std::vector<double> strains{0.0, 0.01, 0.02};
  in.state_maps = state_maps(states, {{"DEM", &dem, strains, {}}, {"FE cube", &fe, strains, {}},
                                      {"FEM x DEM", &femdem, strains, {}}});
  in.state_maps_note = "synthetic sections";
  const fs::path dir = scratch("states");
  ReportOptions o;
  if (!geocomp::program_available("gnuplot"))
    o.gnuplot = "/nonexistent/gnuplot";
  const ReportOutcome out = write_report(in, dir, o);
  const std::string html = read(dir / "index.html"), gp = read(dir / "report.gp");
  for (const char *name : {"B", "peak", "D", "DEM onset"})
    EXPECT_NE(html.find(std::string("data-state=\"") + name + "\""), std::string::npos) << name;
  EXPECT_NE(html.find("DEM onset: not found, no maps: no onset found (DEM)."), std::string::npos);
  // Three states with maps, three rows each (u_x, u_z, local gamma), DEM | FE cube | FEM x DEM.
  for (std::size_t st = 0; st < 3; ++st)
    for (std::size_t r = 0; r < 3; ++r) {
      const MapRow &row = in.state_maps[st].rows[r];
      ASSERT_EQ(row.panels.size(), 3u);
      std::size_t previous = 0;
      for (const MapPanel &p : row.panels) {
        const std::string png = state_map_png(st, r, p.engine) + ".png";
        EXPECT_EQ(panel_range(gp, png), format_number(row.range.low) + ":" + format_number(row.range.high)) << png;
        for (double v : p.v)
          if (std::isfinite(v)) {
            EXPECT_GE(v, row.range.low);
            EXPECT_LE(v, row.range.high);
          }
        if (!out.plots_made)
          continue;
        const std::size_t at = html.find("src=\"" + png + "\"");
        ASSERT_NE(at, std::string::npos) << png;
        EXPECT_GT(at, previous) << png << ": the panels in the order DEM | FE cube | FEM x DEM";
        previous = at;
      }
    }
  EXPECT_EQ(state_map_png(1, 2, "FEM x DEM"), "state1_2_fem-x-dem");
  EXPECT_EQ(state_map_png(0, 0, "FE cube"), "state0_0_fe-cube");
  // The FEM x DEM's tiles are 0.1/15 wide and 0.2/15 high.
  EXPECT_NE(gp.find("using 1:2:(" + format_number(0.1 / 30) + "):(" + format_number(0.2 / 30) + "):3 with boxxyerror"),
            std::string::npos);
  // The DEM's u_x at the peak reaches a L/2 = 0.02 x 0.1 m = 2 mm at x = -L/2 (the FE's at most
  // 0.01 x 0.093 m): the row's range reaches the DEM's largest.
  EXPECT_NEAR(in.state_maps[1].rows[0].range.high, 2.0, 1e-9);
  const Json root = JsonReader(read(dir / "metrics.json")).parse();
  const Json *onset = lookup(root, "named_states/3/found");
  ASSERT_NE(onset, nullptr);
  EXPECT_EQ(onset->kind, Json::Bool);
  EXPECT_EQ(lookup(root, "named_states/1/strain_pct")->text, "2");
  for (const auto &[k, engine] : std::vector<std::pair<std::string, std::string>>{{"0", "DEM"}, {"1", "FE cube"},
                                                                                  {"2", "FEM x DEM"}}) {
    const Json *e = lookup(root, "named_states/1/panels/" + k + "/engine");
    ASSERT_NE(e, nullptr) << k;
    EXPECT_EQ(e->text, engine);
  }
  if (!std::getenv("GEOCOMP_TEST_KEEP"))
    fs::remove_all(dir.parent_path());
}

TEST(Report, OpensInABrowserWithEveryImageAndLinkAndNoScriptError)
{
  if (!geocomp::program_available("chromium") || !geocomp::program_available("gnuplot"))
    GTEST_SKIP() << "chromium or gnuplot not installed (scripts/install-deps.sh installs both)";
  const fs::path dir = scratch("browser");
  const fs::path work = dir.parent_path();
  const ReportOutcome out = write_report(sample_input(), dir);
  ASSERT_TRUE(out.plots_made) << out.message;
  const std::string html = read(dir / "index.html");
  std::size_t links = 0;
  for (std::size_t at = html.find("<a href=\""); at != std::string::npos; at = html.find("<a href=\"", at + 1))
    links += html.compare(at + 9, 4, "http") != 0 && html[at + 9] != '#';
  const std::string counts = "images " + std::to_string(out.plots.size()) + ", links " + std::to_string(links) + ": ";
  EXPECT_GE(links, out.plots.size() + 1); // every plot, and metrics.json
  EXPECT_EQ(browser_check(dir, work), counts + "ok");
  EXPECT_EQ(script_errors(dir / "index.html", work), "");
  // A screenshot of the page as a reader sees it, kept in the build folder (never in the
  // working directory, the source tree under ctest).
  const fs::path shot = fs::path(GEOCOMP_BINARY_DIR) / "report-screenshot.png";
  EXPECT_TRUE(chromium({"--window-size=1200,2600", "--screenshot=" + shot.string()}, dir / "index.html", work).succeeded());
  EXPECT_GT(fs::file_size(shot), 50000u);
  EXPECT_EQ(read(shot).substr(1, 3), "PNG");
  std::cout << "screenshot: " << shot << "\n";
  // The checks can fail: an image removed, and a page with a script error.
  fs::remove(dir / out.plots.back());
  EXPECT_EQ(browser_check(dir, work),
            counts + "image not loaded: " + out.plots.back() + "; broken link: " + out.plots.back());
  std::ofstream(work / "bad.html") << "<!DOCTYPE html><html><body><script>undefined_function();</script></body></html>";
  EXPECT_NE(script_errors(work / "bad.html", work).find("undefined_function"), std::string::npos);
  fs::remove_all(work);
}

// Without gnuplot: a clear message, still the tables and metrics.json; rewriting the same
// folder replaces it whole and leaves no temporary folders behind.
TEST(Report, WithoutGnuplotTablesAreStillWrittenAtomically)
{
  ReportInput in = sample_input();
  const fs::path dir = scratch("nogp");
  ReportOptions o;
  o.gnuplot = "/nonexistent/gnuplot";
  const ReportOutcome out = write_report(in, dir, o);
  EXPECT_FALSE(out.plots_made);
  EXPECT_TRUE(out.plots.empty());
  EXPECT_NE(out.message.find("gnuplot not found"), std::string::npos);
  EXPECT_NE(read(dir / "index.html").find("gnuplot not found"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "report.gp"));
  EXPECT_EQ(check_html_against_json(dir), 11 * 3 + 2 + 2 * 5 + 3 * (4 + 3));

  in.metrics.pop_back();
  in.title = "second";
  write_report(in, dir, o);
  EXPECT_NE(read(dir / "index.html").find("<h1>second</h1>"), std::string::npos);
  EXPECT_EQ(check_html_against_json(dir), 11 + 2 + 2 * 5 + 3 * 4);
  int entries = 0;
  for (const auto &e : fs::directory_iterator(dir.parent_path())) {
    (void)e;
    ++entries;
  }
  EXPECT_EQ(entries, 1); // only the report folder itself
  fs::remove_all(dir.parent_path());
}
