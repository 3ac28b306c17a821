#include "continuum/kinetic/NikolaevskyModel.h"

#include "continuum/kinetic/WilkinsCorrection.h"

#include <cmath>

namespace geocomp::kinetic {

using continuum::mandel_deviatoric_projector;
using continuum::mandel_identity;
using continuum::Matrix6;

NikolaevskyModel::NikolaevskyModel(const S1Material &material)
  : m_((material.validate_plasticity(), material)), elastic_(material.youngs_modulus, material.poisson_ratio),
    Y0_(material.static_cohesion()), H_(material.hardening_modulus())
{
}

double NikolaevskyModel::yield_function(const Vector6 &stress, double kappa) const
{
  const Invariants inv = invariants(stress);
  return m_.omega() * inv.J1 + inv.tau - (Y0_ + H_ * kappa); // S1 eq. (1)
}

continuum::MaterialPointUpdate NikolaevskyModel::update(const Vector6 &total_strain,
                                                        const continuum::PlasticHistory &old) const
{
  continuum::MaterialPointUpdate u;
  const Matrix6 &D = elastic_.stiffness();
  const Vector6 trial = D * (total_strain - old.plastic_strain);
  u.history = old;
  u.trial_yield_value = yield_function(trial, old.kappa);
  if (u.trial_yield_value <= 0.0) {
    u.stress = trial;
    u.tangent = D;
    u.region = continuum::ReturnRegion::elastic;
    return u;
  }
  const double G = elastic_.shear_modulus(), K = elastic_.bulk_modulus();
  const NikolaevskyConstants c{G, K, m_.omega(), m_.dilatancy};
  const double d_gamma = u.trial_yield_value / (c.denominator() + H_);
  const WilkinsResult w = wilkins_correction(trial, c.denominator() * d_gamma, c);
  u.stress = w.stress;
  u.history.plastic_strain = total_strain - elastic_.compliance() * w.stress;
  u.history.kappa = old.kappa + w.plastic_shear;
  u.local_iterations = 0;
  if (w.apex) {
    u.region = continuum::ReturnRegion::apex;
    u.tangent = 1e-3 * D;
    return u;
  }
  u.region = continuum::ReturnRegion::plane;
  const Invariants inv = invariants(trial);
  const Vector6 n = inv.deviator / inv.deviator.norm();
  const Vector6 DP = G / inv.tau * inv.deviator + K * m_.dilatancy * mandel_identity();
  const Vector6 DQ = G / inv.tau * inv.deviator + 3.0 * K * m_.omega() * mandel_identity();
  u.tangent = D - DP * DQ.transpose() / (c.denominator() + H_) -
              2.0 * G * G * d_gamma / inv.tau * (mandel_deviatoric_projector() - n * n.transpose());
  return u;
}

} // namespace geocomp::kinetic
