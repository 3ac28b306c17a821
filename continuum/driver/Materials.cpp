#include "continuum/driver/Materials.h"

#include "continuum/kinetic/NikolaevskyModel.h"
#include "continuum/models/MohrCoulombModel.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace geocomp::continuum {

LinearElasticModel::LinearElasticModel(double E, double nu) : elastic_(E, nu) {}

MaterialPointUpdate LinearElasticModel::update(const Vector6 &total_strain, const PlasticHistory &old) const
{
  MaterialPointUpdate u;
  u.history = old;
  u.stress = elastic_.stiffness() * (total_strain - old.plastic_strain);
  u.tangent = elastic_.stiffness();
  u.region = ReturnRegion::elastic;
  u.trial_yield_value = -1.0;
  return u;
}

double softening_start(const std::vector<const PiecewiseLinear *> &laws)
{
  double start = std::numeric_limits<double>::infinity();
  for (const PiecewiseLinear *law : laws) {
    const auto &x = law->breakpoints();
    const auto &y = law->values();
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
      if (y[i + 1] < y[i]) {
        start = std::min(start, x[i]);
        break;
      }
  }
  return start;
}

PiecewiseLinear stretch_after(const PiecewiseLinear &law, double kappa_s, double scale)
{
  std::vector<double> x = law.breakpoints();
  for (double &xi : x)
    if (xi > kappa_s)
      xi = kappa_s + scale * (xi - kappa_s);
  return PiecewiseLinear(x, law.values());
}

namespace {
PiecewiseLinear scaled_values(const PiecewiseLinear &law, double factor)
{
  std::vector<double> y = law.values();
  for (double &v : y)
    v *= factor;
  return PiecewiseLinear(law.breakpoints(), y);
}

class FixedFactory : public MaterialFactory {
public:
  explicit FixedFactory(std::shared_ptr<const ConstitutiveModel> m) : m_(std::move(m)) {}
  std::shared_ptr<const ConstitutiveModel> make(const MaterialVariant &) const override { return m_; }

private:
  std::shared_ptr<const ConstitutiveModel> m_;
};

// Mohr-Coulomb and Drucker-Prager alike: three hardening tables (a strength, a friction
// and a dilatancy) that a variant stretches past the softening start (crack band) and whose
// strength it scales (imperfection). One class so that both models get the same variants.
template <class Parameters, class Model>
class HardeningTablesFactory : public MaterialFactory {
public:
  using Table = PiecewiseLinear Parameters::*;
  HardeningTablesFactory(Parameters p, Table strength, Table friction, Table dilatancy)
    : p_(std::move(p)), strength_(strength), friction_(friction), dilatancy_(dilatancy)
  {
    p_.validate();
  }
  std::shared_ptr<const ConstitutiveModel> make(const MaterialVariant &v) const override
  {
    Parameters q = p_;
    const double ks = softening_start({&(p_.*strength_), &(p_.*friction_)});
    if (v.softening_scale != 1.0 && std::isfinite(ks))
      for (const Table t : {strength_, friction_, dilatancy_})
        q.*t = stretch_after(q.*t, ks, v.softening_scale);
    q.*strength_ = scaled_values(q.*strength_, v.cohesion_factor);
    return std::make_shared<Model>(q);
  }

private:
  Parameters p_;
  Table strength_, friction_, dilatancy_;
};

// S1's quasi-static model: the imperfection scales every strength of the S1 table, hence
// Y(kappa) = f (Y0 + H kappa) with H = m_c (sigma_c - sigma_y)(...)/eps_p*; linear hardening
// has no softening branch, so the crack-band stretch is ignored (see the header).
class NikolaevskyFactory : public MaterialFactory {
public:
  explicit NikolaevskyFactory(kinetic::S1Material m) : m_(std::move(m)) { m_.validate_plasticity(); }
  std::shared_ptr<const ConstitutiveModel> make(const MaterialVariant &v) const override
  {
    kinetic::S1Material q = m_;
    q.yield_stress *= v.cohesion_factor;
    q.compressive_strength *= v.cohesion_factor;
    q.tensile_strength *= v.cohesion_factor;
    return std::make_shared<kinetic::NikolaevskyModel>(q);
  }

private:
  kinetic::S1Material m_;
};
} // namespace

std::shared_ptr<const MaterialFactory> fixed_material(std::shared_ptr<const ConstitutiveModel> model)
{
  if (!model)
    throw std::invalid_argument("continuum material: no model");
  return std::make_shared<FixedFactory>(std::move(model));
}

std::shared_ptr<const MaterialFactory> make_material_factory(const MaterialParameters &p)
{
  if (p.model == "mohr-coulomb")
    return std::make_shared<HardeningTablesFactory<MohrCoulombParameters, MohrCoulombModel>>(
      p.mohr_coulomb, &MohrCoulombParameters::cohesion, &MohrCoulombParameters::friction_angle,
      &MohrCoulombParameters::dilatancy_angle);
  if (p.model == "drucker-prager")
    return std::make_shared<HardeningTablesFactory<DruckerPragerParameters, DruckerPragerModel>>(
      DruckerPragerParameters::from_mohr_coulomb(p.mohr_coulomb, p.drucker_prager_matching),
      &DruckerPragerParameters::strength, &DruckerPragerParameters::friction, &DruckerPragerParameters::dilatancy);
  if (p.model == "linear-elastic")
    return fixed_material(
      std::make_shared<LinearElasticModel>(p.mohr_coulomb.youngs_modulus, p.mohr_coulomb.poisson_ratio));
  if (p.model == "nikolaevsky")
    return std::make_shared<NikolaevskyFactory>(p.nikolaevsky);
  throw std::invalid_argument("continuum material: model must be mohr-coulomb, drucker-prager, "
                              "linear-elastic or nikolaevsky, got '" + p.model + "'");
}

} // namespace geocomp::continuum
