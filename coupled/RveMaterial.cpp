#include "coupled/RveMaterial.h"

#include "continuum/models/Mandel.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <stdexcept>

namespace geocomp::coupled {

using continuum::Matrix6;
using continuum::Vector6;

namespace {

dem::PeriodicCell made_current(dem::PeriodicCell cell)
{
  cell.refresh();
  if (cell.stress().contacts == 0)
    throw std::invalid_argument("dem rve: the prepared cell carries no contact (prepare it to a pressure first)");
  if (!(cell.parameters().time_step > 0.0))
    throw std::invalid_argument("dem rve: the prepared cell has no time step");
  return cell;
}

/// Isotropic projection of a Mandel stiffness: K = C_iijj / 9, G = (C_ijij - C_iijj / 3) / 10.
continuum::IsotropicElasticity isotropic_projection(const Matrix6 &c)
{
  const double c_iijj = c.topLeftCorner<3, 3>().sum();
  const double c_ijij = c.trace(); // Mandel: the trace is C_ijij
  const double bulk = c_iijj / 9.0, shear = (c_ijij - c_iijj / 3.0) / 10.0;
  if (!(bulk > 0.0 && shear > 0.0))
    throw std::invalid_argument("dem rve: the prepared cell's contact stiffness has no positive bulk and shear moduli");
  const double youngs = 9.0 * bulk * shear / (3.0 * bulk + shear);
  const double poisson = (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear));
  return continuum::IsotropicElasticity(youngs, poisson);
}

} // namespace

RveMaterial::RveMaterial(dem::PeriodicCell prepared, const RveParameters &parameters)
  : prepared_(made_current(std::move(prepared)))
  , p_(parameters)
  , elastic_(isotropic_projection(tangent(prepared_)))
{
  if (p_.steps_per_increment < 1)
    throw std::invalid_argument("dem rve: 'steps per increment' must be >= 1");
}

std::shared_ptr<const continuum::PointState> RveMaterial::initial_state(const Vector6 &initial_strain) const
{
  return std::make_shared<const RveState>(prepared_, initial_strain, tangent(prepared_));
}

dem::Mat3 RveMaterial::velocity_gradient(const Vector6 &increment, std::uint64_t n, double time_step)
{
  return continuum::from_mandel(increment) / (double(n) * time_step); // L = d eps / (n dt)
}

dem::Mat3 RveMaterial::finite_velocity_gradient(const continuum::Matrix3 &increment, std::uint64_t n, double time_step)
{
  const double det = increment.determinant();
  const dem::Mat3 log = det > 0.0 ? dem::Mat3(increment.log()) : dem::Mat3::Constant(std::nan(""));
  if (!log.allFinite() || !(log.exp() - increment).isZero(1e-9 * increment.norm()))
    throw continuum::ReturnMapFailure("dem rve: the deformation increment has no real logarithm (det = " +
                                      std::to_string(det) + ")");
  return log / (double(n) * time_step); // L = ln(F_{n+1} F_n^-1) / (n dt)
}

Vector6 RveMaterial::stress(const dem::PeriodicCell &cell) { return continuum::to_mandel(cell.stress().total()); }

// The orthotropic part of C_ijkl = (1/V) sum k_n |l|^2 n_i n_j n_k n_l from K_ab = C_abab = C_aabb;
// Mandel weights: C_m(I, I) = 2 C_abab on the shear slots.
Matrix6 RveMaterial::tangent(const dem::PeriodicCell &cell)
{
  const dem::Mat3 &k = cell.stress().stiffness;
  Matrix6 c = Matrix6::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      c(a, b) = a == b ? k(a, a) : 0.5 * (k(a, b) + k(b, a));
  c(3, 3) = k(1, 2) + k(2, 1);
  c(4, 4) = k(0, 2) + k(2, 0);
  c(5, 5) = k(0, 1) + k(1, 0);
  return c;
}

