#include "dem/program/SpecimenPreparation.h"

#include "dem/program/LatticePacking.h"
#include "dem/specimen/Packing.h"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geocomp::dem {

namespace {

/// The loose start: the case's text file, or a jittered lattice with at least N sites
/// (the first N kept), radius R and the uniform spread when the distribution is uniform.
Packing loose_packing(const CaseDescription &c, std::string &method)
{
  const SpecimenParameters &s = c.specimen;
  if (s.source == "text") {
    try {
      Packing p = read_xyzr(s.text_file);
      p.density = s.density;
      if (p.size() == 0)
        throw CaseError(c.file, "specimen/text file", "'" + s.text_file + "' holds no spheres");
      method = "text file " + s.text_file;
      return p;
    } catch (const PackingFileError &e) {
      throw CaseError(c.file, "specimen/text file", e.what());
    }
  }
  if (s.source != "generate")
    throw CaseError(c.file, "specimen/source", "'" + s.source + "' is not available in this build (expected generate or text)");
  const int n = int(std::ceil(std::cbrt(double(s.particles)) - 1e-9));
  const double spread = s.size_distribution == "uniform" ? s.radius_spread : 0.0;
  Packing p = jittered_lattice(n, s.radius, spread, 0.1, s.density, c.seed);
  p.position.resize(s.particles);
  p.radius.resize(s.particles);
  method = "jittered lattice";
  return p;
}

/// Holds sigma_0 on all axes, in chunks so that progress can be reported.
HoldResult hold(DemEngine &engine, double pressure, double unbalanced, const PreparationCriteria &k,
                const std::string &phase, const PreparationProgress &progress)
{
  const double interval = k.check_interval_steps * engine.system().time_step();
  const double chunk = 50.0 * interval;
  HoldResult total;
  while (true) {
    const HoldResult r = hold_isotropic(engine, pressure, k.stress_tolerance, unbalanced, chunk, interval);
    total.converged = r.converged;
    total.stress_error = r.stress_error;
    total.unbalanced = r.unbalanced;
    total.time += r.time;
    if (progress)
      progress(phase, total.time);
    if (r.converged || total.time >= k.max_time)
      return total;
  }
}

} // namespace

std::string PreparationRecord::describe() const
{
  std::ostringstream o;
  o << particles << " spheres, " << method << " (seed " << seed << "), packing fraction "
    << initial_packing_fraction << " -> " << final_packing_fraction << "; frictionless servo compaction to "
    << pressure << " Pa in " << frictionless.time << " s of DEM time (stress error " << frictionless.stress_error
    << ", unbalanced-force ratio " << frictionless.unbalanced << "), then with friction at rest after "
    << frictional.time << " s (stress error " << frictional.stress_error << ", unbalanced-force ratio "
    << frictional.unbalanced << "); " << steps << " steps, " << wall_seconds << " s wall";
  return o.str();
}

PreparedSpecimen prepare_specimen(const CaseDescription &c, const PreparationCriteria &criteria,
                                  const PreparationProgress &progress)
{
  const auto start = std::chrono::steady_clock::now();
  PreparationRecord rec;
  Packing loose = loose_packing(c, rec.method);
  rec.method += " + servo compaction";
  rec.seed = c.seed;
  rec.particles = loose.size();
  rec.initial_packing_fraction = loose.packing_fraction();
  rec.pressure = c.specimen.isotropic_pressure;
  if (!(rec.pressure > 0.0))
    throw CaseError(c.file, "specimen/isotropic pressure", "must be > 0 to consolidate a specimen");

  // S0: frictionless particles and walls while the packing forms; preparation damping.
  ContactParameters frictionless = c.contact;
  frictionless.particle_friction = 0.0;
  frictionless.wall_friction = 0.0;
  DemParameters d = c.dem;
  DemSystem loose_system = make_system(loose, frictionless, d);
  loose_system.set_local_damping(std::max(0.5, c.dem.local_damping));
  const DemEngineParameters servo = DemEngineParameters::from_case(c.dem);
  DemEngine compact(std::move(loose_system), servo);
  rec.frictionless = hold(compact, rec.pressure, criteria.preparation_unbalanced, criteria, "compaction", progress);
  if (!rec.frictionless.converged)
    throw std::runtime_error("specimen preparation: the frictionless compaction to " + std::to_string(rec.pressure) +
                             " Pa did not converge in " + std::to_string(criteria.max_time) + " s of DEM time");

  // Friction on, damping as the case says, held until at rest.
  DemSystem dense = compact.system();
  dense.set_friction(c.contact.particle_friction);
  for (std::size_t w = 0; w < dense.n_walls(); ++w)
    dense.set_wall_friction(w, c.contact.wall_friction);
  dense.set_local_damping(c.dem.local_damping);
  DemEngine rest(std::move(dense), servo);
  rec.frictional = hold(rest, rec.pressure, criteria.unbalanced_force_ratio, criteria, "equilibrium", progress);
  if (!rec.frictional.converged)
    throw std::runtime_error("specimen preparation: the specimen did not come to rest at " +
                             std::to_string(rec.pressure) + " Pa in " + std::to_string(criteria.max_time) +
                             " s of DEM time");
  PreparedSpecimen out{rest.system(), {}};
  for (std::size_t w = 0; w < out.system.n_walls(); ++w)
    out.system.set_wall_velocity(w, Vec3::Zero());
  const Vector3 L = rest.box_lengths();
  double solid = 0.0;
  for (double r : out.system.particles().radius)
    solid += 4.0 / 3.0 * M_PI * r * r * r;
  rec.final_packing_fraction = solid / L.prod();
  rec.steps = out.system.n_steps();
  rec.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.record = rec;
  return out;
}

} // namespace geocomp::dem
