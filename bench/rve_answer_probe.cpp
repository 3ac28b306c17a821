// geocomp-bench-rve-answer: how smooth is a cell's answer to a strain increment? (issue 35;
// docs/coupled.md, "The cells' answer near the floor"). The FE Newton of the fem-dem engine
// re-runs every cell from its committed state at each iterate (coupled/RveMaterial.h); how
// far it can lower the residual depends on how the cell's stress at the end of the n steps
// varies with the increment. This program prepares the case's RVE, shears it in plane strain
// (x at the case's pressure by the cell's servo, y fixed, z shortened by one sample of the
// first stage's z rate per `steps per increment` steps: the biaxial case's program in one cell) and, at every
// committed increment de, drives copies kinematically as RveMaterial does, by de and by
// de +- d |de| D (its velocity gradient RveMaterial::finite_velocity_gradient of the cell matrices'
// increment; D a fixed random symmetric unit direction, d = 1e-1, 1e-2, 1e-3). Per d it
// writes the first difference |s(+) - s(-)| / 2p (the linear answer) and the second
// difference |s(+) + s(-) - 2 s(0)| / p (zero for a linear map, O(d^2) for a smooth one; a
// kink or noise shows as O(d) or O(1)), each for three readings of the stress: the end of the
// n steps (what RveMaterial returns), the mean of the last m steps, and the end value of the
// least-squares line through them.
//
// usage: geocomp-bench-rve-answer <case.prm> <increments> <window m> <output.csv>
// Exit 2 on bad arguments (nothing written), 1 when the preparation fails (the file says so).
#include "compare/case/CaseDescription.h"
#include "coupled/RveMaterial.h"
#include "coupled/RvePreparation.h"
#include "coupled/case/RveSection.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace geocomp;

namespace {

struct Readings {
  dem::Mat3 end, mean, fit;
};

/// The cell's stress over the last m of n steps at the constant velocity gradient l.
Readings drive(dem::PeriodicCell cell, const dem::Mat3 &l, int n, int m)
{
  cell.set_velocity_gradient(l);
  std::vector<dem::Mat3> s;
  s.reserve(std::size_t(m));
  for (int k = 0; k < n; ++k) {
    cell.step();
    if (k >= n - m)
      s.push_back(cell.stress().total());
  }
  Readings r{s.back(), dem::Mat3::Zero(), dem::Mat3::Zero()};
  for (const dem::Mat3 &x : s)
    r.mean += x / double(m);
  const double kbar = 0.5 * (m - 1);
  double sxx = 0.0;
  dem::Mat3 sxy = dem::Mat3::Zero();
  for (int k = 0; k < m; ++k) {
    sxx += (k - kbar) * (k - kbar);
    sxy += (k - kbar) * (s[k] - r.mean);
  }
  r.fit = r.mean + sxy / sxx * (m - 1 - kbar);
  return r;
}

} // namespace

int main(int argc, char **argv)
{
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s <case.prm> <increments> <window m> <output.csv>\n", argv[0]);
    return 2;
  }
  CaseDescription c;
  coupled::RveGrains grains;
  coupled::RvePreparationSettings settings;
  int increments = 0, m = 0;
  try {
    c = read_case(argv[1]);
    grains = coupled::rve_grains(c);
    settings = coupled::rve_settings(c, c.rve);
    increments = std::stoi(argv[2]);
    m = std::stoi(argv[3]);
    if (c.program.stages.empty() || !c.program.stages.front().kinematic(2))
      throw std::invalid_argument("the case's first stage must drive z kinematically");
    if (increments < 1 || m < 2 || m > int(c.rve.steps_per_increment))
      throw std::invalid_argument("increments >= 1 and 2 <= m <= steps per increment");
  } catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::ofstream out(argv[4]);
  if (!out) {
    std::fprintf(stderr, "error: cannot write %s\n", argv[4]);
    return 2;
  }
  std::unique_ptr<dem::PeriodicCell> prepared;
  try {
    prepared = std::make_unique<dem::PeriodicCell>(coupled::prepare_rve(grains, settings));
  } catch (const std::exception &e) {
    out << "# status=failed: " << e.what() << "\n";
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  dem::PeriodicCell &cell = *prepared;
  const int n = int(c.rve.steps_per_increment);
  const double p = settings.pressure, dt = cell.parameters().time_step;
  const double de = c.program.sample_interval * std::abs(c.program.stages.front().axes[2].value);
  cell.control().set_parameters(dem::MixedControl::Parameters{0.2, 30.0}); // the servo follows 8 /s
  cell.control().set_velocity_gradient(dem::Mat3::Zero());
  cell.control().set_stress(0, 0, -p);
  cell.control().set_strain_rate(2, 2, -de / (n * dt));
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  dem::Mat3 dir;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      dir(a, b) = normal(rng);
  dir = 0.5 * (dir + dir.transpose()) / (0.5 * (dir + dir.transpose())).norm();
  out << "# case=" << argv[1] << " particles=" << settings.particles << " steps=" << n << " window=" << m
      << " increment=" << de << " pressure=" << p << "\n";
  out << "axial_strain,stress_ratio,d,first,second_end,second_mean,second_fit\n";
  for (int inc = 1; inc <= increments; ++inc) {
    const dem::PeriodicCell committed = cell;
    cell.run(std::uint64_t(n));
    const dem::Mat3 s = cell.stress().total();
    // The increment the servo took, H_{n+1} H_n^-1, as the fem-dem engine would drive it.
    const dem::Mat3 l = coupled::RveMaterial::finite_velocity_gradient(
        cell.cell().h() * committed.cell().inverse(), std::uint64_t(n), dt);
    const Readings zero = drive(committed, l, n, m);
    for (double d : {1e-1, 1e-2, 1e-3}) {
      const dem::Mat3 dl = d * l.norm() * dir;
      const Readings a = drive(committed, l + dl, n, m), b = drive(committed, l - dl, n, m);
      out << inc * de << ',' << (s(0, 0) - s(2, 2)) / cell.stress().pressure() << ',' << d << ','
          << (a.end - b.end).norm() / (2 * p) << ',' << (a.end + b.end - 2 * zero.end).norm() / p << ','
          << (a.mean + b.mean - 2 * zero.mean).norm() / p << ',' << (a.fit + b.fit - 2 * zero.fit).norm() / p
          << '\n';
    }
  }
  if (!out) {
    std::fprintf(stderr, "error: cannot write %s\n", argv[4]);
    return 1;
  }
  return 0;
}
