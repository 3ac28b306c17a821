// The strain-field onset of an FE section (compare/SectionLocalization.h) on synthetic mid-planes
// with the FE engines' point layout (9 points a cell at 1/6, 1/2, 5/6 of its edges): a planted
// band at a known angle comes back with its angle and its onset, and a homogeneous field - the
// field Q1 elements give a homogeneous deformation - stays at an index of round-off.
#include "compare/SectionLocalization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace geocomp;
using namespace geocomp::compare;

namespace {
constexpr double deg = 180.0 / 3.14159265358979323846;

/// The mid-plane points of an nx x nz mesh of a box Lx x Lz (the layout of CubeEngine::mid_plane).
SectionSeries fe_layout(double lx, double lz, int nx, int nz)
{
  SectionSeries s;
  s.engine = "FE cube";
  const double hx = lx / nx, hz = lz / nz;
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k)
      for (double zeta : {1.0 / 6, 0.5, 5.0 / 6})
        for (double xi : {1.0 / 6, 0.5, 5.0 / 6}) {
          s.x.push_back((i + xi) * hx);
          s.z.push_back((k + zeta) * hz);
        }
  s.centre_x = 0.5 * lx;
  s.centre_z = 0.5 * lz;
  s.strain_radius = 1.5 * std::max(hx, hz) / 3;
  s.marker = hx / 6;
  s.marker_z = hz / 6;
  s.tiles = true;
  return s;
}

/// States 0..n - 1 of the displacement field u(k, x, z) -> (u_x, u_z), their strains 0.0025 k
/// and z as the most compressive axis of every state.
StrainedSection record(SectionSeries &s, int n, const std::function<Eigen::Vector2d(int, double, double)> &u)
{
  for (int k = 0; k < n; ++k) {
    s.times.push_back(k);
    s.ux.emplace_back();
    s.uz.emplace_back();
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const Eigen::Vector2d d = u(k, s.x[i], s.z[i]);
      s.ux.back().push_back(d.x());
      s.uz.back().push_back(d.y());
    }
  }
  StrainedSection strained{s.engine, &s, {}, {}};
  for (int k = 0; k < n; ++k) {
    strained.strains.push_back(0.0025 * k);
    strained.compressive_axes.emplace_back(0.0, 1.0);
  }
  return strained;
}

/// Biaxial compression about the centre: e_zz = -0.0025 k, e_xx = +0.0015 k.
Eigen::Vector2d homogeneous(const SectionSeries &s, int k, double x, double z)
{
  return {0.0015 * k * (x - s.centre_x), -0.0025 * k * (z - s.centre_z)};
}
} // namespace

