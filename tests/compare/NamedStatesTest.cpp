// The named states of a curve (B, peak, D, DEM onset) on a synthetic Response whose backbone is
// closed form (Synthetic.h), and the mid-section maps built from either engine's section:
// one displacement reference (the box centre) and one local-strain measure for both.
#include "compare/NamedStates.h"
#include "compare/SectionMaps.h"
#include "Synthetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace geocomp;
using namespace geocomp::compare;
using geocomp::compare::testing::Backbone;
using geocomp::compare::testing::shear_response;

namespace {
constexpr double dg = 5e-4;

struct Located {
  Curve curve;
  MetricSet metrics;
};

Located locate(const Backbone &b, const std::vector<double> &branches = {})
{
  const Response r = shear_response(b, dg, 0.0, branches, b.E);
  MetricOptions o;
  o.kind = CurveKind::ShearIsochoric;
  Located l{extract_curve(r, CurveKind::ShearIsochoric), {}};
  l.metrics = compute_metrics(l.curve, o);
  return l;
}

const NamedState &state(const std::vector<NamedState> &s, const std::string &name)
{
  for (const auto &x : s)
    if (x.name == name)
      return x;
  throw std::runtime_error("no state " + name);
}
} // namespace

TEST(NamedStates, PeakAndDFallWhereTheBackboneSaysAndBIsTheMetricsElasticLimit)
{
  // Peak at g_p = 0.016; past it tau = tau_p - H (g - g_p) (linear, unchanged by the centred
  // smoothing), so a drop of 5 % of tau_p (y0 = 0) is reached at g_p + 0.05 tau_p / H = 0.0185.
  const Backbone b;
  const Located l = locate(b, {0.004, 0.008, 0.012, 0.016, 0.02, 0.024});
  const OnsetEstimate onset{"DEM (particle local strain)", true, 0.021, 60.0, true, ""};
  const std::vector<NamedState> s = named_states(l.curve, l.metrics, &onset);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].name, "B");
  EXPECT_EQ(s[1].name, "peak");
  EXPECT_EQ(s[2].name, "D");
  EXPECT_EQ(s[3].name, "DEM onset");
  ASSERT_TRUE(s[0].found);
  EXPECT_EQ(s[0].strain, l.metrics.elastic_limit_strain);
  EXPECT_GT(s[0].strain, b.g_e()); // the 1 % residual lies past the linear range
  EXPECT_NEAR(state(s, "peak").strain, b.g_p(), 1.5 * dg);
  EXPECT_EQ(state(s, "peak").strain, l.metrics.peak_strain);
  const double d = b.g_p() + 0.05 * b.tau_p / b.H;
  ASSERT_TRUE(state(s, "D").found);
  EXPECT_GE(state(s, "D").strain, d - 1e-9);
  EXPECT_LE(state(s, "D").strain, d + dg + 1e-9); // the first sample at or past the drop
  EXPECT_LE(state(s, "D").stress, 0.95 * b.tau_p * (1 + 1e-12));
  EXPECT_TRUE(state(s, "DEM onset").found);
  EXPECT_EQ(state(s, "DEM onset").strain, 0.021);
}

