// The periodic pair list: every pair the minimum-image brute force finds, in a sheared
// cell, kept complete while the cell deforms; the minimum-image condition enforced.
#include "dem/periodic/PeriodicCell.h"
#include "TestCells.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>

using namespace geocomp::dem;

namespace {
/// Pairs (i < j) closer than R_i + R_j + gap by the minimum image, brute force.
std::set<std::pair<Index, Index>> brute_force_pairs(const PeriodicCell& cell, double gap)
{
  std::set<std::pair<Index, Index>> out;
  const ParticleStore& s = cell.particles();
  for (Index i = 0; i < s.size(); ++i)
    for (Index j = i + 1; j < s.size(); ++j) {
      // Every image within one cell in each direction (the cell is tilted: rounding the
      // reduced coordinates alone is not the minimum image).
      double best = 1e300;
      for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
          for (int c = -1; c <= 1; ++c) {
            Vec3 s_ij = cell.cell().reduced(s.x[j] - s.x[i]);
            for (int k = 0; k < 3; ++k) s_ij[k] -= std::round(s_ij[k]);
            best = std::min(best, (cell.cell().h() * (s_ij + Vec3(a, b, c))).norm());
          }
      if (best < s.radius[i] + s.radius[j] + gap) out.insert({i, j});
    }
  return out;
}

std::set<std::pair<Index, Index>> touching_in_list(const PeriodicCell& cell)
{
  std::set<std::pair<Index, Index>> out;
  const PeriodicNeighbours& nl = cell.neighbours();
  for (std::size_t c = 0; c < nl.pairs.size(); ++c)
    if (nl.overlap[c] > 0.0) out.insert({nl.pairs[c].i, nl.pairs[c].j});
  return out;
}
}  // namespace

TEST(PeriodicNeighbours, FindsEveryTouchingPairThatTheMinimumImageBruteForceFindsWhileTheCellShears)
{
  test::RveSetup s;
  s.particles = 150;
  PeriodicCell cell = test::consolidated_rve(s).cell;
  Mat3 l = Mat3::Zero();
  l(0, 1) = 10.0;  // about 13 % simple shear over the run (dt = 1.5e-6 s, 9000 steps)
  l(1, 2) = -4.0;
  l(2, 2) = -1.5;  // compression keeps the loose packing jammed (at constant volume it liquefies)
  cell.set_velocity_gradient(l);
  const std::size_t builds0 = cell.neighbours().builds();
  for (int k = 0; k < 6; ++k) {
    cell.run(1500);
    const auto brute = brute_force_pairs(cell, 0.0);
    EXPECT_GT(brute.size(), 100u) << "after " << cell.steps() << " steps, p = " << cell.stress().pressure();
    EXPECT_EQ(brute, touching_in_list(cell)) << "after " << cell.steps() << " steps";
  }
  EXPECT_GT(cell.neighbours().builds(), builds0 + 2);
  EXPECT_GT(std::abs(cell.cell().h()(0, 1)), 0.05 * cell.cell().h()(1, 1));  // the cell did tilt
}

TEST(PeriodicNeighbours, RefusesACellNarrowerThanTwiceTheCutOff)
{
  PeriodicCell::Parameters cp;
  cp.time_step = 1e-6;
  PeriodicCell cell(CellMatrix::box(Vec3(1.0, 1.0, 0.3)), test::periodic_linear_law(1e5, 0.5), cp);
  cell.add_sphere(Vec3(0.5, 0.5, 0.15), 0.07, 2650.0);  // 2 (2R + skin) = 0.322 > 0.3
  EXPECT_THROW(cell.evaluate(), std::runtime_error);
}
