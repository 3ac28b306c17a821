#pragma once
// Mohr-Coulomb returns built backwards from their answer: pick the returned stress on
// the plane, an edge or the apex of the yield surface at kappa_{n+1} and non-negative
// multipliers, then s_tr = s + D_hat sum dgamma_b g_b(psi(kappa_{n+1})). With
// `coincident` the multipliers are split evenly so that two (edges) or three (apex,
// elastic) trial eigenvalues coincide.
#include "ContinuumTestSupport.h"

#include "continuum/models/MohrCoulombReturnMap.h"

namespace geocomp::continuum::testing {

struct Constructed {
  Vector3 trial, stress; // principal, slots as constructed (not necessarily sorted)
  ReturnRegion region;
  double kappa_n, kappa_new;
};

// A trial state whose exact return is known.
inline Constructed construct(const MohrCoulombReturnMap &map, ReturnRegion region, double kappa_n,
                             double dkappa, std::mt19937_64 &rng, bool coincident = false) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double k1 = kappa_n + dkappa;
  const MohrCoulombStrength st = map.strength(k1);
  const double sphi = std::sin(st.phi), cphi = std::cos(st.phi);
  const double apex = st.c * cphi / sphi;
  const Matrix3 D = map.elasticity().principal_stiffness();
  // On the 1-3 plane: s1 = (2 c cos phi + s3 (1 - sin phi)) / (1 + sin phi), s3 below the apex.
  const double s3 = apex - st.c * (0.2 + 30.0 * U(rng));
  const double s1 = (2.0 * st.c * cphi + s3 * (1.0 - sphi)) / (1.0 + sphi);
  auto g = [&](int i, int j) { return MohrCoulombReturnMap::flow_generator(i, j, st.psi); };
  Constructed c{Vector3::Zero(), Vector3::Zero(), region, kappa_n, k1};
  const double x = dkappa / 2.0; // sum of multipliers
  const double r = coincident ? 0.5 : 0.1 + 0.8 * U(rng);
  switch (region) {
  case ReturnRegion::elastic: {
    // Inside the surface at kappa_n (kappa does not change).
    const MohrCoulombStrength s0 = map.strength(kappa_n);
    const double sp = std::sin(s0.phi), cp = std::cos(s0.phi), a0 = s0.c * cp / sp;
    const double q3 = a0 - s0.c * (0.2 + 30.0 * U(rng));
    const double q1 = (2.0 * s0.c * cp + q3 * (1.0 - sp)) / (1.0 + sp);
    c.stress = Vector3(q1, q3 + U(rng) * (q1 - q3), q3);
    const double shrink = coincident ? 0.0 : 0.05 + 0.9 * U(rng); // pull towards a point inside
    const Vector3 inside = Vector3::Constant(a0 - s0.c);
    c.trial = c.stress = inside + shrink * (c.stress - inside);
    c.kappa_new = kappa_n;
    return c;
  }
  case ReturnRegion::plane:
    c.stress = Vector3(s1, s3 + (0.05 + 0.9 * U(rng)) * (s1 - s3), s3);
    c.trial = c.stress + D * (x * g(0, 2));
    break;
  case ReturnRegion::left_edge:
    c.stress = Vector3(s1, s1, s3);
    c.trial = c.stress + D * (r * x * g(0, 2) + (1 - r) * x * g(1, 2));
    break;
  case ReturnRegion::right_edge: {
    const double t = (2.0 * st.c * cphi + s3 * (1.0 - sphi)) / (1.0 + sphi);
    c.stress = Vector3(t, s3, s3);
    c.trial = c.stress + D * (r * x * g(0, 2) + (1 - r) * x * g(0, 1));
    break;
  }
  case ReturnRegion::apex: {
    c.stress = Vector3::Constant(apex);
    double w[6], sum = 0.0;
    for (double &v : w)
      sum += (v = coincident ? 1.0 : U(rng));
    const int pairs[6][2] = {{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}};
    Vector3 de = Vector3::Zero();
    for (int k = 0; k < 6; ++k)
      de += (w[k] / sum) * x * g(pairs[k][0], pairs[k][1]);
    c.trial = c.stress + D * de;
    break;
  }
  }
  return c;
}

/// The materials of the tangent tests (E = 1 GPa, nu = 0.3): perfectly plastic (c, 30, 10 deg),
/// or with every parameter varying with kappa on each segment (c/2 -> c -> 0.6 c, 24 -> 36 ->
/// 31 deg, 4 -> 14 -> 8 deg at kappa = 0, 0.02, 0.06).
inline MohrCoulombParameters tangent_test_material(double cohesion, bool hardening)
{
  MohrCoulombParameters p;
  p.youngs_modulus = 1.0e9;
  p.poisson_ratio = 0.3;
  if (hardening) {
    p.cohesion = PiecewiseLinear({0.0, 2e-2, 6e-2}, {0.5 * cohesion, cohesion, 0.6 * cohesion});
    p.friction_angle = PiecewiseLinear({0.0, 2e-2, 6e-2}, {deg(24), deg(36), deg(31)});
    p.dilatancy_angle = PiecewiseLinear({0.0, 2e-2, 6e-2}, {deg(4), deg(14), deg(8)});
  } else {
    p.cohesion = PiecewiseLinear(cohesion);
    p.friction_angle = PiecewiseLinear(deg(30));
    p.dilatancy_angle = PiecewiseLinear(deg(10));
  }
  return p;
}

} // namespace geocomp::continuum::testing