TEST(NamedStates, WithoutASofteningDropDIsTheEndAndWithoutAPeakItIsMissing)
{
  Backbone gentle; // softens by 1 % of the peak by the end: no 5 % drop
  gentle.H = 0.01 * gentle.tau_p / (gentle.g_end - gentle.g_p());
  gentle.tau_r = 0.0;
  const Located l = locate(gentle);
  const std::vector<NamedState> s = named_states(l.curve, l.metrics, nullptr);
  ASSERT_EQ(s.size(), 3u); // no onset asked for
  ASSERT_TRUE(state(s, "D").found);
  EXPECT_NEAR(state(s, "D").strain, gentle.g_end, 1e-12);
  EXPECT_NE(state(s, "D").definition.find("end of the main path"), std::string::npos);

  Backbone hardening; // the peak beyond the end: the maximum is the last sample
  hardening.g_end = 0.8 * hardening.g_p();
  const Located h = locate(hardening);
  const OnsetEstimate none{"DEM (particle local strain)", false, 0.0, 0.0, false, ""};
  const std::vector<NamedState> t = named_states(h.curve, h.metrics, &none);
  EXPECT_TRUE(state(t, "peak").found);
  EXPECT_NE(state(t, "peak").definition.find("may not have been reached"), std::string::npos);
  EXPECT_FALSE(state(t, "D").found);
  EXPECT_NE(state(t, "D").missing.find("last sample"), std::string::npos);
  EXPECT_FALSE(state(t, "DEM onset").found);
  EXPECT_NE(state(t, "DEM onset").missing.find("no onset"), std::string::npos);

  MetricSet unlocated = h.metrics;
  unlocated.elastic_limit_strain = NAN;
  EXPECT_FALSE(named_states(h.curve, unlocated, nullptr).front().found);
  EXPECT_FALSE(named_states(h.curve, unlocated, nullptr).front().missing.empty());
}

namespace {
/// A DEM-like section (random particle centres in a box [-0.1, 0.1]^2, centre at the origin)
/// and an FE-like one (a 12 x 12 grid of tiles on [0, 0.2]^2, centre (0.1, 0.1)), both moved
/// by u(X) = t + G (X - X_c) at state 1 (state 0 is the start).
struct TwoSections {
  SectionSeries dem, fe;
};

void move(SectionSeries &s, const Eigen::Vector2d &t, const Eigen::Matrix2d &G)
{
  s.times = {0.0, 1.0};
  s.ux = {std::vector<double>(s.x.size(), 0.0), {}};
  s.uz = {std::vector<double>(s.x.size(), 0.0), {}};
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const Eigen::Vector2d u = t + G * Eigen::Vector2d(s.x[i] - s.centre_x, s.z[i] - s.centre_z);
    s.ux[1].push_back(u[0]);
    s.uz[1].push_back(u[1]);
  }
}

TwoSections sections(const Eigen::Vector2d &t, const Eigen::Matrix2d &G)
{
  TwoSections s;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
  s.dem.engine = "DEM";
  for (int i = 0; i < 400; ++i) {
    s.dem.x.push_back(coordinate(rng));
    s.dem.z.push_back(coordinate(rng));
  }
  s.dem.strain_radius = 0.03;
  s.fe.engine = "FE cube";
  s.fe.centre_x = s.fe.centre_z = 0.1;
  for (int i = 0; i < 12; ++i)
    for (int k = 0; k < 12; ++k) {
      s.fe.x.push_back((i + 0.5) * 0.2 / 12);
      s.fe.z.push_back((k + 0.5) * 0.2 / 12);
    }
  s.fe.strain_radius = 1.5 * 0.2 / 12;
  move(s.dem, t, G);
  move(s.fe, t, G);
  return s;
}

std::vector<StateMaps> maps_at(const TwoSections &s, double strain)
{
  NamedState peak{"peak", "synthetic", true, strain, NAN, ""};
  return state_maps({peak}, {{"DEM", &s.dem, {0.0, strain}, {}}, {"FE cube", &s.fe, {0.0, strain}, {}}});
}
} // namespace

TEST(SectionMaps, ARigidTranslationGivesZeroDisplacementAndStrainMapsInBothEngines)
{
  const TwoSections s = sections({3e-3, -2e-3}, Eigen::Matrix2d::Zero());
  const std::vector<StateMaps> m = maps_at(s, 0.01);
  ASSERT_EQ(m.size(), 1u);
  ASSERT_EQ(m[0].rows.size(), 3u);
  for (const MapRow &row : m[0].rows)
    for (const MapPanel &p : row.panels) {
      ASSERT_TRUE(p.present) << p.missing;
      for (double v : p.v)
        EXPECT_NEAR(v, 0.0, 1e-9) << row.quantity << " " << p.engine; // mm or %
    }
  // Zero everywhere is one colour: the range is about zero and wider than the round-off, at
  // least 1 % of the translation before the reference (3 mm).
  const MapRow &ux = m[0].rows[0];
  EXPECT_LE(ux.range.low, 0.0);
  EXPECT_GE(ux.range.high, 0.0);
  EXPECT_GE(ux.range.high - ux.range.low, 0.01 * 3.0 * (1 - 1e-12));
}

