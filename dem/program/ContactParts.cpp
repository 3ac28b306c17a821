#include "dem/program/ContactParts.h"

#include <stdexcept>

namespace geocomp::dem {

ContactModel with_contact_parts(const ContactModel &base, const ContactParameters &c)
{
  const bool rolling = c.rolling_friction > 0.0;
  const bool bonds = c.cohesion > 0.0 || c.adhesion > 0.0;
  const bool s3_friction = c.tangential_model == "s3-stick-slip";
  if (!rolling && !bonds && !s3_friction)
    return base;
  const LinearRolling roll({c.rolling_friction, c.rolling_stiffness_ratio}); // S2, mu_r = 0: no moment
  if (const auto *h = std::get_if<HertzMindlin>(&base)) {
    if (bonds || s3_friction)
      throw std::invalid_argument("contact parts: S3 bonds and S3 friction need the linear normal model");
    return HertzMindlinRolling(h->normal(), h->tangential(), roll);
  }
  const auto *l = std::get_if<LinearSpringDashpot>(&base);
  if (!l)
    throw std::invalid_argument("contact parts: the base law must be linear or hertz-mindlin");
  S3Bonding::Parameters b;
  b.cohesion = c.cohesion;
  b.cohesion_modulus = c.cohesion_modulus;
  b.adhesion = c.adhesion;
  b.adhesion_modulus = c.adhesion_modulus;
  if (s3_friction)
    return S3Soil(l->normal(), StickSlipTangential({c.slip_displacement, c.slip_retention}), roll, S3Bonding(b));
  if (bonds)
    return LinearCohesive(l->normal(), l->tangential(), roll, S3Bonding(b));
  return LinearRollingResistance(l->normal(), l->tangential(), roll);
}

} // namespace geocomp::dem
