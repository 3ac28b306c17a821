// continuum/quadrature points (continuum/fe/GaussPoints.h, GaussRule.h): one axis may take
// `degree` Gauss points instead of degree + 1. These tests prove the two claims the rule rests
// on, on one hexahedron of FE_Q(p)^3: (1) with one reduced axis the elastic stiffness of a Q2
// or Q3 element has exactly the six zero eigenvalues of the rigid motions (no hourglass mode),
// while a Q1 element with one point across, or two reduced axes at any degree, add spurious
// ones - so the rule refuses those; (2) the residual of a
// stress that does not vary along the reduced axis (a plane-strain slab's) is integrated
// exactly, while one that varies quadratically along it is not.
#include "continuum/fe/GaussRule.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <functional>

using namespace geocomp::continuum;
namespace dl = dealii;

namespace {

/// One hexahedron [0, 1] x [0, 0.25] x [0, 2] (unequal edges: a slab's element), FE_Q(p)^3.
struct OneElement {
  explicit OneElement(unsigned degree)
    : fe(dl::FE_Q<3>(degree), 3)
  {
    dl::GridGenerator::hyper_rectangle(tria, dl::Point<3>(0, 0, 0), dl::Point<3>(1.0, 0.25, 2.0));
    dofs.reinit(tria);
    dofs.distribute_dofs(fe);
  }
  dl::Triangulation<3> tria;
  dl::FESystem<3> fe;
  dl::DoFHandler<3> dofs;
};

/// The isotropic elastic stiffness (lambda = 1.5, mu = 1) of the element under `rule`.
Eigen::MatrixXd stiffness(const OneElement &e, const dl::Quadrature<3> &rule)
{
  const double lambda = 1.5, mu = 1.0;
  dl::FEValues<3> v(e.fe, rule, dl::update_gradients | dl::update_JxW_values);
  v.reinit(e.dofs.begin_active());
  const unsigned n = e.fe.n_dofs_per_cell();
  const dl::FEValuesExtractors::Vector u(0);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (unsigned q = 0; q < rule.size(); ++q)
    for (unsigned i = 0; i < n; ++i) {
      const dl::SymmetricTensor<2, 3> ei = v[u].symmetric_gradient(i, q);
      for (unsigned j = 0; j < n; ++j) {
        const dl::SymmetricTensor<2, 3> ej = v[u].symmetric_gradient(j, q);
        K(i, j) += (lambda * dl::trace(ei) * dl::trace(ej) + 2.0 * mu * (ei * ej)) * v.JxW(q);
      }
    }
  return K;
}

/// Eigenvalues of K below 1e-10 of its largest: its zero-energy modes.
int zero_modes(const Eigen::MatrixXd &K)
{
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  int zeros = 0;
  for (Eigen::Index k = 0; k < ev.size(); ++k)
    zeros += std::abs(ev[k]) < 1e-10 * ev.maxCoeff() ? 1 : 0;
  return zeros;
}

/// R_i = int sigma(x) : grad phi_i dV under `rule`.
Eigen::VectorXd residual(const OneElement &e, const dl::Quadrature<3> &rule,
                         const std::function<dl::SymmetricTensor<2, 3>(const dl::Point<3> &)> &sigma)
{
  dl::FEValues<3> v(e.fe, rule, dl::update_gradients | dl::update_quadrature_points | dl::update_JxW_values);
  v.reinit(e.dofs.begin_active());
  const dl::FEValuesExtractors::Vector u(0);
  Eigen::VectorXd R = Eigen::VectorXd::Zero(e.fe.n_dofs_per_cell());
  for (unsigned q = 0; q < rule.size(); ++q) {
    const dl::SymmetricTensor<2, 3> s = sigma(v.quadrature_point(q));
    for (unsigned i = 0; i < e.fe.n_dofs_per_cell(); ++i)
      R[i] += s * v[u].symmetric_gradient(i, q) * v.JxW(q);
  }
  return R;
}

} // namespace

