// Polar distributions of contact number and mean contact force (S2, Zhao & Chi 2022,
// Figs. 8-11): hand-placed contacts land in the bins the projection rules say, with the
// right counts and means, and the mechanical variant drops exactly the contacts of
// particles with 0 or 1 contacts; isotropic normals give flat roses in both planes; a
// uniaxially compressed random packing carries larger mean forces near the loading axis.
#include "dem/ContactPolarDistribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace geocomp::dem;
using CPD = ContactPolarDistribution;

namespace {
/// A particle-particle record with normal n (normalized) and normal force f.
ContactRecord pair(ParticleId i, ParticleId j, const Vec3& n, double f)
{
  ContactRecord c;
  c.i = i;
  c.j = j;
  c.normal = n.normalized();
  c.normal_force = f;
  c.force = f * c.normal;
  return c;
}

ContactRecord wall(std::uint32_t w, ParticleId j, const Vec3& n, double f)
{
  ContactRecord c = pair(w, j, n, f);
  c.wall = true;
  return c;
}

/// Bin index of a centre angle [deg] for 36 bins.
std::size_t bin(double deg) { return std::size_t(std::lround(deg / 10.0)) % 36; }

double deg(double d) { return d * M_PI / 180.0; }

/// S2's contact form (linear springs, ks/kn = 6/7, rolling mu_r = 0.7) with stiffness kn.
ContactModel s2_law(double kn)
{
  LinearRolling::Parameters rp;
  rp.mu_r = 0.7;
  return LinearRollingResistance(LinearNormal::with_stiffness(kn, 0.3), LinearTangential::with_ratio(6.0 / 7.0),
                                 LinearRolling(rp));
}

/// Mean normal stress on the six walls [Pa] of a box of edges L.
double wall_pressure(const DemSystem& sys, const Vec3& L)
{
  double p = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double area = L[(a + 1) % 3] * L[(a + 2) % 3];
    p += (std::fabs(sys.wall(2 * a).force[a]) + std::fabs(sys.wall(2 * a + 1).force[a])) / (2.0 * area);
  }
  return p / 3.0;
}
}  // namespace

