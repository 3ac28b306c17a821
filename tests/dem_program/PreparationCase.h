// A small case for the specimen-preparation tests: N spheres of R = 5 mm, k_n = 2e5 N/m
// (kappa = k_n/(p d) = 200 at sigma_0 = 100 kPa), mu_s = 0.4, one thread.
#pragma once

#include "Specimen.h"

#include "compare/case/CaseDescription.h"

namespace geocomp::dem::test {

inline CaseDescription preparation_case(unsigned particles, double packing_fraction, std::uint64_t seed = 7)
{
  CaseDescription c;
  c.file = "preparation-test.prm";
  c.seed = seed;
  c.specimen.source = "generate";
  c.specimen.particles = particles;
  c.specimen.packing_fraction = packing_fraction;
  c.specimen.radius = 0.005;
  c.specimen.density = 2650.0;
  c.specimen.isotropic_pressure = kPressure;
  c.contact = contact_parameters();
  c.dem = dem_parameters();
  return c;
}

} // namespace geocomp::dem::test
