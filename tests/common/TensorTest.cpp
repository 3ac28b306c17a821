#include "common/Tensor.h"

#include <gtest/gtest.h>

using namespace geocomp;

TEST(TensorMeasures, RotationInvariantShearMeasures)
{
  Tensor3 s = Vector3(-3e6, -2e6, -1e6).asDiagonal();
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  const Tensor3 r = Q * s * Q.transpose();
  EXPECT_NEAR(tau_max(r), 1e6, 1e-6);
  EXPECT_NEAR(mean_stress(r), -2e6, 1e-6);
  EXPECT_NEAR(von_mises(r), std::sqrt(3.0) * 1e6, 1e-6);
}

TEST(TensorMeasures, LogStrainAndVolumeOfABox)
{
  const Tensor3 e = Vector3(-0.1, 0.05, 0.2).asDiagonal();
  const Tensor3 l = logarithmic_strain(e);
  EXPECT_NEAR(l(0, 0), std::log(0.9), 1e-15);
  EXPECT_NEAR(l(2, 2), std::log(1.2), 1e-15);
  EXPECT_NEAR(volumetric_strain(e), 0.9 * 1.05 * 1.2 - 1.0, 1e-15);
  EXPECT_NEAR(gamma_max(e), 0.3, 1e-15);
}
