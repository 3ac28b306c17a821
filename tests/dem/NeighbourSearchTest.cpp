// Neighbour lists: complete (same contacts as brute force), history carried across
// rebuilds and checkpoints; the half stencil of a cell-ordered grid.
#include "dem/CellGrid.h"
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <vector>

using namespace geocomp::dem;

namespace {
/// With `reverse_ids`, the same spheres numbered backwards (the id order of nearly every
/// pair is then the reverse of its storage order, the lists' i < j).
void make_specimen(DemSystem& sys, bool reverse_ids = false)
{
  sys.set_contact_model(test::linear_law(1e5, 0.5, 2.0 / 7.0));
  sys.set_friction(0.4);
  if (reverse_ids) {
    DemSystem ref;
    test::fill_box(ref, 6, 0.01, 0.3, 9u, 0.2);
    test::add_renumbered_backwards(sys, ref, 0.01);
  } else {
    test::fill_box(sys, 6, 0.01, 0.3, 9u, 0.2);
  }
  for (std::size_t w = 0; w < 6; ++w) sys.set_wall_velocity(w, 0.05 * sys.wall(w).normal);
  const double m = 4.0 / 3.0 * M_PI * 1e-6 * 2650.0;
  sys.set_time_step(0.1 * std::sqrt(m / 1e5));
}
}  // namespace

TEST(NeighbourSearch, FindsEveryTouchingPairThatBruteForceFinds)
{
  DemSystem sys;
  make_specimen(sys);
  sys.run(1500);
  std::set<std::pair<ParticleId, ParticleId>> brute, listed;
  for (ParticleId a = 0; a < sys.n_particles(); ++a)
    for (ParticleId b = a + 1; b < sys.n_particles(); ++b)
      if ((sys.position(a) - sys.position(b)).norm() < 0.02) brute.insert({a, b});
  for (const ContactRecord& c : sys.contacts())
    if (!c.wall) listed.insert({c.i, c.j});
  ASSERT_GT(brute.size(), 100u);
  EXPECT_EQ(brute, listed);
  EXPECT_GT(sys.n_rebuilds(), 1u);
}

TEST(NeighbourSearch, ContactHistorySurvivesRebuild)
{
  // Extra rebuilds (with re-sorting of the storage) must not change the physics: the
  // tangential springs are carried over by stable ids.
  DemSystem a, b;
  make_specimen(a);
  make_specimen(b);
  a.run(600);
  b.run(600);
  std::size_t sticking = 0;
  for (const ContactRecord& c : a.contacts()) sticking += c.tangential_force.norm() > 0.0 ? 1 : 0;
  ASSERT_GT(sticking, 50u);
  for (int k = 0; k < 20; ++k) {
    b.request_rebuild();
    a.run(5);
    b.run(5);
  }
  EXPECT_GT(b.n_rebuilds(), a.n_rebuilds() + 10);
  std::map<std::pair<ParticleId, ParticleId>, Vec3> fa;
  for (const ContactRecord& c : a.contacts())
    if (!c.wall) fa[{c.i, c.j}] = c.tangential_force;
  double worst = 0.0, scale = 0.0;
  for (const ContactRecord& c : b.contacts()) {
    if (c.wall) continue;
    auto it = fa.find({c.i, c.j});
    ASSERT_NE(it, fa.end());
    worst = std::max(worst, (it->second - c.tangential_force).norm());
    scale = std::max(scale, c.tangential_force.norm());
  }
  EXPECT_LT(worst, 1e-8 * scale);
}