TEST(ContactPolar, HandPlacedContactsLandInTheirProjectedBinsWithExactCountsAndMeans)
{
  // Particles 0, 1, 2 form a triangle, 3 hangs on 2; (1, 3) pulls (F_n < 0: not a contact).
  const double c20 = std::cos(deg(20)), s20 = std::sin(deg(20));
  const std::vector<ContactRecord> records = {
    pair(0, 1, Vec3(0, 0, 1), 10.0),                       // axial: vertical 0/180 (both planes), no x-y angle
    pair(1, 2, Vec3(1, 0, 0), 4.0),                        // x: x-y 0/180, x-z 90/270, no y-z angle
    pair(0, 2, Vec3(std::cos(deg(30)), std::sin(deg(30)), 0), 6.0),  // x-y 30/210; x-z and y-z 90/270
    pair(2, 3, Vec3(s20, 0, c20), 2.0),                    // x-y 0/180; x-z 20/200; y-z 0/180
    pair(1, 3, Vec3(0, 1, 0), -5.0),                       // tensile: ignored everywhere
    wall(4, 0, Vec3(0, 0, 1), 100.0)};                     // wall contact: not binned by default
  const CPD d = CPD::of(records);
  EXPECT_EQ(d.contacts(CPD::all), 4u);
  EXPECT_EQ(d.single_contact_particles(), 1u);  // particle 3 (its pull does not count)

  const PolarRose& h = d.rose(CPD::horizontal, CPD::all);
  EXPECT_DOUBLE_EQ(h.total(), 6.0);  // 3 contacts with an x-y angle, 2 ends each
  for (double a : {0.0, 180.0}) {
    EXPECT_DOUBLE_EQ(h.contacts[bin(a)], 2.0);
    EXPECT_DOUBLE_EQ(h.mean_force(bin(a)), 3.0);  // (4 + 2) / 2
  }
  for (double a : {30.0, 210.0}) {
    EXPECT_DOUBLE_EQ(h.contacts[bin(a)], 1.0);
    EXPECT_DOUBLE_EQ(h.mean_force(bin(a)), 6.0);
  }
  EXPECT_DOUBLE_EQ(h.contacts[bin(90)], 0.0);
  EXPECT_DOUBLE_EQ(h.mean_force(bin(90)), 0.0);

  const PolarRose& v = d.rose(CPD::vertical, CPD::all);
  EXPECT_DOUBLE_EQ(v.total(), 7.0);  // weight 1/2 per vertical plane and end: (4 + 2 + 4 + 4) / 2
  for (double a : {0.0, 180.0}) {
    EXPECT_DOUBLE_EQ(v.contacts[bin(a)], 1.5);                  // axial (1) + tilted in y-z (1/2)
    EXPECT_DOUBLE_EQ(v.mean_force(bin(a)), (10.0 + 1.0) / 1.5);  // (10 + 2/2) / 1.5
  }
  for (double a : {90.0, 270.0}) {
    EXPECT_DOUBLE_EQ(v.contacts[bin(a)], 1.5);  // x in x-z (1/2) + 30 deg in both planes (1)
    EXPECT_DOUBLE_EQ(v.mean_force(bin(a)), (2.0 + 6.0) / 1.5);
  }
  for (double a : {20.0, 200.0}) {
    EXPECT_DOUBLE_EQ(v.contacts[bin(a)], 0.5);
    EXPECT_DOUBLE_EQ(v.mean_force(bin(a)), 2.0);
  }
  EXPECT_DOUBLE_EQ(v.contacts[bin(340)], 0.0);  // the tilt has a side: 20 deg, not -20
  // Sectors within 30 deg of the axis and of the lateral direction.
  EXPECT_DOUBLE_EQ(v.sector(0, 30).contacts, 4.0);
  EXPECT_DOUBLE_EQ(v.sector(0, 30).mean_force, (10.0 + 1.0 + 1.0) * 2 / 4.0);
  EXPECT_DOUBLE_EQ(v.sector(90, 30).contacts, 3.0);

  // Mechanical: particle 3 has one contact, so (2, 3) goes; the others stay.
  EXPECT_EQ(d.contacts(CPD::mechanical), 3u);
  const PolarRose& hm = d.rose(CPD::horizontal, CPD::mechanical);
  EXPECT_DOUBLE_EQ(hm.contacts[bin(0)], 1.0);
  EXPECT_DOUBLE_EQ(hm.mean_force(bin(0)), 4.0);
  const PolarRose& vm = d.rose(CPD::vertical, CPD::mechanical);
  EXPECT_DOUBLE_EQ(vm.contacts[bin(0)], 1.0);
  EXPECT_DOUBLE_EQ(vm.contacts[bin(20)], 0.0);
  EXPECT_DOUBLE_EQ(vm.contacts[bin(90)], 1.5);

  // A wall under particle 3 gives it a second contact: (2, 3) is mechanical again; with
  // include_walls the wall contacts are binned (axial, 100 N and 7 N).
  std::vector<ContactRecord> with_wall = records;
  with_wall.push_back(wall(5, 3, Vec3(0, 0, 1), 7.0));
  EXPECT_EQ(CPD::of(with_wall).contacts(CPD::mechanical), 4u);
  EXPECT_EQ(CPD::of(with_wall).single_contact_particles(), 0u);
  CPD::Settings walls;
  walls.include_walls = true;
  const CPD dw = CPD::of(with_wall, walls);
  EXPECT_EQ(dw.contacts(CPD::all), 6u);
  EXPECT_DOUBLE_EQ(dw.rose(CPD::vertical, CPD::all).contacts[bin(0)], 3.5);
  EXPECT_DOUBLE_EQ(dw.rose(CPD::horizontal, CPD::all).total(), 6.0);  // vertical wall normals: no x-y angle

  // Other bin counts: 4 bins of 90 deg centred on the axes; odd counts are refused.
  CPD::Settings four;
  four.bins = 4;
  const CPD d4 = CPD::of(records, four);
  const PolarRose& v4 = d4.rose(CPD::vertical, CPD::all);
  EXPECT_DOUBLE_EQ(v4.contacts[0], 2.0);  // axial 1, tilted 20 deg in x-z 1/2, in y-z 1/2
  EXPECT_DOUBLE_EQ(v4.contacts[1], 1.5);
  EXPECT_DOUBLE_EQ(v4.angle_deg(1), 90.0);
  four.bins = 5;
  EXPECT_THROW(CPD::of(records, four), std::invalid_argument);
}

