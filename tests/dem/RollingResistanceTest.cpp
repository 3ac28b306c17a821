// Rolling resistance (S2, PFC's linear model): the moment cap mu_r R* F_n, the closed-form
// deceleration of a rolling sphere, and the rolling spring surviving rebuilds and checkpoints.
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

using namespace geocomp::dem;

namespace {
constexpr double kR = 0.01, kK = 1e5, kG = 9.81, kRho = 2650.0;

LinearRollingResistance rolling_law(double mu_r)
{
  // A tangential dashpot (c_t = c_n) damps the stick oscillation of the friction spring.
  return LinearRollingResistance(LinearNormal::with_stiffness(kK, 0.3), LinearTangential({true, 2.0 / 7.0, true, 1.0}),
                                 LinearRolling({mu_r, 1.0}));
}

double sphere_mass() { return 4.0 / 3.0 * M_PI * kR * kR * kR * kRho; }

/// One sphere resting on the floor z = 0 under gravity, with friction mu on the floor.
void sphere_on_floor(DemSystem& sys, double mu_r, double mu, const Vec3& v, const Vec3& w)
{
  const double m = sphere_mass();
  sys.set_contact_model(rolling_law(mu_r));
  sys.set_gravity(Vec3(0, 0, -kG));
  sys.add_sphere(Vec3(0, 0, kR - m * kG / kK), kR, kRho, v, w);  // normal equilibrium
  PlaneWall floor;
  floor.normal = Vec3::UnitZ();
  floor.mu = mu;
  sys.add_wall(floor);
  sys.set_time_step(0.02 * std::sqrt(m / kK));
}
}  // namespace

