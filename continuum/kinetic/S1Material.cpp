#include "continuum/kinetic/S1Material.h"

#include "common/S1StrengthOrder.h"

#include <cmath>
#include <stdexcept>

namespace geocomp::kinetic {

namespace {
const double inv_sqrt3 = 1.0 / std::sqrt(3.0);
void require(bool ok, const std::string &field, const std::string &expectation)
{
  if (!ok)
    throw std::invalid_argument(field + ": expected " + expectation);
}
} // namespace

void S1Material::validate_plasticity() const
{
  require(youngs_modulus > 0.0, "youngs modulus", "a positive value [Pa]");
  require(poisson_ratio > -1.0 && poisson_ratio < 0.5, "poisson ratio", "a value in (-1, 0.5)");
  require(yield_stress > 0.0, "yield stress", "a positive value [Pa]");
  require(s1_strength_above_yield(compressive_strength, yield_stress), "compressive strength",
          s1_strength_expectation);
  require(internal_friction >= 0.0 && omega() < inv_sqrt3, "internal friction",
          "alpha in [0, sqrt(3)) so that uniaxial compression can yield");
  require(dilatancy >= 0.0 && dilatancy < std::sqrt(3.0), "dilatancy", "Lambda in [0, sqrt(3))");
  require(plastic_strain_at_strength > 0.0, "plastic strain at strength", "a positive value");
}

void S1Material::validate() const
{
  validate_plasticity();
  require(density > 0.0, "density", "a positive value [kg/m^3]");
  require(tensile_strength > 0.0, "tensile strength", "a positive value [Pa]");
  require(cohesion_rate_gain > 0.0, "cohesion rate gain", "a positive value");
  require(reference_rate > 0.0, "reference rate", "a positive value [1/s]");
  require(tensile_strength * tension_factor() > static_cohesion(), "tensile strength",
          "a value above the static tensile yield stress Y0/(1/sqrt3 + omega)");
}

double S1Material::shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
double S1Material::bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
double S1Material::compression_factor() const { return inv_sqrt3 - omega(); }
double S1Material::tension_factor() const { return inv_sqrt3 + omega(); }
double S1Material::static_cohesion() const { return compression_factor() * yield_stress; }

double S1Material::hardening_modulus() const
{
  return compression_factor() * (compressive_strength - yield_stress) * (inv_sqrt3 - dilatancy / 3.0) /
         plastic_strain_at_strength;
}

S1Material S1Material::concrete()
{
  S1Material m;
  m.name = "concrete";
  m.poisson_ratio = 0.194;
  m.density = 4660.0;
  m.youngs_modulus = 38.6e9;
  m.yield_stress = 21.8e6;
  m.compressive_strength = 45.8e6;
  m.tensile_strength = 21.0e6;
  m.internal_friction = 0.63;
  m.dilatancy = 0.0;
  m.plastic_strain_at_strength = 6.0e-5; // 0.1 (sigma_c - sigma_y) / E, see docs
  return m;
}

S1Material S1Material::sandstone()
{
  S1Material m;
  m.name = "sandstone";
  m.poisson_ratio = 0.28;
  m.density = 2200.0;
  m.youngs_modulus = 16.0e9;
  m.yield_stress = 40.0e6;
  m.compressive_strength = 70.0e6;
  m.tensile_strength = 31.5e6;
  m.internal_friction = 0.57;
  m.dilatancy = 0.36;
  m.plastic_strain_at_strength = 2.0e-4; // 0.1 (sigma_c - sigma_y) / E, see docs
  return m;
}

S1Material S1Material::preset(const std::string &name)
{
  if (name == "concrete")
    return concrete();
  if (name == "sandstone")
    return sandstone();
  throw std::invalid_argument("material '" + name + "': expected concrete or sandstone");
}

} // namespace geocomp::kinetic
