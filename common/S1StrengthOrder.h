#pragma once
// S1's order of the static strengths of its quasi-static Nikolaevsky model: the uniaxial
// compressive strength sigma_c lies above the yield stress sigma_y (the linear hardening
// runs from one to the other).
//
// Why a header of its own: two places refuse a material that breaks it, the case reader
// (common/case/NikolaevskySection.cpp, which cannot see continuum/) and
// S1Material::validate_plasticity (continuum/kinetic, which links no common library, hence
// header-only); one rule, one wording.
namespace geocomp {

/// sigma_c > sigma_y (false when either is NaN).
inline bool s1_strength_above_yield(double compressive_strength, double yield_stress)
{
  return compressive_strength > yield_stress;
}

/// What a message says is expected of the compressive strength.
inline constexpr const char *s1_strength_expectation = "a value above the yield stress (S1: sigma_c > sigma_y)";

} // namespace geocomp
