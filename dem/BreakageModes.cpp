#include "dem/BreakageModes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

BreakageMode parse_breakage_mode(const std::string& name)
{
  if (name == "cube") return BreakageMode::cube;
  if (name == "4-ball") return BreakageMode::four_ball;
  if (name == "18-ball") return BreakageMode::eighteen_ball;
  throw std::invalid_argument("unknown breakage mode '" + name + "' (expected cube, 4-ball or 18-ball)");
}

std::string to_string(BreakageMode m)
{
  switch (m) {
    case BreakageMode::cube: return "cube";
    case BreakageMode::four_ball: return "4-ball";
    case BreakageMode::eighteen_ball: return "18-ball";
  }
  return "?";
}

namespace {
double uniform(std::mt19937_64& rng) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }

/// A uniformly random rotation (Shoemake's method), from three draws.
Eigen::Matrix3d random_rotation(std::mt19937_64& rng)
{
  const double u1 = uniform(rng), u2 = uniform(rng), u3 = uniform(rng);
  const double s1 = std::sqrt(1.0 - u1), s2 = std::sqrt(u1);
  const Quat q(s2 * std::cos(2.0 * M_PI * u3), s1 * std::sin(2.0 * M_PI * u2), s1 * std::cos(2.0 * M_PI * u2),
               s2 * std::sin(2.0 * M_PI * u3));
  return q.normalized().toRotationMatrix();
}

/// Children radii `r` on unit directions `dirs`, internally tangent to the parent.
Fragment child(const ParentSphere& p, const Vec3& dir, double r) { return {p.centre + (p.radius - r) * dir, r, p.density}; }

double cube(double x) { return x * x * x; }

/// Drops children below d_M; with `transfer` their volume goes to the smallest valid
/// child (re-placed tangent on its direction), else it is lost.
Fragmentation apply_minimum_size(const ParentSphere& p, const std::vector<Vec3>& dirs, std::vector<double> radii,
                                 double minimum_size, bool transfer, double lost_volume)
{
  Fragmentation out;
  out.lost_volume = lost_volume;
  double dropped_r3 = 0.0;
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (2.0 * radii[i] < minimum_size) {
      dropped_r3 += cube(radii[i]);
      ++out.dropped;
    } else {
      valid.push_back(i);
    }
  }
  if (valid.empty()) return Fragmentation{};  // nothing valid: the parent stays whole
  if (dropped_r3 > 0.0) {
    if (transfer) {
      const std::size_t s = *std::min_element(valid.begin(), valid.end(),
                                              [&](std::size_t a, std::size_t b) { return radii[a] < radii[b]; });
      radii[s] = std::cbrt(cube(radii[s]) + dropped_r3);  // S2 section 2.2: mass to the smallest valid child
    } else {
      out.lost_volume += 4.0 / 3.0 * M_PI * dropped_r3;
    }
  }
  for (std::size_t i : valid) out.children.push_back(child(p, dirs[i], radii[i]));
  return out;
}
}  // namespace

std::vector<double> cube_fractions(double a, double b, double c)
{
  std::vector<double> k(8);
  for (int i = 0; i < 8; ++i)
    k[i] = ((i & 1) ? 1.0 - a : a) * ((i & 2) ? 1.0 - b : b) * ((i & 4) ? 1.0 - c : c);  // S2 eq. (1)
  return k;
}

Fragmentation cube_replacement(const ParentSphere& p, int cut_power, double minimum_size, std::mt19937_64& rng)
{
  if (cut_power < 1 || cut_power > 3) throw std::invalid_argument("cube_replacement: cut power must be 1, 2 or 3");
  const double a = std::pow(uniform(rng), cut_power);
  const double b = std::pow(uniform(rng), cut_power);
  const double c = std::pow(uniform(rng), cut_power);
  const std::vector<double> k = cube_fractions(a, b, c);
  std::vector<Vec3> dirs(8);
  std::vector<double> radii(8);
  for (int i = 0; i < 8; ++i) {
    dirs[i] = Vec3((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0) / std::sqrt(3.0);
    radii[i] = p.radius * std::cbrt(k[i]);  // S2 eq. (2)
  }
  return apply_minimum_size(p, dirs, radii, minimum_size, true, 0.0);
}

Fragmentation four_ball(const ParentSphere& p, double minimum_size, std::mt19937_64& rng)
{
  const Eigen::Matrix3d Q = random_rotation(rng);
  const double s = 1.0 / std::sqrt(3.0);
  const std::array<Vec3, 4> tetra = {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s), Vec3(-s, -s, s)};
  std::vector<Vec3> dirs;
  for (const Vec3& d : tetra) dirs.push_back(Q * d);
  const double r = p.radius * std::cbrt(0.25);  // 4 r^3 = R0^3: mass conserved
  return apply_minimum_size(p, dirs, std::vector<double>(4, r), minimum_size, true, 0.0);
}

std::pair<double, double> eighteen_ball_ratios()
{
  const double r1 = 1.0 / (1.0 + std::sqrt(2.0));
  // Edge sphere r on direction e = (1,1,0)/sqrt2 (unit parent): its distance to the axial
  // centre (1-r1) x and to the neighbour edge sphere (1-r)(1,0,1)/sqrt2 must be >= the sum of
  // radii. Both gaps fall as r grows: bisection on the smaller one.
  const Vec3 e = Vec3(1.0, 1.0, 0.0).normalized(), f = Vec3(1.0, 0.0, 1.0).normalized();
  auto gap = [&](double r) {
    const double axial = ((1.0 - r) * e - (1.0 - r1) * Vec3::UnitX()).norm() - (r + r1);
    const double edge = ((1.0 - r) * e - (1.0 - r) * f).norm() - 2.0 * r;
    return std::min(axial, edge);
  };
  double lo = 0.0, hi = r1;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) >= 0.0 ? lo : hi) = mid;
  }
  return {r1, lo};
}

Fragmentation eighteen_ball(const ParentSphere& p, double minimum_size, std::mt19937_64& rng)
{
  const Eigen::Matrix3d Q = random_rotation(rng);
  const auto [r1, r2] = eighteen_ball_ratios();
  std::vector<Vec3> dirs;
  std::vector<double> radii;
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      dirs.push_back(Q * (s * Vec3::Unit(a)));
      radii.push_back(r1 * p.radius);
    }
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0})
      for (double t : {-1.0, 1.0}) {
        Vec3 d = Vec3::Zero();
        d[(a + 1) % 3] = s;
        d[(a + 2) % 3] = t;
        dirs.push_back(Q * d.normalized());
        radii.push_back(r2 * p.radius);
      }
  const double lost = 4.0 / 3.0 * M_PI * cube(p.radius) * (1.0 - 6.0 * cube(r1) - 12.0 * cube(r2));
  return apply_minimum_size(p, dirs, radii, minimum_size, false, lost);
}

Fragmentation fragment(const ParentSphere& parent, const FragmentRules& rules, std::mt19937_64& rng)
{
  if (!(parent.radius > 0.0) || !(parent.density > 0.0)) throw std::invalid_argument("fragment: bad parent");
  if (2.0 * parent.radius < rules.breakage_limit) return Fragmentation{};  // below d_L: never breaks
  switch (rules.mode) {
    case BreakageMode::cube: return cube_replacement(parent, rules.cut_power, rules.minimum_size, rng);
    case BreakageMode::four_ball: return four_ball(parent, rules.minimum_size, rng);
    case BreakageMode::eighteen_ball: return eighteen_ball(parent, rules.minimum_size, rng);
  }
  return Fragmentation{};
}

}  // namespace geocomp::dem
