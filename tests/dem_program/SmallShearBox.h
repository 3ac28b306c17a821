// A small S4 direct shear box for the tests (DirectShearTest, FloatingBoxTest): 3 x 3 cm,
// halves 9 mm, grains of 1/8 of S4's mass (half the size) so that ~230 clumps fill it,
// modulus x 1/100 (S4's rubble: 58.54 GPa), 100 kPa, 3 mm of shear at 0.05 m/s
// (I = 8e-4), a free upper box of 0.2 kg with W_B = 2 N (P = 90 N) and a top stop 6 mm
// above its seat.
#pragma once

#include "dem/program/DirectShearBox.h"

#include <cmath>
#include <cstdint>

namespace geocomp::dem::test {

inline DirectShearParameters small_shear_box(std::uint64_t seed)
{
  DirectShearParameters p;
  p.length = p.width = 0.03;
  p.half_height = 0.009;
  p.clumps.log_mass_mean -= std::log(8.0);
  p.clumps.mass_min /= 8.0;
  p.clumps.mass_max /= 8.0;
  p.modulus_scale = 0.01;
  p.normal_stress = 100e3;
  p.shear_speed = 0.05;
  p.max_shear = 0.003;
  p.output_points = 30;
  p.growth_stages = 8;
  p.settle_steps = 600;
  p.load_max_time = 0.05;
  p.seed = seed;
  p.upper_box_free = true;
  p.box_mass = 0.2;
  p.box_weight = 2.0;
  p.box_max_rise = 0.006;
  return p;
}

}  // namespace geocomp::dem::test