TEST(RollingResistance, MomentOnASpinningSphereIsCappedAtMuRTimesRTimesNormalForce)
{
  // Frictionless floor: the only torque is the rolling moment. Once the rolling spring
  // saturates, |T| = mu_r R F_n exactly and the spin decays at 2.5 mu_r g / R.
  const double mu_r = 0.2, w0 = 50.0;
  DemSystem sys;
  sphere_on_floor(sys, mu_r, 0.0, Vec3::Zero(), Vec3(0, w0, 0));
  const double t_end = 0.5 * w0 / (2.5 * mu_r * kG / kR);  // half-way to rest
  int checked = 0;
  while (sys.time() < t_end) {
    sys.step();
    if (sys.time() < 0.05 * t_end) continue;
    const ContactRecord c = sys.contacts().at(0);
    EXPECT_NEAR(sys.torque(0).norm() / (mu_r * kR * c.normal_force), 1.0, 1e-9);
    EXPECT_LT(sys.torque(0).y(), 0.0);  // opposes the spin
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  const double expected = w0 - 2.5 * mu_r * kG / kR * sys.time();
  EXPECT_NEAR(sys.angular_velocity(0).y() / expected, 1.0, 2e-3);
}

TEST(RollingResistance, SphereRollingOnAWallDeceleratesAtFiveSeventhsMuRG)
{
  // Rolling without slip with the moment at its cap: m a = F_t, I dw/dt = -R F_t - M,
  // a = R dw/dt  =>  a = -M R / (I + m R^2) = -(5/7) mu_r g (DEM-NOTES 10.4, S2 rolling model).
  const double mu_r = 0.1, mu = 0.5, v0 = 0.5;
  DemSystem sys;
  sphere_on_floor(sys, mu_r, mu, Vec3(v0, 0, 0), Vec3(0, v0 / kR, 0));
  const double a = 5.0 / 7.0 * mu_r * kG;
  const double t_stop = v0 / a;
  int checked = 0;
  while (sys.time() < 0.9 * t_stop) {
    sys.step();
    if (sys.n_steps() % 1000 != 0 || sys.time() < 0.05 * t_stop) continue;
    const double expected = v0 - a * sys.time();
    EXPECT_NEAR(sys.velocity(0).x(), expected, 2e-3 * v0) << "t = " << sys.time();
    EXPECT_NEAR(sys.velocity(0).x(), kR * sys.angular_velocity(0).y(), 1e-3 * v0);  // still rolling
    ++checked;
  }
  EXPECT_GT(checked, 20);
  // Without the rolling part the same sphere keeps rolling at v0.
  DemSystem free;
  sphere_on_floor(free, 0.0, mu, Vec3(v0, 0, 0), Vec3(0, v0 / kR, 0));
  free.run(20000);
  EXPECT_NEAR(free.velocity(0).x(), v0, 1e-3 * v0);
}

namespace {
std::map<std::pair<std::uint32_t, ParticleId>, Vec3> rolling_moments(const DemSystem& sys)
{
  std::map<std::pair<std::uint32_t, ParticleId>, Vec3> out;
  for (const ContactState& c : sys.export_contact_state())
    if (!c.wall) out[{c.i, c.j}] = c.memory.rolling;
  return out;
}

void rolling_pack(DemSystem& sys, bool reverse_ids = false)
{
  sys.set_contact_model(rolling_law(0.3));
  sys.set_friction(0.5);
  sys.set_gravity(Vec3(0, 0, -kG));
  if (reverse_ids) {
    DemSystem ref;
    test::fill_box(ref, 4, kR, 0.2, 5u, 0.3);
    test::add_renumbered_backwards(sys, ref, kR);
  } else {
    test::fill_box(sys, 4, kR, 0.2, 5u, 0.3);
  }
  sys.set_time_step(0.05 * std::sqrt(sphere_mass() / kK));
}
}  // namespace

TEST(RollingResistance, RollingSpringsKeepTheirSignWhenIdOrderOpposesStorageOrder)
{
  // The rolling moment acts on j and flips when i and j swap: numbering the pack
  // backwards makes the archive flip every loaded spring at every rebuild. The moments
  // must be those of the pack numbered forwards (to round-off).
  DemSystem fwd, rev;
  rolling_pack(fwd);
  rolling_pack(rev, true);
  fwd.run(3000);
  rev.run(3000);
  ASSERT_GT(rev.n_rebuilds(), 2u);
  const ParticleId n = ParticleId(fwd.n_particles());
  const auto mf = rolling_moments(fwd), mr = rolling_moments(rev);
  double largest = 0.0, worst = 0.0;
  for (const auto& [key, m] : mr) {
    // key = (lower, higher) id of the backwards numbering; forwards the roles swap.
    const auto it = mf.find({n - 1 - key.second, n - 1 - key.first});
    ASSERT_NE(it, mf.end());
    worst = std::max(worst, (it->second + m).norm());
    largest = std::max(largest, m.norm());
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-8 * largest);
}

TEST(RollingResistance, RollingSpringSurvivesRebuildsAndCheckpoints)
{
  DemSystem a, b;
  rolling_pack(a);
  rolling_pack(b);
  a.run(3000);
  b.run(3000);
  const auto before = rolling_moments(a);
  std::size_t loaded = 0;
  for (const auto& [key, m] : before) loaded += m.norm() > 0.0 ? 1 : 0;
  ASSERT_GT(loaded, 10u);
  // A forced rebuild carries every moment over by its stable key.
  b.request_rebuild();
  b.step();
  a.step();
  const auto ra = rolling_moments(a), rb = rolling_moments(b);
  ASSERT_EQ(ra.size(), rb.size());
  for (const auto& [key, m] : ra) {
    ASSERT_TRUE(rb.count(key));
    EXPECT_NEAR((rb.at(key) - m).norm(), 0.0, 1e-12 * (1.0 + m.norm()));
  }
  // A checkpoint read back continues bit for bit.
  std::stringstream state;
  a.write_state(state);
  DemSystem c;
  c.read_state(state);
  a.run(500);
  c.run(500);
  for (ParticleId id = 0; id < a.n_particles(); ++id) {
    EXPECT_EQ(a.position(id), c.position(id));
    EXPECT_EQ(a.angular_velocity(id), c.angular_velocity(id));
  }
  // Exported and re-imported contact state restores the moments (to the difference the
  // dashpots make: the fresh system's first forces see on-step velocities; a lost moment
  // would be off by 100 %).
  DemSystem d;
  rolling_pack(d);
  for (ParticleId id = 0; id < a.n_particles(); ++id) {
    d.set_position(id, a.position(id));
    d.set_velocity(id, a.velocity(id));
    d.set_angular_velocity(id, a.angular_velocity(id));
  }
  d.import_contact_state(a.export_contact_state());
  d.step();
  a.step();
  const auto rd = rolling_moments(d), ra2 = rolling_moments(a);
  double largest = 0.0;
  for (const auto& [key, m] : ra2) largest = std::max(largest, m.norm());
  std::size_t compared = 0;
  for (const auto& [key, m] : ra2)
    if (m.norm() > 0.1 * largest) {
      EXPECT_NEAR((rd.at(key) - m).norm(), 0.0, 1e-3 * m.norm());
      ++compared;
    }
  EXPECT_GT(compared, 5u);
}
