#pragma once
// @sect3{Nikolaevsky plasticity as a ConstitutiveModel (S1's quasi-static model)}
//
// Why: the quasi-static limit of S1's model, plugged into the same interface as
// Mohr-Coulomb and Drucker-Prager (total strain + history -> stress, tangent, history),
// so the material-point driver or an implicit FE solver can use it. The return is S1's
// Wilkins correction with DeltaPhi chosen to land on the hardened surface, which with
// linear hardening is also the exact backward-Euler return:
//   Phi_tr = omega J1_tr + tau_tr,   Y(kappa) = Y0 + H kappa,
//   d gamma = (Phi_tr - Y(kappa_n)) / (G + 3 K Lambda omega + H)
//   tau = tau_tr - G d gamma,  J1 = J1_tr - 3 K Lambda d gamma          (S1 eq. (5))
// Consistent tangent on the cone (n = s_tr / |s_tr|, D:P = G s_tr/tau_tr + K Lambda 1,
// D:Q = G s_tr/tau_tr + 3 K omega 1):
//   C = D - (D:P) (x) (D:Q) / (G + 3 K Lambda omega + H) - 2 G^2 (d gamma / tau_tr) (I_dev - n (x) n)
// which is non-symmetric unless Lambda = 3 omega (associated flow). At the apex the
// tangent falls back to 1e-3 D (the perfect-plastic apex tangent is singular).
// Fracture (S1 eq. (6)) and rate effects are not part of this interface: its history has
// no clock; see KineticNikolaevsky for the full S1 model. Hence only the quasi-static fields
// of the S1Material are required (validate_plasticity): density, sigma_t and the rate
// constants may be left unset. Case files select it as continuum/model = nikolaevsky
// (continuum/driver/Materials.cpp).
#include "continuum/kinetic/S1Material.h"
#include "continuum/models/ConstitutiveModel.h"

namespace geocomp::kinetic {

class NikolaevskyModel : public continuum::ConstitutiveModel {
public:
  explicit NikolaevskyModel(const S1Material &material);

  continuum::MaterialPointUpdate update(const continuum::Vector6 &total_strain,
                                        const continuum::PlasticHistory &old) const override;
  double yield_function(const continuum::Vector6 &stress, double kappa) const override;
  const continuum::IsotropicElasticity &elasticity() const override { return elastic_; }
  std::string name() const override { return "nikolaevsky"; }
  const S1Material &material() const { return m_; }

private:
  S1Material m_;
  continuum::IsotropicElasticity elastic_;
  double Y0_, H_;
};

} // namespace geocomp::kinetic
