// Clumps (S3, S4): voxel mass properties against closed forms, torque-free motion
// conserving angular momentum and energy, no contacts inside a clump, and S4's
// lognormal grain masses.
#include "dem/ClumpGenerator.h"
#include "dem/ClumpMassProperties.h"
#include "dem/DemSystem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace geocomp::dem;

namespace {
/// Quadrature of a solid of revolution about x with section radius r(x): volume,
/// centroid, axial inertia and transverse inertia about the centroid (unit density).
struct Revolution
{
  double volume = 0.0, centroid = 0.0, axial = 0.0, transverse = 0.0;
};

template <class Radius>
Revolution revolve(Radius r, double a, double b, int n = 200000)
{
  Revolution s;
  double sx = 0.0, sxx = 0.0, sr4 = 0.0;
  const double h = (b - a) / n;
  for (int k = 0; k < n; ++k) {  // midpoint rule
    const double x = a + (k + 0.5) * h, q = r(x), a2 = M_PI * q * q * h;
    s.volume += a2;
    sx += a2 * x;
    sxx += a2 * x * x;
    sr4 += a2 * q * q;
  }
  s.centroid = sx / s.volume;
  s.axial = 0.5 * sr4;                                            // disks: m r^2 / 2
  s.transverse = 0.25 * sr4 + sxx - s.volume * s.centroid * s.centroid;  // m r^2 / 4 + m x^2
  return s;
}
}  // namespace

TEST(ClumpMassProperties, SingleSphereMatchesClosedFormWithinVoxelError)
{
  const double R = 0.013;
  // S4: cubes of side D/20 give "> 97 %" accuracy, the voxel error we hold it to.
  const ClumpMassProperties p = voxel_mass_properties({{Vec3(0.1, -0.2, 0.3), R}});
  const double V = 4.0 / 3.0 * M_PI * R * R * R;
  EXPECT_NEAR(p.volume / V, 1.0, 0.03);
  EXPECT_LT((p.centroid - Vec3(0.1, -0.2, 0.3)).norm(), 1e-3 * R);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.principal_moments[k] / (0.4 * V * R * R), 1.0, 0.03);
  EXPECT_NEAR(p.axes.determinant(), 1.0, 1e-12);
  // The error shrinks with the cube (first order in h): at D/80 a quarter of it.
  const ClumpMassProperties fine = voxel_mass_properties({{Vec3(0.1, -0.2, 0.3), R}}, 2.0 * R / 80.0);
  EXPECT_LT(std::abs(fine.volume / V - 1.0), 0.3 * std::abs(p.volume / V - 1.0) + 1e-4);
  EXPECT_NEAR(fine.principal_moments[0] / (0.4 * V * R * R), 1.0, 0.0075);
}

TEST(ClumpMassProperties, TwoEqualOverlappingSpheresMatchLensVolumeAndRevolutionInertia)
{
  const double R = 0.01, d = 1.2 * R;  // overlap 0.8 R
  const std::vector<ClumpMember> m{{Vec3::Zero(), R}, {Vec3(d, 0, 0), R}};
  const ClumpMassProperties p = voxel_mass_properties(m);
  const double V = 2.0 * (4.0 / 3.0 * M_PI * R * R * R) - lens_volume(R, R, d);  // union
  EXPECT_NEAR(p.volume / V, 1.0, 0.03);  // S4's voxel error at D/20
  EXPECT_LT((p.centroid - Vec3(0.5 * d, 0, 0)).norm(), 1e-3 * R);
  // Inertia of the union as a solid of revolution about the x axis.
  const auto section = [&](double x) {
    const double a = R * R - x * x, b = R * R - (x - d) * (x - d);
    return std::sqrt(std::max({a, b, 0.0}));
  };
  const Revolution s = revolve(section, -R, d + R);
  EXPECT_NEAR(s.volume / V, 1.0, 1e-6);  // the quadrature agrees with the lens formula
  EXPECT_NEAR(p.principal_moments[0] / s.axial, 1.0, 0.03);  // smallest: about the axis
  EXPECT_NEAR(p.principal_moments[1] / s.transverse, 1.0, 0.03);
  EXPECT_NEAR(p.principal_moments[2] / s.transverse, 1.0, 0.03);
  EXPECT_NEAR(std::abs(p.axes.col(0).x()), 1.0, 1e-9);  // principal axis along the line of centres
  // Summing the two spheres would count the lens twice: far outside the voxel error.
  EXPECT_GT(lens_volume(R, R, d) / V, 0.1);
  // Finer cubes converge on the closed forms.
  const ClumpMassProperties fine = voxel_mass_properties(m, 2.0 * R / 80.0);
  EXPECT_NEAR(fine.volume / V, 1.0, 0.0075);
  EXPECT_NEAR(fine.principal_moments[0] / s.axial, 1.0, 0.0075);
  EXPECT_NEAR(fine.principal_moments[2] / s.transverse, 1.0, 0.0075);
}