// A 5 x 10 cm section in 8 x 16 cells under biaxial compression; from state 6 on, a band of
// width 2 point spacings (a tanh layer) through the centre whose normal makes 40 deg with the
// compressive axis z slips a fifth of its width per increment (a peak shear of 0.1 against the
// background's 0.004). The index stays below a tenth of the threshold for the homogeneous
// increments, the onset falls in the first slipping increment (from 1.25 to 1.5 % strain), and
// the fitted line's normal is within 2 deg of the planted one (a normal taken along the band
// would be at 50 deg).
TEST(SectionLocalization, APlantedBandAtAKnownAngleGivesThatAngleAndAnOnsetWhereItStarts)
{
  SectionSeries s = fe_layout(0.05, 0.1, 8, 16);
  const double theta = 40.0 / deg, width = 2 * 0.05 / 24;
  const Eigen::Vector2d normal(std::sin(theta), std::cos(theta)), slip(std::cos(theta), -std::sin(theta));
  const int onset = 6, states = 10;
  const StrainedSection strained = record(s, states, [&](int k, double x, double z) {
    const Eigen::Vector2d d(x - s.centre_x, z - s.centre_z);
    const double amplitude = k >= onset ? 0.2 * width * (k - onset + 1) : 0.0;
    return Eigen::Vector2d(homogeneous(s, k, x, z) + amplitude * 0.5 * (1 + std::tanh(d.dot(normal) / width)) * slip);
  });
  LocalizationOptions o;
  o.strain.radius = s.strain_radius;
  const SectionLocalization r = detect_section_localization(strained, o);
  ASSERT_EQ(r.index.size(), std::size_t(states - 1));
  for (int k = 1; k < onset; ++k)
    EXPECT_LT(r.index[k - 1], 0.1 * o.threshold) << "increment " << k;
  ASSERT_TRUE(r.onset.found);
  EXPECT_EQ(r.onset.increment + 1, std::size_t(onset)) << "the first slipping increment";
  EXPECT_GT(r.onset.label, strained.strains[onset - 1]);
  EXPECT_LE(r.onset.label, strained.strains[onset]);
  ASSERT_TRUE(r.band.found);
  EXPECT_LT(std::acos(std::min(1.0, std::abs(r.band.normal.dot(normal)))) * deg, 2.0)
    << "normal " << r.band.normal.transpose();
  EXPECT_TRUE(r.band.has_angle);
  EXPECT_NEAR(r.band.angle_to_compressive_deg, 40.0, 2.0);
  EXPECT_GT(r.band.linearity, 0.9);
  // The verdict table's row says the same.
  const OnsetEstimate e = strain_field_onset(strained, "FE cube (strain field)");
  EXPECT_TRUE(e.found);
  EXPECT_EQ(e.strain, r.onset.label);
  EXPECT_NEAR(e.angle_deg, 40.0, 2.0);
  EXPECT_NE(e.note.find("threshold 1"), std::string::npos) << e.note;
  std::printf("[band] onset %.4g %% strain (band from %.4g %%), normal at %.2f deg (planted 40), index %.3g -> %.3g\n",
              100 * r.onset.label, 100 * strained.strains[onset], r.band.angle_to_compressive_deg,
              r.index[onset - 2], r.index[onset - 1]);
}

// The same section deformed homogeneously: every increment is affine, the Q1 layout's fits are
// exact, and the index is round-off; no onset. A box of unequal spacings (2 x 4 cells on
// 2.5 x 5 cm: s_x = s_z) and one of a flat mesh (4 x 2 cells on 2.5 x 5 cm: s_z = 4 s_x) alike.
TEST(SectionLocalization, AHomogeneousFeFieldHasAnIndexOfRoundOffAndNoOnset)
{
  for (const auto &[nx, nz] : {std::pair{2, 4}, std::pair{4, 2}}) {
    SectionSeries s = fe_layout(0.025, 0.05, nx, nz);
    const StrainedSection strained =
      record(s, 8, [&s](int k, double x, double z) { return homogeneous(s, k, x, z); });
    LocalizationOptions o;
    o.strain.radius = s.strain_radius;
    const SectionLocalization r = detect_section_localization(strained, o);
    for (double h : r.index)
      EXPECT_LT(h, 1e-6) << nx << " x " << nz;
    EXPECT_FALSE(r.onset.found);
    const OnsetEstimate e = strain_field_onset(strained, "FE cube (strain field)");
    EXPECT_FALSE(e.found);
  }
}

TEST(SectionLocalization, WithoutASectionOrWithOneStateThereIsNoOnsetAndTheRowSaysWhy)
{
  EXPECT_NE(strain_field_onset({"FEM x DEM", nullptr, {}, {}}, "FEM x DEM (strain field)").note.find("no mid-plane"),
            std::string::npos);
  SectionSeries s = fe_layout(0.025, 0.05, 2, 4);
  const StrainedSection one = record(s, 1, [&s](int k, double x, double z) { return homogeneous(s, k, x, z); });
  const OnsetEstimate e = strain_field_onset(one, "FE cube (strain field)");
  EXPECT_FALSE(e.found);
  EXPECT_NE(e.note.find("fewer than two"), std::string::npos) << e.note;
  EXPECT_THROW(detect_section_localization(one, LocalizationOptions{}), std::invalid_argument);
}