TEST(GaussPoints, OneReducedAxisKeepsOnlyTheSixRigidModesOfAQ2OrQ3Element)
{
  for (unsigned p = 2; p <= 3; ++p) {
    const OneElement e(p);
    EXPECT_EQ(zero_modes(stiffness(e, gauss_rule(p, {{0, 0, 0}}))), 6) << "degree " << p << ", full";
    for (int axis = 0; axis < 3; ++axis) {
      std::array<unsigned, 3> n{{p + 1, p + 1, p + 1}};
      n[axis] = p;
      ASSERT_TRUE(gauss_points_problem(p, n).empty()) << gauss_points_problem(p, n);
      ASSERT_EQ(gauss_rule(p, n).size(), p * (p + 1) * (p + 1));
      EXPECT_EQ(zero_modes(stiffness(e, gauss_rule(p, n))), 6) << "degree " << p << ", axis " << axis << " reduced";
    }
  }
}

// Q1 with one Gauss point across y: the twist u = (-y z, x z, -x y) about the element's centre
// has zero strain on the plane y = 0, a seventh zero mode; the rule refuses it.
TEST(GaussPoints, OnePointAcrossAQ1ElementLeavesATwistModeAndTheRuleRefusesIt)
{
  const OneElement e(1);
  EXPECT_EQ(zero_modes(stiffness(e, gauss_rule(1, {{0, 0, 0}}))), 6);
  const dl::Quadrature<3> rule = dl::QAnisotropic<3>(dl::QGauss<1>(2), dl::QGauss<1>(1), dl::QGauss<1>(2));
  EXPECT_EQ(zero_modes(stiffness(e, rule)), 7);
  EXPECT_FALSE(gauss_points_problem(1, {{2, 1, 2}}).empty());
  EXPECT_EQ(gauss_rule(1, {{2, 1, 2}}).size(), 8u); // refused: the full rule
}

TEST(GaussPoints, TwoReducedAxesAdmitZeroEnergyModesAndTheRuleRefusesThem)
{
  for (unsigned p = 1; p <= 3; ++p) {
    const OneElement e(p);
    const std::array<unsigned, 3> two{{p, p, p + 1}};
    const dl::Quadrature<3> rule = dl::QAnisotropic<3>(dl::QGauss<1>(p), dl::QGauss<1>(p), dl::QGauss<1>(p + 1));
    EXPECT_GT(zero_modes(stiffness(e, rule)), 6) << "degree " << p;
    EXPECT_FALSE(gauss_points_problem(p, two).empty()) << "degree " << p;
    EXPECT_EQ(gauss_rule(p, two).size(), (p + 1) * (p + 1) * (p + 1)); // refused: the full rule
  }
  EXPECT_FALSE(gauss_points_problem(2, {{3, 1, 3}}).empty()); // below the degree
  EXPECT_FALSE(gauss_points_problem(2, {{3, 0, 3}}).empty()); // a zero beside counts
  EXPECT_TRUE(gauss_points_problem(2, {{4, 3, 3}}).empty());  // more than full: allowed
}

TEST(GaussPoints, TheResidualOfAStressConstantAcrossTheReducedAxisIsExact)
{
  const unsigned p = 2;
  const OneElement e(p);
  const dl::Quadrature<3> full = gauss_rule(p, {{0, 0, 0}}), slab = gauss_rule(p, {{3, 2, 3}});
  ASSERT_EQ(slab.size(), 18u);
  // A plane-strain stress: linear in x and z, constant along y.
  const auto plane = [](const dl::Point<3> &x) {
    dl::SymmetricTensor<2, 3> s;
    s[0][0] = 1.0 + 0.7 * x[0] - 0.2 * x[2];
    s[2][2] = -2.0 + 0.3 * x[2];
    s[0][2] = 0.4 * x[0] + 0.1 * x[2];
    s[1][1] = 0.5 * (s[0][0] + s[2][2]);
    return s;
  };
  const Eigen::VectorXd a = residual(e, full, plane), b = residual(e, slab, plane);
  EXPECT_LT((a - b).norm(), 1e-13 * a.norm());
  // The same stress with a part quadratic across the thickness: the reduced rule misses it.
  const auto across = [&](const dl::Point<3> &x) {
    dl::SymmetricTensor<2, 3> s = plane(x);
    s[0][0] += 30.0 * x[1] * x[1];
    return s;
  };
  const Eigen::VectorXd c = residual(e, full, across), d = residual(e, slab, across);
  EXPECT_GT((c - d).norm(), 1e-4 * c.norm());
}