namespace {
/// An asymmetric clump: three unequal spheres, not collinear.
std::vector<ClumpMember> asymmetric_members(const Vec3& at)
{
  return {{at + Vec3(0, 0, 0), 0.010}, {at + Vec3(0.013, 0.002, 0), 0.007}, {at + Vec3(0.003, 0.011, 0.004), 0.005}};
}
}  // namespace

TEST(Clump, TorqueFreeAsymmetricClumpConservesAngularMomentumAndKineticEnergy)
{
  DemSystem sys;
  const Vec3 w0(30.0, -50.0, 80.0);  // not along a principal axis: the body tumbles
  const std::size_t c = sys.add_clump(asymmetric_members(Vec3::Zero()), 2650.0, Vec3(0.1, 0, 0), w0);
  const ClumpSet& cl = sys.clumps();
  const Vec3 I = cl.inertia[c];
  ASSERT_GT((I[2] - I[1]) / I[2], 0.05);  // really asymmetric
  ASSERT_GT((I[1] - I[0]) / I[2], 0.05);
  sys.set_time_step(2e-6);  // |w| dt ~ 2e-4
  const Vec3 L0 = cl.angular_momentum(c);
  const double E0 = sys.energy().kinetic();
  double max_dw = 0.0;
  for (int block = 0; block < 100; ++block) {
    sys.run(500);
    const Vec3 L = cl.angular_momentum(c);
    EXPECT_LT((L - L0).norm() / L0.norm(), 1e-10);
    EXPECT_NEAR(sys.energy().kinetic() / E0, 1.0, 1e-6);
    max_dw = std::max(max_dw, (cl.angular_velocity(c) - w0).norm() / w0.norm());
  }
  EXPECT_GT(max_dw, 0.1);  // the angular velocity did change: Euler's equations at work
  // Members move rigidly: distances to the centre of mass are kept.
  const auto ids = sys.clump_members(c);
  const auto ref = asymmetric_members(Vec3::Zero());
  const ClumpMassProperties p = voxel_mass_properties(ref);
  for (std::size_t k = 0; k < ids.size(); ++k)
    EXPECT_NEAR((sys.position(ids[k]) - cl.x[c]).norm(), (ref[k].centre - p.centroid).norm(), 1e-12);
  EXPECT_NEAR((cl.x[c] - p.centroid).x(), 0.1 * sys.time(), 1e-12);
}

