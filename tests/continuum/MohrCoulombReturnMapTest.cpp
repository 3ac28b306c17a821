// 10^5 trial stresses across all Mohr-Coulomb return regions.
//
// Two independent families:
//  (a) constructed: pick the answer first (a point on the plane, an edge or the apex of
//      the yield surface at kappa_{n+1}, and non-negative multipliers), build the trial
//      stress s_tr = s + D_hat sum dgamma_b g_b(psi(kappa_{n+1})) from it, and require the
//      return to recover the stress, the region and kappa_{n+1};
//  (b) uniformly random trial stresses: the returned stress must lie on the surface, the
//      plastic strain increment D^-1 (s_tr - s) must be a non-negative combination of the
//      flow vectors g_ij(psi) of the active region, and d kappa = 2 sum dgamma.
#include "ContinuumTestSupport.h"

#include "continuum/models/MohrCoulombModel.h"
#include "continuum/models/SpectralDecomposition.h"
#include "MohrCoulombConstruction.h"

#include <gtest/gtest.h>

#include <map>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {

MohrCoulombParameters material(bool hardening) {
  MohrCoulombParameters p;
  p.youngs_modulus = 1.0e9;
  p.poisson_ratio = 0.27;
  if (hardening) {
    // Hardening, then softening mild enough that the local problem has one solution
    // (strong softening makes backward Euler non-unique; see docs/continuum-models.md).
    p.cohesion = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.6e6, 1.0e6, 0.5e6});
    p.friction_angle = PiecewiseLinear({0.0, 1e-2, 5e-2}, {deg(25), deg(35), deg(30)});
    p.dilatancy_angle = PiecewiseLinear({0.0, 1e-2, 5e-2}, {deg(12), deg(10), deg(6)});
  } else {
    p.cohesion = PiecewiseLinear(1.0e6);
    p.friction_angle = PiecewiseLinear(deg(30));
    p.dilatancy_angle = PiecewiseLinear(deg(10));
  }
  return p;
}

std::vector<Vector3> generators(ReturnRegion region, double psi) {
  auto g = [&](int i, int j) { return MohrCoulombReturnMap::flow_generator(i, j, psi); };
  switch (region) {
  case ReturnRegion::plane:
    return {g(0, 2)};
  case ReturnRegion::left_edge:
    return {g(0, 2), g(1, 2)};
  case ReturnRegion::right_edge:
    return {g(0, 2), g(0, 1)};
  case ReturnRegion::apex:
    return {g(0, 1), g(0, 2), g(1, 0), g(1, 2), g(2, 0), g(2, 1)};
  default:
    return {};
  }
}

void run_constructed(bool hardening, int cases_per_region) {
  const MohrCoulombModel model(material(hardening));
  const MohrCoulombReturnMap &map = model.return_map();
  std::mt19937_64 rng(hardening ? 7 : 11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const ReturnRegion regions[] = {ReturnRegion::elastic, ReturnRegion::plane,
                                  ReturnRegion::left_edge, ReturnRegion::right_edge,
                                  ReturnRegion::apex};
  const Matrix6 &S = model.elasticity().compliance();
  for (ReturnRegion region : regions) {
    int failures = 0;
    for (int n = 0; n < cases_per_region; ++n) {
      const double kappa_n = hardening ? 0.06 * U(rng) : 0.0;
      const double dkappa = 1e-4 + 5e-3 * U(rng);
      const Constructed c = construct(map, region, kappa_n, dkappa, rng);
      // Through the full tensor model, with a random orientation.
      const Matrix3 Q = random_rotation(rng);
      const Vector6 trial_stress = rotated(c.trial, Q);
      PlasticHistory old;
      old.kappa = kappa_n;
      MaterialPointUpdate u;
      try {
        u = model.update(S * trial_stress, old);
      } catch (const ReturnMapFailure &e) {
        ADD_FAILURE() << e.what() << " region " << to_string(region) << " trial "
                      << c.trial.transpose() << " kappa_n " << kappa_n << " -> " << c.kappa_new;
        ++failures;
        continue;
      }
      const Vector6 expected = rotated(c.stress, Q);
      const double scale = std::max(c.trial.cwiseAbs().maxCoeff(), 1e6);
      const bool ok = u.region == region &&
                      (u.stress - expected).cwiseAbs().maxCoeff() <= 1e-10 * scale &&
                      std::abs(u.history.kappa - c.kappa_new) <= 1e-10 * std::max(dkappa, 1e-3);
      if (!ok && ++failures <= 3)
        ADD_FAILURE() << "region " << to_string(region) << " got " << to_string(u.region)
                      << " stress error " << (u.stress - expected).cwiseAbs().maxCoeff() / scale
                      << " kappa " << u.history.kappa << " vs " << c.kappa_new;
    }
    EXPECT_EQ(failures, 0) << to_string(region);
  }
}

} // namespace

TEST(MohrCoulombReturnMap, RecoversConstructedReturnsInEveryRegionPerfectPlasticity) {
  run_constructed(false, 10000);
}

