// S3 bonds in a specimen with a closed form: a simple-cubic lattice of equal spheres, every
// touching pair bonded (S3 eq. (8)), its end rows bonded to the z walls, pulled apart along
// z. Each of the n x n columns fails when its first grain bond reaches |e| = eps*, carrying
// the largest bond force C_c r_ij^2 = C_c R^2 (r_ij = 2R* = R); over the column's
// cross-section (2R)^2 the tensile strength is sigma_t = C_c / 4, whatever E_c. A wall bond
// (r_ij = 2R) is four times as strong, so the lattice fails inside.
#include "dem/DemSystem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

using namespace geocomp::dem;

namespace {
constexpr double kR = 0.005, kKn = 5e6, kDensity = 2650.0;
constexpr int kN = 3, kLayers = 4;
constexpr double kDelta0 = 1e-3 * kR; // initial overlap of each bonded pair

struct Pull {
  double peak_stress = 0.0;   ///< [Pa] largest tensile stress on the top wall
  double final_stress = 0.0;  ///< [Pa] at the end of the pull
};

/// The lattice bonded at its start, top wall pulled up at speed v until the gap is opened
/// by `opening` (m); the stress is the top wall's force over the lattice's cross-section.
Pull pull_lattice(double cohesion, double cohesion_modulus, double v, double opening)
{
  DemSystem sys;
  S3Bonding::Parameters b;
  b.cohesion = cohesion;
  b.cohesion_modulus = cohesion_modulus;
  sys.set_contact_model(LinearCohesive(LinearNormal::with_stiffness(kKn, 0.3), LinearTangential::with_ratio(2.0 / 7.0),
                                       LinearRolling({0.0, 1.0}), S3Bonding(b)));
  const double a = 2.0 * kR - kDelta0;  // lattice spacing
  const double side = kN * 2.0 * kR;
  // Lateral walls well clear of the lattice (they neither touch nor bond); the z walls
  // overlap the end rows by delta0 / 2.
  const double z1 = kR - 0.5 * kDelta0, height = 2.0 * z1 + (kLayers - 1) * a;
  sys.add_box(Vec3(-side, -side, 0.0), Vec3(2.0 * side, 2.0 * side, height), 0.0);
  for (int k = 0; k < kLayers; ++k)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i)
        sys.add_sphere(Vec3(kR + i * a, kR + j * a, z1 + k * a), kR, kDensity);
  sys.set_friction(0.5);
  sys.set_wall_bonding(true);
  sys.set_local_damping(0.3);
  sys.set_time_step(0.1 * sys.critical_time_step());
  const std::size_t top = 5;  // z+ wall of add_box
  sys.set_wall_velocity(top, Vec3(0.0, 0.0, v));
  const double area = std::pow(kN * a, 2);
  Pull p;
  const double z0 = sys.wall(top).point.z();
  while (sys.wall(top).point.z() - z0 < opening) {
    sys.step();
    const double stress = sys.wall(top).force.z() / area;  // particles pull the top wall down: < 0 in tension
    p.peak_stress = std::max(p.peak_stress, -stress);
    p.final_stress = -stress;
  }
  return p;
}
}  // namespace

TEST(BondedLattice, TensileStrengthIsAQuarterOfTheBondStrengthCc)
{
  const double cc = 1e6, ec = 5e7;
  const double eps = kR * cc / ec;  // S3 eq. (8): eps* = r_ij C_c / E_c, r_ij = R
  // Slow against the lattice's waves (a bond stretches over ~100 steps of its own period).
  const Pull p = pull_lattice(cc, ec, 0.01, 2.0 * kLayers * eps);
  EXPECT_NEAR(p.peak_stress, cc / 4.0, 0.05 * cc / 4.0);
  EXPECT_LT(std::abs(p.final_stress), 0.01 * cc / 4.0) << "all columns broken: nothing carries tension";
}

TEST(BondedLattice, TensileStrengthDoublesWithCcButNotWithTheBondModulus)
{
  const double ec = 5e7;
  const Pull weak = pull_lattice(1e6, ec, 0.01, 2.0 * kLayers * kR * 1e6 / ec);
  const Pull strong = pull_lattice(2e6, ec, 0.01, 2.0 * kLayers * kR * 2e6 / ec);
  const Pull stiff = pull_lattice(1e6, 2.0 * ec, 0.01, 2.0 * kLayers * kR * 1e6 / ec);
  EXPECT_NEAR(strong.peak_stress / weak.peak_stress, 2.0, 0.1);
  EXPECT_NEAR(stiff.peak_stress / weak.peak_stress, 1.0, 0.05);
}

TEST(BondedLattice, AWallOutsideTheBondingMaskNeitherBondsNorGrips)
{
  // Direct tension bonds the platens only (`bonding walls = z`): a sphere touching the x- and
  // z- walls, pulled away from both, is held by the z- wall's bond and let go by the x- wall.
  DemSystem sys;
  S3Bonding::Parameters b;
  b.cohesion = 1e6;
  b.cohesion_modulus = 5e7;
  sys.set_contact_model(LinearCohesive(LinearNormal::with_stiffness(kKn, 1.0), LinearTangential::with_ratio(2.0 / 7.0),
                                       LinearRolling({0.0, 1.0}), S3Bonding(b)));
  sys.add_box(Vec3::Zero(), Vec3::Constant(0.1), 0.0);
  const double d0 = 1e-3 * kR;
  sys.add_sphere(Vec3(kR - d0, 0.05, kR - d0), kR, 1e15);  // so heavy that its velocity stays as set
  sys.set_wall_bonding(true);
  sys.set_bonding_walls(0b110000);  // walls 4, 5: z-, z+
  sys.set_time_step(1e-6);
  const double eps = 2.0 * kR * b.cohesion / b.cohesion_modulus;  // wall bond: r_ij = 2R
  sys.set_velocity(0, Vec3(0.01, 0.0, 0.01));
  while (sys.position(0).z() < kR + 0.5 * eps)
    sys.step();
  const double kc = b.cohesion_modulus * 2.0 * kR;
  EXPECT_NEAR(sys.wall(4).force.z(), kc * (sys.position(0).z() - kR + d0), 0.02 * kc * eps)
    << "the z- wall's bond pulls its wall along +z (S3 eq. (8))";
  EXPECT_EQ(sys.wall(0).force.norm(), 0.0) << "the x- wall does not bond";
}

TEST(BondedLattice, TheWallsThatBondSurviveACheckpoint)
{
  DemSystem sys;
  sys.add_box(Vec3::Zero(), Vec3::Constant(0.1), 0.0);
  sys.add_sphere(Vec3::Constant(0.05), kR, kDensity);
  sys.set_wall_bonding(true);
  sys.set_bonding_walls(0b110000);
  std::stringstream state;
  sys.write_state(state);
  DemSystem back;
  back.read_state(state);
  EXPECT_EQ(back.bonding_walls(), std::uint64_t(0b110000));
}