TEST(NeighbourSearch, IdOrderOppositeToStorageOrderGivesTheSameMotion)
{
  // The lists store a pair with i before j in storage, the archive and the outputs with
  // the lower id first: with every id reversed, each loaded spring is flipped into and
  // out of the archive at every rebuild. The motion must be that of the same spheres
  // numbered forwards (to round-off: the slots are summed in another order).
  DemSystem fwd, rev;
  make_specimen(fwd);
  make_specimen(rev, true);
  fwd.run(600);
  rev.run(600);
  std::size_t reversed = 0;
  for (const PairSlot& s : rev.contact_lists().pairs)
    reversed += (rev.particles().id[s.i] > rev.particles().id[s.j] && s.shear.norm() > 0.0) ? 1 : 0;
  ASSERT_GT(reversed, 50u);
  ASSERT_GT(rev.n_rebuilds(), 2u);
  const ParticleId n = ParticleId(fwd.n_particles());
  double worst = 0.0;
  for (ParticleId id = 0; id < n; ++id)
    worst = std::max(worst, (fwd.position(id) - rev.position(n - 1 - id)).norm());
  EXPECT_LT(worst, 1e-12);  // [m]; spheres of 1 cm that moved about 1 mm
  double worst_f = 0.0, scale = 0.0;
  std::size_t matched = 0;
  std::map<std::pair<ParticleId, ParticleId>, Vec3> ft;
  for (const ContactRecord& c : fwd.contacts())
    if (!c.wall) ft[{c.i, c.j}] = c.tangential_force;
  for (const ContactRecord& c : rev.contacts()) {
    if (c.wall) continue;
    ASSERT_LT(c.i, c.j);  // reported with the lower id first
    // Forward ids of the pair: j is the lower one there, so the force on it is -F_t.
    auto it = ft.find({n - 1 - c.j, n - 1 - c.i});
    ASSERT_NE(it, ft.end());
    worst_f = std::max(worst_f, (it->second + c.tangential_force).norm());
    scale = std::max(scale, c.tangential_force.norm());
    ++matched;
  }
  EXPECT_GT(matched, 100u);
  EXPECT_LT(worst_f, 1e-8 * scale);
}

TEST(NeighbourSearch, ExportedContactStateRestoresTangentialForces)
{
  DemSystem a;
  make_specimen(a);
  a.run(600);
  const std::vector<ContactState> saved = a.export_contact_state();
  ASSERT_FALSE(saved.empty());
  // A second system with the same particles (by id) and walls, histories imported.
  DemSystem b;
  make_specimen(b);
  for (ParticleId id = 0; id < a.n_particles(); ++id) {
    b.set_position(id, a.position(id));
    b.set_velocity(id, a.velocity(id));
    b.set_angular_velocity(id, a.angular_velocity(id));
  }
  for (std::size_t w = 0; w < a.n_walls(); ++w) b.set_wall_position(w, a.wall(w).point);
  b.import_contact_state(saved);
  b.run(1);
  a.run(1);
  std::map<std::pair<ParticleId, ParticleId>, Vec3> fa;
  for (const ContactRecord& c : a.contacts())
    if (!c.wall) fa[{c.i, c.j}] = c.tangential_force;
  double worst = 0.0, scale = 0.0;
  std::size_t matched = 0;
  for (const ContactRecord& c : b.contacts()) {
    if (c.wall) continue;
    auto it = fa.find({c.i, c.j});
    if (it == fa.end()) continue;
    ++matched;
    worst = std::max(worst, (it->second - c.tangential_force).norm());
    scale = std::max(scale, c.tangential_force.norm());
  }
  EXPECT_GT(matched, 50u);
  // Not bitwise: the restart evaluates the dashpots once more with on-step velocities.
  EXPECT_LT(worst, 1e-2 * scale);
}

TEST(CellGrid, HalfStencilMeetsTheLaterParticlesInTheFullStencilsOrder)
{
  // Random points binned, then stored in cell order (as the spatial sort leaves them):
  // for_each_after(p) must list exactly the q > p of the 27-cell stencil, in its order.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> x(3000);
  for (Vec3& p : x) p = Vec3(u(rng), 0.6 * u(rng), 0.3 * u(rng));
  CellGrid grid;
  grid.build(x, 0.07);
  std::vector<Vec3> sorted;
  for (const Index k : grid.sorted()) sorted.push_back(x[k]);
  grid.build(sorted, 0.07);
  for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(grid.sorted()[k], Index(k));
  std::size_t listed = 0;
  for (Index p = 0; p < sorted.size(); ++p) {
    std::vector<Index> full, half;
    grid.for_each_near(grid.cell_of_particle(p), [&](Index q) {
      if (q > p) full.push_back(q);
    });
    grid.for_each_after(p, [&](Index q) { half.push_back(q); });
    ASSERT_EQ(full, half) << "particle " << p;
    listed += half.size();
  }
  EXPECT_GT(listed, 20 * sorted.size());  // a real neighbourhood, not empty cells
}
