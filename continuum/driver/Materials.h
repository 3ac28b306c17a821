#pragma once
// Materials of the continuum engines: which constitutive model a run uses, and the
// point-wise variants the FE cube needs.
//
// Both engines call the models of continuum/models through ConstitutiveModel::update
// (total strain + old history -> stress, consistent tangent, new history, region). The FE
// cube needs two kinds of point-wise variation of one material:
//   - the imperfection: a zone with the cohesion (Drucker-Prager: the strength Y)
//     multiplied by a factor f < 1;
//   - the crack band (Bazant & Oh 1983; Pietruszczak & Mroz 1981 for shear bands): a band
//     one element wide must dissipate per unit area what a band of the reference width
//     l_ref dissipates, so every softening branch is stretched in kappa by s = l_ref / h_e,
//         kappa_i -> kappa_s + s (kappa_i - kappa_s)   for breakpoints kappa_i > kappa_s,
//     where kappa_s is the first breakpoint after which a strength parameter (c or phi;
//     Y or omega) decreases. The hardening branch (distributed deformation) is unchanged.
// A MaterialFactory builds the model for any such variant; the engines cache one model per
// distinct variant. For S1's nikolaevsky model (linear hardening, no softening branch) the
// imperfection scales every strength of its S1Material (sigma_y, sigma_c, sigma_t), so Y(kappa)
// = f (Y0 + H kappa); the crack-band stretch has nothing to act on and is ignored, as for a
// Mohr-Coulomb table that never softens.
//
// LinearElasticModel is a ConstitutiveModel that never yields: the reference of the
// closed-form elastic tests of the engines.
#include "continuum/kinetic/S1Material.h"
#include "continuum/models/ConstitutiveModel.h"
#include "continuum/models/DruckerPragerModel.h"
#include "continuum/models/MohrCoulombReturnMap.h"

#include <memory>
#include <string>

namespace geocomp::continuum {

/// How a point's material differs from the base material.
struct MaterialVariant {
  double cohesion_factor = 1.0; ///< multiplies c(kappa) (Drucker-Prager, Nikolaevsky: Y(kappa))
  double softening_scale = 1.0; ///< crack-band stretch s of the softening branches
  bool operator<(const MaterialVariant &o) const
  {
    return cohesion_factor < o.cohesion_factor ||
           (cohesion_factor == o.cohesion_factor && softening_scale < o.softening_scale);
  }
};

/// Which model and its parameters (the lead maps the case file's "continuum/material"
/// section onto this).
struct MaterialParameters {
  /// mohr-coulomb | drucker-prager | linear-elastic | nikolaevsky
  std::string model = "mohr-coulomb";
  /// Mohr-Coulomb parameters (E, nu, c/phi/psi(kappa)). Also the source of E, nu for
  /// linear-elastic and of the cone for drucker-prager.
  MohrCoulombParameters mohr_coulomb;
  /// How drucker-prager is fitted to mohr_coulomb.
  DruckerPragerMatching drucker_prager_matching = DruckerPragerMatching::outer_cone;
  /// S1's material for nikolaevsky (kinetic::NikolaevskyModel; its quasi-static fields only).
  kinetic::S1Material nikolaevsky;
};

class MaterialFactory {
public:
  virtual ~MaterialFactory() = default;
  virtual std::shared_ptr<const ConstitutiveModel> make(const MaterialVariant &variant) const = 0;
};

/// The factory for a MaterialParameters (validates them; throws std::invalid_argument).
std::shared_ptr<const MaterialFactory> make_material_factory(const MaterialParameters &parameters);

/// A factory that always returns the same model (variants ignored), e.g. for elasticity.
std::shared_ptr<const MaterialFactory> fixed_material(std::shared_ptr<const ConstitutiveModel> model);

/// Stretch of the softening branches of a set of laws (see the file comment):
/// kappa_s = first breakpoint after which any of `strength_laws` decreases.
double softening_start(const std::vector<const PiecewiseLinear *> &strength_laws);
PiecewiseLinear stretch_after(const PiecewiseLinear &law, double kappa_s, double scale);

/// Hooke's law as a ConstitutiveModel: stress = D (eps - eps^p_n), never yields.
class LinearElasticModel : public ConstitutiveModel {
public:
  LinearElasticModel(double youngs_modulus, double poisson_ratio);
  MaterialPointUpdate update(const Vector6 &total_strain, const PlasticHistory &old) const override;
  double yield_function(const Vector6 &, double) const override { return -1.0; }
  const IsotropicElasticity &elasticity() const override { return elastic_; }
  std::string name() const override { return "linear_elastic"; }

private:
  IsotropicElasticity elastic_;
};

} // namespace geocomp::continuum
