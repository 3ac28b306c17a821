// The Mohr-Coulomb consistent tangent equals central finite differences of the full
// return map (eigenvector rotation included) to 1e-6 relative, in every region, with and
// without hardening/softening, and where trial eigenvalues coincide.
#include "MohrCoulombConstruction.h"

#include "continuum/models/MohrCoulombModel.h"

#include <gtest/gtest.h>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {

MohrCoulombParameters material(bool hardening) { return tangent_test_material(1.0e6, hardening); }

// kappa_n and the kappa increment stay inside one table segment, so the map is smooth.
void check_tangent(bool hardening, double kappa_n) {
  const MohrCoulombModel model(material(hardening));
  const Matrix6 &S = model.elasticity().compliance();
  const Matrix6 &D = model.elasticity().stiffness();
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int checked = 0;
  for (ReturnRegion region : {ReturnRegion::elastic, ReturnRegion::plane, ReturnRegion::left_edge,
                              ReturnRegion::right_edge, ReturnRegion::apex}) {
    for (bool coincident : {false, true}) {
      if (coincident && region == ReturnRegion::plane)
        continue; // a plane return needs distinct s1 > s2 > s3
      for (int sample = 0; sample < 6; ++sample) {
        const Constructed c =
            construct(model.return_map(), region, kappa_n, 1e-3 + 4e-3 * U(rng), rng, coincident);
        const Matrix3 Q = sample == 0 ? Matrix3::Identity() : random_rotation(rng);
        PlasticHistory old;
        old.kappa = kappa_n;
        old.plastic_strain = to_mandel(Q * Vector3(1e-4, -3e-4, 2e-4).asDiagonal() * Q.transpose());
        const Vector6 eps = S * rotated(c.trial, Q) + old.plastic_strain;
        const MaterialPointUpdate u = model.update(eps, old);
        ASSERT_EQ(u.region, region) << to_string(region);
        const Matrix6 fd = finite_difference_tangent(model, eps, old, 1e-9);
        const double err = relative_difference(u.tangent, fd, 1e-3 * D.cwiseAbs().maxCoeff());
        EXPECT_LT(err, 1e-6) << to_string(region) << (coincident ? " coincident" : "")
                             << (hardening ? " hardening" : " perfect") << " sample " << sample
                             << "\nC_alg=\n" << u.tangent << "\nFD=\n" << fd;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 9 * 6);
}

} // namespace

TEST(MohrCoulombTangent, MatchesFiniteDifferencesInEveryRegionPerfectPlasticity) {
  check_tangent(false, 0.0);
}

TEST(MohrCoulombTangent, MatchesFiniteDifferencesInEveryRegionOnHardeningBranch) {
  check_tangent(true, 0.004); // c, phi, psi all rise with kappa
}

TEST(MohrCoulombTangent, MatchesFiniteDifferencesInEveryRegionOnSofteningBranch) {
  check_tangent(true, 0.03); // c, phi, psi all fall with kappa
}

TEST(MohrCoulombTangent, PerfectPlasticApexTangentIsZeroAndElasticTangentIsD) {
  const MohrCoulombModel model(material(false));
  const Matrix6 &S = model.elasticity().compliance();
  const MaterialPointUpdate apex = model.update(S * rotated(Vector3(4e6, 3e6, 3e6), Matrix3::Identity()), {});
  ASSERT_EQ(apex.region, ReturnRegion::apex);
  EXPECT_LT(apex.tangent.cwiseAbs().maxCoeff(), 1e-6 * model.elasticity().shear_modulus());
  const MaterialPointUpdate el = model.update(S * rotated(Vector3(-1e6, -1e6, -1e6), Matrix3::Identity()), {});
  ASSERT_EQ(el.region, ReturnRegion::elastic);
  EXPECT_EQ(el.tangent, model.elasticity().stiffness());
}
