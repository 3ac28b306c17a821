// S2 Fig. 3 (Zhao & Chi 2022, sec. 1.2): the single-particle test repeated with ten seeds
// of the cut point gives ten different fragment size distributions that "fluctuate within
// a range". The range has a closed form. Without d_M a parent breaks into eight children
// with d/D = (x y z)^{1/3}, x in {a, 1-a}, ..., a = U^p (S2 eqs. (1)-(2)); their mean over
// the eight factorizes, m = prod_axes g(a) with g(a) = (a^{1/3} + (1-a)^{1/3}) / 2, so
// E[m] = (E g)^3 and Var[m] = (E g^2)^3 - (E g)^6 (three independent axes). The mean of m
// over the n parents of one seed scatters from seed to seed with variance Var[m] / n.
// The expectations are integrals over U, done here by quadrature (the report's closed form,
// CrushRuns.h, uses the Beta function: the two must agree).
#include "compare/CrushRuns.h"
#include "dem/program/CrushPrograms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <vector>

namespace {

using namespace geocomp;

/// int_0^1 f(u) du by the midpoint rule (the integrands are bounded, one has an infinite
/// slope at u = 1 that the midpoint rule tolerates).
double integral(const std::function<double(double)>& f, int n = 200000)
{
  double s = 0.0;
  for (int k = 0; k < n; ++k) s += f((k + 0.5) / n);
  return s / n;
}

struct Moments
{
  double mean = 0.0, variance = 0.0;  ///< of m, the mean d/D over one parent's children
};

Moments moments(int power)
{
  auto g = [power](double u) {
    const double a = std::pow(u, power);
    return 0.5 * (std::cbrt(a) + std::cbrt(1.0 - a));
  };
  const double eg = integral(g), eg2 = integral([&](double u) { return g(u) * g(u); });
  return {std::pow(eg, 3), std::pow(eg2, 3) - std::pow(eg, 6)};
}

dem::CrushSetup ten_seeds(int particles_per_seed)
{
  dem::CrushSetup s;
  s.mode = "single particle";
  s.density_scaling = 100.0;  // a longer step; the fragment sizes do not depend on the dynamics
  s.record_interval = 1000;
  s.breakage.rules.mode = dem::BreakageMode::cube;
  s.breakage.rules.cut_power = 2;       // S2's squared cut point
  s.breakage.rules.minimum_size = 0.0;  // every parent gives its eight children (closed form)
  s.breakage.rules.breakage_limit = 0.005;
  s.breakage.criterion.strength = 10e6;
  s.breakage.interval = 10;
  s.single.particles = particles_per_seed;
  s.single.runs = 10;
  return s;
}

}  // namespace

TEST(SingleParticleCrushing, TenSeedsScatterTheMeanFragmentSizeAsMuchAsTheRandomCutPointPredicts)
{
  const int n = 20;  // parents per seed
  const dem::CrushResults r = dem::run_crush(ten_seeds(n));
  const auto& f = r.fragments;
  ASSERT_EQ(f.columns.back(), "run");
  ASSERT_EQ(f.rows.size(), std::size_t(8 * n * 10)) << "every parent of every seed broke into eight children";
  // m per parent, then its mean per seed.
  std::map<int, double> m;
  std::vector<double> seed_mean(10, 0.0);
  for (const auto& row : f.rows) m[int(row[0])] += row[3] / 8.0;
  for (const auto& [parent, value] : m) seed_mean[std::size_t(parent / n)] += value / n;

  const Moments squared = moments(2);
  EXPECT_NEAR(squared.mean, compare::expected_mean_relative_size(2), 1e-6) << "quadrature against the Beta form";
  EXPECT_NEAR(moments(1).mean, compare::expected_mean_relative_size(1), 1e-6);
  EXPECT_NEAR(moments(3).mean, compare::expected_mean_relative_size(3), 1e-6);
  double grand = 0.0, scatter = 0.0;
  for (double x : seed_mean) grand += x / 10.0;
  for (double x : seed_mean) scatter += (x - grand) * (x - grand) / 9.0;
  const double se_seed = std::sqrt(squared.variance / n), se_all = se_seed / std::sqrt(10.0);
  const double ratio = scatter / (se_seed * se_seed);
  std::printf("mean d/D over 10 seeds %.4f, closed form %.4f (plain %.4f, cubed %.4f); |diff| %.4f against the "
              "allowed 4 SE = %.4f\nscatter between seeds: sd %.4f, predicted %.4f, variance ratio %.3f in "
              "[0.128, 3.10] (chi^2_9 / 9, 99.9 %%)\n",
              grand, squared.mean, moments(1).mean, moments(3).mean, std::abs(grand - squared.mean), 4.0 * se_all,
              std::sqrt(scatter), se_seed, ratio);
  // The seeds agree with the squared cut point, and could tell it from the plain or cubed one.
  EXPECT_LT(std::abs(grand - squared.mean), 4.0 * se_all);
  EXPECT_GT(std::abs(moments(1).mean - squared.mean), 6.0 * se_all);
  EXPECT_GT(std::abs(moments(3).mean - squared.mean), 6.0 * se_all);
  // S2: the ten seeds differ, within the range the cut point's randomness gives.
  EXPECT_GT(ratio, 0.128);
  EXPECT_LT(ratio, 3.10);
}
