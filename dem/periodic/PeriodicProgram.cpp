#include "dem/periodic/PeriodicProgram.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

namespace {
/// sigma_ab = 0 for a != b through the upper triangle of L (the lower one held at zero).
void hold_shear_stress_free(MixedControl& control)
{
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) control.set_stress(a, b, 0.0);
}

bool isotropic_reached(const PeriodicCell& cell, const IsotropicCompression& c)
{
  const Mat3 s = cell.stress().total();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double target = a == b ? -c.pressure : 0.0;
      if (std::abs(s(a, b) - target) > c.tolerance * c.pressure) return false;
    }
  return cell.unbalanced_force_ratio() <= c.unbalanced;
}
}  // namespace

CompressionResult compress_isotropic(PeriodicCell& cell, const IsotropicCompression& c)
{
  if (!(c.pressure > 0.0) || c.check_interval == 0)
    throw std::invalid_argument("compress_isotropic: needs a positive pressure and check interval");
  MixedControl& control = cell.control();
  control.set_velocity_gradient(Mat3::Zero());
  for (int a = 0; a < 3; ++a) control.set_stress(a, a, -c.pressure);
  hold_shear_stress_free(control);
  cell.refresh();
  CompressionResult r;
  while (r.steps < c.max_steps) {
    cell.step();
    ++r.steps;
    if (r.steps % c.check_interval == 0 && isotropic_reached(cell, c)) {
      r.converged = true;
      break;
    }
  }
  r.stress = cell.stress().total();
  r.unbalanced = cell.unbalanced_force_ratio();
  r.packing_fraction = cell.packing_fraction();
  return r;
}

namespace {
TriaxialRecord triaxial_record(const PeriodicCell& cell, const TriaxialShear& t, double edge0, double volume0)
{
  const int a = t.axis, b = (a + 1) % 3, c = (a + 2) % 3;
  const Mat3 s = cell.stress().total();
  TriaxialRecord r;
  r.axial_strain = -std::log(cell.cell().h().col(a).norm() / edge0);
  r.volumetric_strain = std::log(cell.cell().volume() / volume0);
  r.deviator = 0.5 * (s(b, b) + s(c, c)) - s(a, a);
  r.pressure = cell.stress().pressure();
  r.lateral_error = std::max(std::abs(s(b, b) + t.lateral_pressure), std::abs(s(c, c) + t.lateral_pressure)) /
                    t.lateral_pressure;
  return r;
}
}  // namespace

std::vector<TriaxialRecord> shear_triaxial(PeriodicCell& cell, const TriaxialShear& t)
{
  if (t.axis < 0 || t.axis > 2 || !(t.lateral_pressure > 0.0) || !(t.strain_rate > 0.0) || !(t.axial_strain > 0.0) ||
      t.record_interval == 0)
    throw std::invalid_argument("shear_triaxial: needs an axis 0..2 and positive pressure, rate, strain and interval");
  MixedControl& control = cell.control();
  // Measured (docs/dem.md): at 8 /s with the servo capped at 3 /s the lateral stresses
  // lagged 60 % behind -p by 5 % strain; an isochoric shear needs half the axial rate
  // laterally, dilation more.
  if (control.parameters().max_strain_rate < t.strain_rate)
    throw std::invalid_argument("shear_triaxial: the servo's largest strain rate is below the axial rate; the lateral "
                                "stresses could not follow");
  control.set_velocity_gradient(Mat3::Zero());
  control.set_strain_rate(t.axis, t.axis, -t.strain_rate);
  for (int k = 1; k <= 2; ++k) control.set_stress((t.axis + k) % 3, (t.axis + k) % 3, -t.lateral_pressure);
  hold_shear_stress_free(control);
  cell.refresh();
  const double edge0 = cell.cell().h().col(t.axis).norm(), volume0 = cell.cell().volume();
  std::vector<TriaxialRecord> out;
  out.push_back(triaxial_record(cell, t, edge0, volume0));
  for (std::uint64_t n = 1;; ++n) {
    cell.step();
    const bool done = -std::log(cell.cell().h().col(t.axis).norm() / edge0) >= t.axial_strain;
    if (n % t.record_interval == 0 || done) out.push_back(triaxial_record(cell, t, edge0, volume0));
    if (done) break;
  }
  return out;
}

}  // namespace geocomp::dem