Matrix6 RveMaterial::branch_tangent(const Matrix6 &contact, const Vector6 &s, const Vector6 &y)
{
  const Vector6 cs = contact * s;
  const double scs = s.dot(cs), sy = s.dot(y);
  if (!(scs > 0.0) || !std::isfinite(sy))
    return contact;
  const double theta = sy >= 0.2 * scs ? 1.0 : 0.8 * scs / (scs - sy); // Powell's damping
  const Vector6 r = theta * y + (1.0 - theta) * cs;
  const Matrix6 c = contact - cs * cs.transpose() / scs + r * r.transpose() / s.dot(r); // BFGS: C~ s = r
  return 0.5 * (c + c.transpose());
}

continuum::PointStateUpdate RveMaterial::advance(const Vector6 &total_strain,
                                                 const std::shared_ptr<const continuum::PointState> &old) const
{
  const auto *committed = dynamic_cast<const RveState *>(old.get());
  if (!committed)
    throw std::logic_error("dem rve: the point state is not an RVE's");
  continuum::PointStateUpdate u;
  const Vector6 increment = total_strain - committed->strain;
  if (increment.isZero(0.0)) {
    u.stress = stress(committed->cell);
    u.tangent = committed->tangent;
    u.state = old;
    return u;
  }
  auto trial = std::make_shared<RveState>(*committed); // the committed cell is never touched
  trial->strain = total_strain;
  const std::uint64_t n = p_.steps_per_increment;
  trial->cell.set_velocity_gradient(velocity_gradient(increment, n, trial->cell.parameters().time_step));
  trial->cell.run(n);
  u.stress = stress(trial->cell);
  trial->tangent = tangent(trial->cell);
  if (p_.tangent == RveTangent::branch_secant)
    trial->tangent = branch_tangent(trial->tangent, increment, u.stress - stress(committed->cell));
  u.tangent = trial->tangent;
  u.state = std::move(trial);
  return u;
}

continuum::FiniteStrainUpdate RveMaterial::advance_finite(const continuum::Matrix3 &F,
                                                          const continuum::FiniteStrainHistory &old) const
{
  const auto *committed = dynamic_cast<const RveState *>(old.state.get());
  if (!committed)
    throw std::logic_error("dem rve: the point state is not an RVE's");
  const continuum::Matrix3 increment = F * committed->deformation_gradient.inverse();
  const RveState *state = committed;
  continuum::FiniteStrainUpdate u;
  u.history.state = old.state;
  if (F != committed->deformation_gradient) {
    auto trial = std::make_shared<RveState>(*committed); // the committed cell is never touched
    trial->deformation_gradient = F;
    const std::uint64_t n = p_.steps_per_increment;
    const dem::Mat3 l = finite_velocity_gradient(increment, n, trial->cell.parameters().time_step);
    trial->cell.set_velocity_gradient(l);
    trial->cell.run(n);
    trial->tangent = tangent(trial->cell);
    if (p_.tangent == RveTangent::branch_secant) {
      const dem::Mat3 log = l * (double(n) * trial->cell.parameters().time_step); // ln(F_{n+1} F_n^-1)
      const dem::Mat3 w = 0.5 * (log - log.transpose()), &sigma_n = committed->cell.stress().total();
      const dem::Mat3 jaumann = trial->cell.stress().total() - sigma_n - (w * sigma_n - sigma_n * w);
      trial->tangent = branch_tangent(trial->tangent, continuum::to_mandel(0.5 * (log + log.transpose())),
                                      continuum::to_mandel(jaumann));
    }
    state = trial.get();
    u.history.state = std::move(trial);
  }
  const dem::PeriodicCell *cell = &state->cell;
  u.jacobian = F.determinant();
  u.kirchhoff_stress = u.jacobian * cell->stress().total();
  u.logarithmic_tangent = state->tangent;
  u.spatial_tangent = continuum::jaumann_spatial_tangent(u.logarithmic_tangent, u.kirchhoff_stress, u.jacobian);
  u.history.deformation_gradient = F;
  return u;
}

} // namespace geocomp::coupled
