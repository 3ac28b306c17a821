#include "coupled/wall/TriaxialCurve.h"

#include "common/ProgramRunner.h"
#include "dem/case/DemParameters.h"
#include "dem/periodic/PeriodicProgram.h"
#include "dem/program/DemEngine.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::coupled {

namespace {

void check(const TriaxialTest &t)
{
  if (!(t.pressure > 0.0) || !(t.strain_rate > 0.0) || !(t.axial_strain > 0.0) || !(t.record_strain > 0.0))
    throw std::invalid_argument("triaxial test: needs a positive pressure, strain rate, axial strain and record strain");
}

/// Mean diameter and density of the spheres of a store.
struct Grains {
  double diameter = 0.0, density = 0.0;
};
Grains grains_of(const dem::ParticleStore &p)
{
  Grains g;
  double volume = 0.0, mass = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    g.diameter += 2.0 * p.radius[k];
    volume += 4.0 / 3.0 * M_PI * p.radius[k] * p.radius[k] * p.radius[k];
    mass += p.mass[k];
  }
  g.diameter /= double(std::max<std::size_t>(p.size(), 1));
  g.density = volume > 0.0 ? mass / volume : 0.0;
  return g;
}

/// I = d(eps_lat - eps_zz)/dt d sqrt(rho / p) from each point and the one before.
void set_inertial_numbers(TriaxialCurve &curve, const Grains &g)
{
  auto gamma = [](const TriaxialPoint &q) { return 0.5 * (q.volumetric_strain + q.axial_strain) + q.axial_strain; };
  for (std::size_t k = 1; k < curve.size(); ++k) {
    const double dt = curve[k].time - curve[k - 1].time;
    if (dt > 0.0 && curve[k].pressure > 0.0)
      curve[k].inertial_number = (gamma(curve[k]) - gamma(curve[k - 1])) / dt * g.diameter *
                                 std::sqrt(g.density / curve[k].pressure);
  }
}

} // namespace

TriaxialCurve triaxial_on_walls(dem::DemSystem specimen, const TriaxialTest &t)
{
  check(t);
  const Grains g = grains_of(specimen.particles());
  Stage stage;
  stage.name = "triaxial compression";
  stage.axes = {AxisDrive::stress(-t.pressure), AxisDrive::stress(-t.pressure), AxisDrive::rate(-t.strain_rate)};
  const double end = std::expm1(-t.axial_strain); // engineering eps_zz at the logarithmic end
  stage.stop_any = {Condition{Quantity::EpsZZ, false, end, "eps_zz <= " + std::to_string(end)}};
  stage.max_duration = 2.0 * t.axial_strain / t.strain_rate;
  LoadingProgram program;
  program.stages = {stage};
  program.sample_interval = t.record_strain / t.strain_rate;

  dem::DemEngineParameters parameters = dem::DemEngineParameters::from_case(dem::DemParameters{});
  parameters.check_interrupts = false;
  dem::DemEngine engine(std::move(specimen), parameters);
  ProgramRunner runner(program, engine);
  const Response r = runner.run();

  TriaxialCurve curve;
  for (const ResponseSample *s : r.path(0)) {
    TriaxialPoint q;
    q.time = s->time;
    q.axial_strain = -std::log1p(s->strain(2, 2));
    q.volumetric_strain = std::log1p(s->strain(0, 0)) + std::log1p(s->strain(1, 1)) + std::log1p(s->strain(2, 2));
    q.deviator = 0.5 * (s->stress(0, 0) + s->stress(1, 1)) - s->stress(2, 2);
    q.pressure = -s->stress.trace() / 3.0;
    q.lateral_error = std::max(std::abs(s->stress(0, 0) + t.pressure), std::abs(s->stress(1, 1) + t.pressure)) / t.pressure;
    curve.push_back(q);
  }
  set_inertial_numbers(curve, g);
  return curve;
}

TriaxialCurve triaxial_on_cell(dem::PeriodicCell &cell, const TriaxialTest &t)
{
  check(t);
  dem::TriaxialShear shear;
  shear.axis = 2;
  shear.lateral_pressure = t.pressure;
  shear.strain_rate = t.strain_rate;
  shear.axial_strain = t.axial_strain;
  shear.record_interval =
    std::max<std::uint64_t>(1, std::uint64_t(std::llround(t.record_strain / (t.strain_rate * cell.parameters().time_step))));
  TriaxialCurve curve;
  for (const dem::TriaxialRecord &rec : dem::shear_triaxial(cell, shear)) {
    TriaxialPoint q;
    q.time = rec.axial_strain / t.strain_rate; // L_zz = -rate: the logarithmic strain grows linearly
    q.axial_strain = rec.axial_strain;
    q.volumetric_strain = rec.volumetric_strain;
    q.deviator = rec.deviator;
    q.pressure = rec.pressure;
    q.lateral_error = rec.lateral_error;
    curve.push_back(q);
  }
  set_inertial_numbers(curve, grains_of(cell.particles()));
  return curve;
}

} // namespace geocomp::coupled