TEST(SectionMaps, AHomogeneousShearIsTheSameFieldAboutTheBoxCentreInBothEngines)
{
  // Isochoric pure shear with a translation: u = t + diag(-a, a)(X - X_c); from the box
  // centre the maps are u_x = -a (x - x_c), u_z = a (z - z_c) in both engines whatever their
  // coordinates, and the local gamma is 2a at every point with a full neighbourhood (E of
  // F = diag(1 - a, 1 + a): E_xx - E_zz = -2a).
  const double a = 0.02;
  Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
  G(0, 0) = -a;
  G(1, 1) = a;
  const TwoSections s = sections({1e-3, 4e-3}, G);
  const std::vector<StateMaps> m = maps_at(s, 2 * a);
  for (const MapPanel &p : m[0].rows[0].panels) {
    const SectionSeries &sec = p.engine == "DEM" ? s.dem : s.fe;
    for (std::size_t i = 0; i < p.v.size(); ++i)
      EXPECT_NEAR(p.v[i], -a * (sec.x[i] - sec.centre_x) * 1e3, 1e-9) << p.engine;
  }
  for (const MapPanel &p : m[0].rows[1].panels) {
    const SectionSeries &sec = p.engine == "DEM" ? s.dem : s.fe;
    for (std::size_t i = 0; i < p.v.size(); ++i)
      EXPECT_NEAR(p.v[i], a * (sec.z[i] - sec.centre_z) * 1e3, 1e-9) << p.engine;
  }
  std::size_t fitted = 0;
  for (const MapPanel &p : m[0].rows[2].panels)
    for (double g : p.v)
      if (std::isfinite(g)) {
        EXPECT_NEAR(g, 2 * a * 100, 1e-9);
        ++fitted;
      }
  EXPECT_GT(fitted, 400u);
  // A homogeneous gamma is one colour: the shared range is 1 % of it, not its round-off.
  EXPECT_NEAR(m[0].rows[2].range.high - m[0].rows[2].range.low, 0.01 * 2 * a * 100, 1e-9);
}

TEST(SectionMaps, ARowSharesOneColourRangeSpanningBothPanels)
{
  const std::vector<double> dem{-1.0, 0.25, 1.0}, fe{-3.0, 0.5, NAN};
  const ColourRange r = shared_colour_range({&dem, &fe}, 0.0);
  EXPECT_EQ(r.low, -3.0);
  EXPECT_EQ(r.high, 1.0);
  // Nearly uniform (round-off of 1e-15 on 0.2): widened to 1 % of 0.2 about its middle.
  const std::vector<double> flat{0.2, 0.2 * (1 + 1e-15), 0.2 * (1 - 1e-15)};
  const ColourRange f = shared_colour_range({&flat, &flat}, 0.0);
  EXPECT_NEAR(f.high - f.low, 0.002, 1e-12);
  EXPECT_NEAR(0.5 * (f.high + f.low), 0.2, 1e-12);
  // A state recorded by one engine only: its panel says so, the other keeps the range.
  const TwoSections s = sections({0.0, 0.0}, Eigen::Matrix2d::Identity() * 0.01);
  NamedState late{"D", "synthetic", true, 0.2, NAN, ""};
  const std::vector<StateMaps> m =
    state_maps({late}, {{"DEM", &s.dem, {0.0, 0.2}, {}}, {"FE cube", &s.fe, {0.0, 0.02}, {}}});
  ASSERT_EQ(m[0].rows[0].panels.size(), 2u);
  EXPECT_TRUE(m[0].rows[0].panels[0].present);
  EXPECT_FALSE(m[0].rows[0].panels[1].present);
  EXPECT_NE(m[0].rows[0].panels[1].missing.find("no recorded mid-section within"), std::string::npos);
}
