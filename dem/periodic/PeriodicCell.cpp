#include "dem/periodic/PeriodicCell.h"

#include "dem/periodic/MatrixExponential.h"
#include "dem/periodic/PeriodicContactPass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace geocomp::dem {

PeriodicCell::PeriodicCell(const CellMatrix& cell, const ContactModel& law, const Parameters& p)
  : law_(law), cell_(cell)
{
  const bool cohesive = std::visit([](const auto& m) { return std::decay_t<decltype(m)>::has_cohesion; }, law_);
  if (cohesive)
    throw std::invalid_argument("PeriodicCell: laws with a cohesion part are not taken (their reach is not in the periodic list)");
  set_parameters(p);
}

void PeriodicCell::set_parameters(const Parameters& p)
{
  if (!(p.time_step >= 0.0)) throw std::invalid_argument("PeriodicCell: the time step must be >= 0");
  if (!(p.friction >= 0.0)) throw std::invalid_argument("PeriodicCell: the friction coefficient must be >= 0");
  if (!(p.local_damping >= 0.0 && p.local_damping < 1.0))
    throw std::invalid_argument("PeriodicCell: the local damping must be in [0, 1)");
  if (!(p.skin_ratio > 0.0)) throw std::invalid_argument("PeriodicCell: the skin ratio must be positive");
  p_ = p;
  integrator_.set_local_damping(p.local_damping);
  loads_current_ = false;  // friction or the kinetic stress may have changed
}

Index PeriodicCell::add_sphere(const Vec3& x, double radius, double density, const Vec3& u, const Vec3& omega)
{
  if (!(density > 0.0)) throw std::invalid_argument("PeriodicCell: the density must be positive");
  const double m = density * 4.0 / 3.0 * M_PI * radius * radius * radius;
  const Index k = store_.add_sphere(ParticleId(store_.size()), x, radius, m);
  store_.v[k] = u;
  store_.omega[k] = omega;
  lists_valid_ = false;
  loads_current_ = false;
  return k;
}

void PeriodicCell::set_velocity(Index p, const Vec3& u, const Vec3& omega)
{
  store_.v.at(p) = u;
  store_.omega.at(p) = omega;
  loads_current_ = false;
}

void PeriodicCell::scale_radii(double factor)
{
  if (!(factor > 0.0)) throw std::invalid_argument("PeriodicCell: the radius factor must be positive");
  const double f3 = factor * factor * factor;
  double grown = 0.0;
  for (std::size_t p = 0; p < store_.size(); ++p) {
    grown = std::max(grown, (factor - 1.0) * store_.radius[p]);
    store_.radius[p] *= factor;
    store_.mass[p] *= f3;
    store_.inv_mass[p] = 1.0 / store_.mass[p];
    store_.inv_inertia[p] = 1.0 / (0.4 * store_.mass[p] * store_.radius[p] * store_.radius[p]);
  }
  grown_ += grown;
  loads_current_ = false;
}

void PeriodicCell::build_lists()
{
  double r_max = 0.0;
  for (std::size_t p = 0; p < store_.size(); ++p) {
    store_.x[p] = cell_.wrap(store_.x[p]);
    r_max = std::max(r_max, store_.radius[p]);
  }
  x_ref_ = store_.x;  // the capacity is kept from one build to the next
  h_ref_inv_ = cell_.inverse();
  grown_ = 0.0;
  lists_.set_skin(p_.skin_ratio * r_max);
  const bool memory = std::visit([](const auto& m) { return std::decay_t<decltype(m)>::has_memory; }, law_);
  lists_.build(PeriodicNeighbours::BuildInput{store_.x, store_.radius, store_.id, cell_, memory});
  lists_valid_ = true;
}

void PeriodicCell::forces(double history_dt)
{
  std::visit(
    [&](const auto& law) {
      if constexpr (!std::decay_t<decltype(law)>::has_cohesion)
        periodic_contact_pass(law, PeriodicPassInput{store_, lists_, cell_, l_, history_dt, p_.friction}, stress_);
    },
    law_);
  stress_.kinetic.setZero();
  if (p_.kinetic_stress) {
    Mat3 k = Mat3::Zero();
    for (std::size_t p = 0; p < store_.size(); ++p) k.noalias() += store_.mass[p] * store_.v[p] * store_.v[p].transpose();
    stress_.kinetic = -k / cell_.volume();  // kinetic stress, tension positive
  }
}

void PeriodicCell::kick(double dt)
{
  for (std::size_t p = 0; p < store_.size(); ++p) integrator_.kick_particle(store_, p, dt);
}

void PeriodicCell::drift(double dt)
{
  const Mat3 ldt = l_ * dt;
  if (ldt != l_step_) {  // a constant L reuses its step matrix
    a_ = matrix_exponential(ldt);
    l_step_ = ldt;
  }
  cell_.deform(a_);
  const Vec3 spin = affine_spin(l_);  // the grains turn with the cell (PeriodicContactPass.h)
  const Mat3 f = cell_.h() * h_ref_inv_;  // deformation since the last build
  double d2_max = 0.0;
  for (std::size_t p = 0; p < store_.size(); ++p) {
    const Vec3 x = a_ * store_.x[p] + dt * store_.v[p];  // affine drift
    store_.x[p] = x;
    rotate_orientation(store_.orientation[p], Vec3(store_.omega[p] + spin), dt);
    d2_max = std::max(d2_max, (x - f * x_ref_[p]).squaredNorm());
  }
  const double e = (f.inverse() - Mat3::Identity()).norm();
  if (lists_.needs_rebuild(std::sqrt(d2_max) + grown_, e)) build_lists();
}

void PeriodicCell::evaluate()
{
  if (!lists_valid_) build_lists();
  forces(0.0);
  loads_current_ = true;
}

void PeriodicCell::refresh()
{
  if (!loads_current_ || !lists_valid_) evaluate();
}

void PeriodicCell::step()
{
  const double dt = p_.time_step;
  if (!(dt > 0.0)) throw std::logic_error("PeriodicCell: set a positive time step before stepping");
  refresh();
  l_ = control_.velocity_gradient(stress_, dt);
  kick(dt);
  drift(dt);
  forces(dt);
  kick(dt);
  loads_current_ = true;
  time_ += dt;
  ++steps_;
}

void PeriodicCell::run(std::uint64_t steps)
{
  for (std::uint64_t k = 0; k < steps; ++k) step();
}

double PeriodicCell::packing_fraction() const
{
  double solid = 0.0;
  for (double r : store_.radius) solid += 4.0 / 3.0 * M_PI * r * r * r;
  return solid / cell_.volume();
}

double PeriodicCell::unbalanced_force_ratio() const
{
  if (!(stress_.mean_contact_force > 0.0) || store_.size() == 0) return 1.0;
  double net = 0.0;
  for (const Vec3& f : store_.force) net += f.norm();
  return net / double(store_.size()) / stress_.mean_contact_force;
}

double PeriodicCell::kinetic_energy() const
{
  double e = 0.0;
  for (std::size_t p = 0; p < store_.size(); ++p)
    e += 0.5 * store_.mass[p] * store_.v[p].squaredNorm() + 0.5 * store_.omega[p].squaredNorm() / store_.inv_inertia[p];
  return e;
}

double PeriodicCell::coordination() const
{
  return store_.size() > 0 ? 2.0 * double(stress_.contacts) / double(store_.size()) : 0.0;
}

}  // namespace geocomp::dem
