// The quasi-static Nikolaevsky ConstitutiveModel: the return is on the hardened surface,
// and its algorithmic tangent is the derivative of the stress (finite differences).
#include "continuum/kinetic/NikolaevskyModel.h"

#include <gtest/gtest.h>

using namespace geocomp::kinetic;
using geocomp::continuum::Matrix6;
using geocomp::continuum::Vector6;
using geocomp::continuum::PlasticHistory;

namespace {
Vector6 compressive_strain()
{
  Vector6 e;
  e << 1.2e-3, 1.5e-3, -1.5e-2, 6e-4, -3e-4, 9e-4;
  return e;
}
} // namespace

TEST(S1NikolaevskyModel, PlasticReturnLandsOnHardenedSurface)
{
  const NikolaevskyModel model(S1Material::sandstone());
  const auto u = model.update(compressive_strain(), PlasticHistory{});
  ASSERT_EQ(u.region, geocomp::continuum::ReturnRegion::plane);
  EXPECT_GT(u.history.kappa, 0.0);
  EXPECT_NEAR(model.yield_function(u.stress, u.history.kappa), 0.0, 1e-8 * model.material().static_cohesion());
}

TEST(S1NikolaevskyModel, ConsistentTangentMatchesFiniteDifferences)
{
  const NikolaevskyModel model(S1Material::sandstone());
  PlasticHistory old;
  const Vector6 eps = compressive_strain();
  const auto u = model.update(eps, old);
  Matrix6 numeric;
  const double h = 1e-9;
  for (int j = 0; j < 6; ++j) {
    Vector6 ep = eps, em = eps;
    ep(j) += h;
    em(j) -= h;
    numeric.col(j) = (model.update(ep, old).stress - model.update(em, old).stress) / (2 * h);
  }
  EXPECT_LT((numeric - u.tangent).norm(), 1e-5 * u.tangent.norm());
  // Non-associated (Lambda != 3 omega): the tangent is not symmetric.
  EXPECT_GT((u.tangent - u.tangent.transpose()).norm(), 1e-3 * u.tangent.norm());
}