TEST(ContactPolar, IsotropicNormalsGiveFlatRosesInBothPlanes)
{
  // 20 000 normals uniform on the sphere, forces uniform in [0, 2] N independent of them.
  // A bin of a plane holds Binomial(C, 1/18) lines, 1111 +- 32 (vertical: two planes
  // averaged, less): 12 % is about four standard deviations.
  std::mt19937_64 rng(2022);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 2.0);
  std::vector<ContactRecord> records;
  const int C = 20000;
  for (int k = 0; k < C; ++k)
    records.push_back(pair(ParticleId(2 * k), ParticleId(2 * k + 1), Vec3(g(rng), g(rng), g(rng)), u(rng)));
  const CPD d = CPD::of(records);
  EXPECT_EQ(d.contacts(CPD::all), std::size_t(C));
  EXPECT_EQ(d.contacts(CPD::mechanical), 0u);  // every particle has one contact
  for (CPD::Plane p : {CPD::horizontal, CPD::vertical}) {
    const PolarRose& r = d.rose(p, CPD::all);
    EXPECT_NEAR(r.total(), 2.0 * C, 1e-9);
    const double uniform = 2.0 * C / 36.0;
    for (std::size_t k = 0; k < 36; ++k) {
      EXPECT_NEAR(r.contacts[k] / uniform, 1.0, 0.12) << to_string(p) << " bin " << r.angle_deg(k);
      EXPECT_NEAR(r.mean_force(k), 1.0, 0.10) << to_string(p) << " bin " << r.angle_deg(k);
      EXPECT_DOUBLE_EQ(r.contacts[k], r.contacts[(k + 18) % 36]);  // undirected lines
    }
    // Second-order anisotropy: standard deviation sqrt(2 / C) = 0.01.
    EXPECT_LT(r.contact_anisotropy(), 0.04) << to_string(p);
    EXPECT_LT(std::fabs(r.force_cos2()), 0.04) << to_string(p);
    EXPECT_NEAR(r.sector(0, 30).contacts / r.sector(90, 30).contacts, 1.0, 0.06) << to_string(p);
  }
}