TEST(MohrCoulombReturnMap, RecoversConstructedReturnsInEveryRegionWithHardeningSoftening) {
  run_constructed(true, 10000);
}

TEST(MohrCoulombReturnMap, RandomTrialStressesLandOnSurfaceWithFlowConsistentWithPsi) {
  for (bool hardening : {false, true}) {
    const MohrCoulombModel model(material(hardening));
    const MohrCoulombReturnMap &map = model.return_map();
    const Matrix3 D = model.elasticity().principal_stiffness();
    const Matrix3 Dinv = D.inverse();
    std::mt19937_64 rng(hardening ? 3 : 5);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::map<ReturnRegion, int> count;
    int failures = 0;
    for (int n = 0; n < 25000; ++n) {
      // Half the samples span the whole compressive range, half the tensile side where
      // the apex and the edges near it live.
      const bool tensile_side = n % 2 == 1;
      Vector3 e;
      for (int i = 0; i < 3; ++i)
        e(i) = 1e6 * (tensile_side ? -4.0 + 10.0 * U(rng) : -40.0 + 45.0 * U(rng));
      std::sort(e.data(), e.data() + 3, std::greater<double>());
      const double kappa_n = hardening ? 0.06 * U(rng) : 0.0;
      const PrincipalReturn r = map.return_principal(e, kappa_n);
      ++count[r.region];
      const double k1 = kappa_n + r.delta_kappa;
      const double scale = r.stress.cwiseAbs().maxCoeff() + map.strength(k1).c;
      const double phi_new = map.yield_principal(r.stress, k1);
      std::string why;
      if (r.region == ReturnRegion::elastic) {
        if (!(map.yield_principal(e, kappa_n) <= 0.0) || r.delta_kappa != 0.0)
          why = "elastic but yields";
      } else {
        if (std::abs(phi_new) > 1e-10 * scale)
          why = "off the yield surface";
        if (r.stress(0) < r.stress(1) - 1e-10 * scale || r.stress(1) < r.stress(2) - 1e-10 * scale)
          why = "ordering lost";
        // Region geometry of the returned stress.
        const double d12 = r.stress(0) - r.stress(1), d23 = r.stress(1) - r.stress(2);
        const double tol = 1e-9 * scale;
        const bool geom =
            (r.region == ReturnRegion::plane) ||
            (r.region == ReturnRegion::left_edge && std::abs(d12) <= tol) ||
            (r.region == ReturnRegion::right_edge && std::abs(d23) <= tol) ||
            (r.region == ReturnRegion::apex && std::abs(d12) <= tol && std::abs(d23) <= tol);
        if (!geom)
          why = "stress not on the region's face/edge/apex";
        // Flow: d eps^p = D^-1 (s_tr - s) in the cone of the region's g_ij(psi(k1)),
        // with 2 sum(weights) = d kappa.
        const Vector3 dep = Dinv * (e - r.stress);
        std::vector<double> w;
        const double psi = map.parameters().dilatancy_angle(k1);
        if (!in_generated_cone(dep, generators(r.region, psi), 1e-8, &w))
          why = "plastic strain increment not generated by the flow vectors";
        else if (r.region != ReturnRegion::apex || std::sin(psi) > std::sin(1e-3)) {
          double sum = 0.0;
          for (double v : w)
            sum += v;
          if (std::abs(2.0 * sum - r.delta_kappa) > 1e-8 * r.delta_kappa + 1e-18)
            why = "d kappa != 2 sum dgamma";
        }
      }
      if (!why.empty() && ++failures <= 5)
        ADD_FAILURE() << why << " region " << to_string(r.region) << " trial " << e.transpose()
                      << " returned " << r.stress.transpose();
    }
    EXPECT_EQ(failures, 0);
    for (ReturnRegion reg : {ReturnRegion::elastic, ReturnRegion::plane, ReturnRegion::left_edge,
                             ReturnRegion::right_edge, ReturnRegion::apex})
      EXPECT_GT(count[reg], 100) << "too few random samples in " << to_string(reg);
  }
}

TEST(MohrCoulombReturnMap, RefusesTablesWhoseDilatancyExceedsTheFrictionAngleBetweenTheDilatancyKnots) {
  // psi <= phi at both psi knots (0 and 0.1), but phi dips to 8 deg at kappa = 0.05 where the
  // psi table passes 10 deg: a check at the psi knots alone misses it (calibration steps there).
  const double deg = M_PI / 180.0;
  MohrCoulombParameters p;
  p.youngs_modulus = 1.0e9;
  p.poisson_ratio = 0.27;
  p.cohesion = PiecewiseLinear(1e5);
  p.friction_angle = PiecewiseLinear({0.0, 0.05, 0.1}, {30 * deg, 8 * deg, 30 * deg});
  p.dilatancy_angle = PiecewiseLinear({0.0, 0.1}, {0.0, 20 * deg});
  EXPECT_THROW(MohrCoulombReturnMap{p}, std::invalid_argument);
  p.friction_angle = PiecewiseLinear({0.0, 0.05, 0.1}, {30 * deg, 12 * deg, 30 * deg});
  EXPECT_NO_THROW(MohrCoulombReturnMap{p});
}
