// Local strain, heterogeneity and band fitting on synthetic particle fields: exact
// answers for affine fields, and a planted shear band whose onset and angle must come back.
#include "compare/Localization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

using namespace geocomp;
using namespace geocomp::compare;

namespace {
constexpr double deg = 180.0 / 3.14159265358979323846;

/// n^3 particles on a jittered cubic lattice of spacing a (fixed seed).
ParticleSnapshot lattice(int n, double a, double jitter, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * a, jitter * a);
  ParticleSnapshot s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        s.ids.push_back(static_cast<std::int64_t>(s.ids.size()) * 7 + 3); // not 0..N-1
        s.positions.emplace_back(i * a + u(rng), j * a + u(rng), k * a + u(rng));
      }
  return s;
}
} // namespace

TEST(Localization, NeighbourGridFindsExactlyTheBruteForcePairs)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vector3> p(600);
  for (auto &x : p)
    x = Vector3(u(rng), 0.3 * u(rng), 2.0 * u(rng));
  const double r = 0.09;
  auto pairs = neighbour_pairs(p, r);
  std::set<std::pair<std::size_t, std::size_t>> got(pairs.begin(), pairs.end());
  EXPECT_EQ(got.size(), pairs.size());
  std::size_t brute = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if ((p[i] - p[j]).norm() <= r) {
        ++brute;
        EXPECT_TRUE(got.count({i, j}));
      }
  EXPECT_EQ(brute, got.size());
}

// An affine map x = F X + c: every interior fit recovers F, D2_min vanishes, and eta is
// the von Mises shear of E = (F^T F - I)/2. Shuffled current order checks id matching.
TEST(Localization, AffineFieldGivesExactStrainAndZeroD2min)
{
  const ParticleSnapshot ref = lattice(8, 1.0, 0.2, 3);
  Tensor3 F;
  F << 0.99, 0.004, 0.0, 0.0, 1.0, 0.0, 0.01, 0.0, 1.012;
  ParticleSnapshot cur;
  for (std::size_t i = ref.ids.size(); i-- > 0;) {
    cur.ids.push_back(ref.ids[i]);
    cur.positions.push_back(F * ref.positions[i] + Vector3(0.3, -1.0, 2.0));
  }
  LocalStrainOptions o;
  o.radius = 1.6;
  const LocalStrainField f = local_strain(ref, cur, o);
  const Tensor3 E = 0.5 * (F.transpose() * F - Tensor3::Identity());
  const Tensor3 dev = E - E.trace() / 3 * Tensor3::Identity();
  const double eta = std::sqrt(0.5 * (dev.array() * dev.array()).sum());
  EXPECT_GT(f.valid_count(), ref.ids.size() * 9 / 10);
  for (std::size_t i = 0; i < f.ids.size(); ++i) {
    if (!f.valid[i])
      continue;
    EXPECT_LT((f.F[i] - F).norm(), 1e-10);
    EXPECT_NEAR(f.eta[i], eta, 1e-10);
    EXPECT_NEAR(f.volumetric[i], E.trace(), 1e-10);
    EXPECT_LT(f.d2min[i], 1e-20);
  }
  EXPECT_NEAR(heterogeneity(f, HeterogeneityIndex::CoefficientOfVariation), 0.0, 1e-6);
  // A particle that vanished is invalid, not a crash.
  ParticleSnapshot fewer = cur;
  fewer.ids.pop_back();
  fewer.positions.pop_back();
  const LocalStrainField g = local_strain(ref, fewer, o);
  EXPECT_FALSE(g.valid[0]); // ref.ids[0] was the last one pushed to cur
  EXPECT_THROW(local_strain(ref, cur, LocalStrainOptions{}), std::invalid_argument);
}

// A planted band: homogeneous pure shear (x shortens, z extends) for 5 increments, then a
// slip of 0.3 a per increment across a tanh layer of width 1.5 a on the plane with normal
// n at 60 deg from x in the x-z plane. Position noise 2e-5 a per snapshot. The index must
// cross the threshold on the first slipping increment and the fitted normal must be
// within 2 deg of n.
TEST(Localization, PlantedShearBandOnsetAndAngleRecovered)
{
  const double a = 0.01;
  const int n = 16;
  const ParticleSnapshot ref = lattice(n, a, 0.15, 5);
  const Vector3 centre = Vector3::Constant(0.5 * (n - 1) * a);
  const double theta = 60.0 / deg;
  const Vector3 normal(std::cos(theta), 0.0, std::sin(theta));
  const Vector3 slip(-std::sin(theta), 0.0, std::cos(theta));
  const int onset = 5, count = 9;
  std::mt19937 rng(17);
  std::normal_distribution<double> noise(0.0, 2e-5 * a);
  std::vector<ParticleSnapshot> snaps;
  for (int k = 0; k < count; ++k) {
    ParticleSnapshot s;
    s.ids = ref.ids;
    s.label = 0.002 * k; // gamma_max of the box
    const double e = 0.001 * k;
    const double amp = k >= onset ? 0.3 * a * (k - onset + 1) : 0.0;
    for (const auto &X : ref.positions) {
      const Vector3 d = X - centre;
      Vector3 x = X + Vector3(-e * d.x(), 0.0, e * d.z());
      x += amp * 0.5 * (1.0 + std::tanh(d.dot(normal) / (1.5 * a))) * slip;
      s.positions.push_back(x + Vector3(noise(rng), noise(rng), noise(rng)));
    }
    snaps.push_back(s);
  }
  LocalizationOptions o;
  o.strain.radius = 1.6 * a;
  o.compressive_axis = Vector3::UnitX();
  o.intermediate_axis = Vector3::UnitY();
  const LocalizationResult r = detect_localization(snaps, o);
  ASSERT_EQ(r.index.size(), std::size_t(count - 1));
  for (int k = 1; k < onset; ++k)
    EXPECT_LT(r.index[k - 1], 0.5 * o.threshold) << "increment " << k;
  ASSERT_TRUE(r.onset_found);
  EXPECT_EQ(r.onset_snapshot, std::size_t(onset));
  EXPECT_GT(r.onset_label, snaps[onset - 1].label);
  EXPECT_LE(r.onset_label, snaps[onset].label);
  ASSERT_TRUE(r.band.found);
  const double err = std::acos(std::min(1.0, std::abs(r.band.normal.dot(normal)))) * deg;
  EXPECT_LT(err, 2.0) << "normal " << r.band.normal.transpose();
  EXPECT_NEAR(r.band.angle_to_compressive_deg, 60.0, 2.0);
  EXPECT_NEAR(r.band.angle_to_intermediate_deg, 90.0, 2.0);
  EXPECT_EQ(r.band.clusters, 1u);
  EXPECT_GT(r.band.planarity, 0.8);
  // The plane passes through the centre of the planted band.
  EXPECT_LT(std::abs((r.band.centroid - centre).dot(normal)), 1.0 * a);

  // The other index tells the same story.
  o.index = HeterogeneityIndex::TopShare;
  o.threshold = 0.3; // homogeneous: ~0.1, band: most of the shear in the top 10 %
  const LocalizationResult t = detect_localization(snaps, o);
  ASSERT_TRUE(t.onset_found);
  EXPECT_EQ(t.onset_snapshot, std::size_t(onset));
}