TEST(ContactPolar, AxialCompressionConcentratesForceNearTheLoadingAxis)
{
  // 400 spheres, radii uniform in [8, 12] mm, placed at random at 0.75 of their size in a
  // box, grown frictionless to a jammed isotropic state of about 100 kPa, then compressed
  // by the lid (wall z+) to 2 % strain with friction 0.4: one-dimensional compression as in
  // S2's uniaxial test. S2's law with a softer kn = 2e5 N/m (overlap 1 % of d at 100 kPa:
  // the growth reaches the jammed state in 10^4 steps; with S2's 7e7 N/m the window of
  // packing fraction between loose and 100 kPa is 300 times narrower); density x100
  // (quasi-static mass scaling). Measured: axial/lateral mean force 1.02 -> 1.93, a_c
  // 0.047 -> 0.088, a_f 0.40, horizontal a 0.03; about 1.5 s.
  const int N = 400;
  const double R = 0.01, rho = 2650.0 * 100.0;
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> size(0.8 * R, 1.2 * R), unit(0.0, 1.0);
  std::vector<double> radii(N);
  double solid = 0.0;
  for (double& r : radii) {
    r = size(rng);
    solid += 4.0 / 3.0 * M_PI * r * r * r;
  }
  const double L = std::cbrt(solid / 0.62);
  const double s0 = 0.75;
  std::vector<Vec3> x;
  for (double r : radii) {
    const double a = s0 * r;
    for (int attempt = 0;; ++attempt) {
      ASSERT_LT(attempt, 100000);
      const Vec3 c(a + (L - 2 * a) * unit(rng), a + (L - 2 * a) * unit(rng), a + (L - 2 * a) * unit(rng));
      bool clear = true;
      for (std::size_t k = 0; k < x.size() && clear; ++k) clear = (x[k] - c).norm() > a + s0 * radii[k];
      if (clear) {
        x.push_back(c);
        break;
      }
    }
  }
  DemSystem sys;
  sys.set_contact_model(s2_law(2e5));
  sys.set_friction(0.0);
  sys.set_local_damping(0.7);
  for (int k = 0; k < N; ++k) sys.add_sphere(x[std::size_t(k)], s0 * radii[std::size_t(k)], rho);
  sys.add_box(Vec3::Zero(), Vec3::Constant(L), 0.0);
  sys.set_time_step(0.2 * sys.critical_time_step());
  const double p0 = 100e3;
  double scale = s0;
  std::vector<double> now(N);
  // Grow until the wall pressure, after 2000 steps of rest, holds at half the target or more
  // (a growing particle's collisions give transient wall forces).
  for (;;) {
    while (wall_pressure(sys, Vec3::Constant(L)) < p0) {
      ASSERT_LT(scale, 1.1);
      scale *= wall_pressure(sys, Vec3::Constant(L)) < 0.1 * p0 ? 1.0001 : 1.00001;
      for (int k = 0; k < N; ++k) now[std::size_t(k)] = scale * radii[std::size_t(k)];
      sys.set_radii(now);
      sys.step();
    }
    sys.run(2000);
    if (wall_pressure(sys, Vec3::Constant(L)) >= 0.5 * p0) break;
  }
  const CPD start = CPD::of(sys);
  const PolarRose& v0 = start.rose(CPD::vertical, CPD::all);
  const double ratio0 = v0.sector(0, 30).mean_force / v0.sector(90, 30).mean_force;

  sys.set_friction(0.4);
  sys.set_time_step(0.2 * sys.critical_time_step());
  const double strain = 0.02, speed = 0.005;
  sys.set_wall_velocity(5, Vec3(0, 0, -speed));
  sys.run(std::size_t(strain * L / speed / sys.time_step()));
  sys.set_wall_velocity(5, Vec3::Zero());
  const CPD end = CPD::of(sys);
  const PolarRose& v = end.rose(CPD::vertical, CPD::all);
  const PolarRose& h = end.rose(CPD::horizontal, CPD::all);
  const PolarRose::Sector axial = v.sector(0, 30), lateral = v.sector(90, 30);
  const double ratio = axial.mean_force / lateral.mean_force;
  std::cout << "contacts " << start.contacts(CPD::all) << " -> " << end.contacts(CPD::all) << " (mechanical "
            << end.contacts(CPD::mechanical) << "), vertical axial/lateral mean force " << ratio0 << " -> " << ratio
            << ", a_c " << v0.contact_cos2() << " -> " << v.contact_cos2() << ", a_f " << v.force_cos2()
            << ", horizontal a " << h.contact_anisotropy() << ", stress z " << sys.wall(5).force.z() / (L * L)
            << " Pa\n";

  EXPECT_GT(end.contacts(CPD::all), std::size_t(2 * N));  // a load-carrying network (Z > 4)
  EXPECT_NEAR(ratio0, 1.0, 0.15);                         // isotropic start
  EXPECT_GT(ratio, 1.5);                                  // S2 Fig. 11: larger near 0/180 deg
  EXPECT_GT(v.force_cos2(), 0.25);
  EXPECT_GT(v.contact_cos2(), v0.contact_cos2());         // S2 Fig. 9: contacts gather along the axis
  EXPECT_LT(h.contact_anisotropy(), 0.1);                 // S2 Fig. 8: isotropic horizontal plane
  EXPECT_LT(std::fabs(h.force_cos2()), 0.1);              // S2 Fig. 10
  for (CPD::Plane p : {CPD::horizontal, CPD::vertical})
    for (std::size_t k = 0; k < 36; ++k)
      EXPECT_LE(end.rose(p, CPD::mechanical).contacts[k], end.rose(p, CPD::all).contacts[k]);
  EXPECT_LE(end.contacts(CPD::mechanical), end.contacts(CPD::all));
}