TEST(Clump, ContactsOnlyBetweenMembersOfDifferentClumps)
{
  DemSystem sys;
  sys.set_contact_model(LinearSpringDashpot(LinearNormal::with_stiffness(1e4, 0.8), LinearTangential::with_ratio(2.0 / 7.0)));
  sys.set_friction(0.3);
  // Two clumps whose members overlap inside each clump, thrown at each other.
  const std::size_t a = sys.add_clump(asymmetric_members(Vec3(0, 0, 0)), 2650.0, Vec3(0.5, 0, 0), Vec3(0, 0, 20));
  const std::size_t b = sys.add_clump(asymmetric_members(Vec3(0.04, 0.003, 0)), 2650.0, Vec3(-0.5, 0, 0));
  sys.set_time_step(2e-6);
  const auto body_of = [&](ParticleId id) { return sys.particles().body[sys.index_of(id)]; };
  const ClumpSet& cl = sys.clumps();
  const Vec3 p0 = cl.mass[a] * cl.v[a] + cl.mass[b] * cl.v[b];
  std::size_t touching = 0;
  for (int s = 0; s < 40000; ++s) {
    sys.step();
    for (const ContactRecord& c : sys.contacts()) {
      ASSERT_FALSE(c.wall);
      ASSERT_NE(body_of(c.i), body_of(c.j)) << "contact inside one clump";
      ++touching;
    }
  }
  EXPECT_GT(touching, 100u);  // they did collide
  for (const auto& s : sys.contact_lists().pairs)
    EXPECT_NE(sys.particles().body[s.i], sys.particles().body[s.j]);
  // The collision exchanged momentum and conserved it.
  const Vec3 p1 = cl.mass[a] * cl.v[a] + cl.mass[b] * cl.v[b];
  EXPECT_LT((p1 - p0).norm(), 1e-12 * cl.mass[a] * 0.5);
  EXPECT_LT(cl.v[a].x(), 0.4);
}

TEST(ClumpGeneration, S4TemplatesGiveTruncatedLognormalMassesAndExactVoxelMass)
{
  ClumpGenerationParameters p;
  const auto grains = generate_s4_clumps(4000, p, 7u);
  double s = 0.0, s2 = 0.0;
  int per_template[4] = {0, 0, 0, 0};
  for (const ClumpShape& g : grains) {
    ASSERT_GE(g.mass, p.mass_min);
    ASSERT_LE(g.mass, p.mass_max);
    const double l = std::log(g.mass / 1e-3);
    s += l;
    s2 += l * l;
    ++per_template[g.template_index];
    EXPECT_EQ(g.members.size(), g.template_index == 1 || g.template_index == 2 ? 3u : 2u);
  }
  const double n = double(grains.size()), mean = s / n, sd = std::sqrt(s2 / n - mean * mean);
  // Moments of N(mu, sigma) truncated to [ln 0.4, ln 2.0].
  const double mu = p.log_mass_mean, sg = p.log_mass_sigma;
  const double a = (std::log(0.4) - mu) / sg, b = (std::log(2.0) - mu) / sg;
  const auto phi = [](double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI); };
  const auto Phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  const double Z = Phi(b) - Phi(a);
  const double t_mean = mu + sg * (phi(a) - phi(b)) / Z;
  const double t_var = sg * sg * (1.0 + (a * phi(a) - b * phi(b)) / Z - std::pow((phi(a) - phi(b)) / Z, 2));
  EXPECT_NEAR(mean, t_mean, 4.0 * std::sqrt(t_var / n));
  EXPECT_NEAR(sd, std::sqrt(t_var), 0.03 * std::sqrt(t_var));
  for (int t = 0; t < 4; ++t) EXPECT_NEAR(per_template[t] / n, 0.25, 0.03);
  // The voxel mass of a generated grain is its drawn mass.
  for (std::size_t k = 0; k < 20; ++k)
    EXPECT_NEAR(p.density * voxel_mass_properties(grains[k].members).volume / grains[k].mass, 1.0, 1e-9);
  // Placement: bounding spheres apart, a clump system can be built from it.
  const double L = 0.1;
  const auto placed = place_clumps(std::vector<ClumpShape>(grains.begin(), grains.begin() + 200), Vec3::Zero(),
                                   Vec3::Constant(L), 0.5, 3u);
  DemSystem sys;
  for (const auto& members : placed) sys.add_clump(members, p.density);
  sys.set_time_step(1e-6);
  sys.step();
  EXPECT_EQ(sys.n_touching_pairs(), 0u);
  EXPECT_EQ(sys.n_clumps(), 200u);
}
