#include "Engines.h"

#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/fe/CubeEngine.h"

#include <cmath>

namespace geocomp::cli {

namespace {
continuum::PiecewiseLinear table(const HardeningTable &t, double scale)
{
  std::vector<std::pair<double, double>> points;
  for (const auto &[k, v] : t.points)
    points.emplace_back(k, v * scale);
  return continuum::PiecewiseLinear(points);
}

} // namespace

continuum::MaterialParameters continuum_material(const CaseDescription &c)
{
  const ContinuumParameters &p = c.continuum;
  continuum::MaterialParameters m;
  m.model = p.model;
  m.mohr_coulomb.youngs_modulus = p.youngs_modulus;
  m.mohr_coulomb.poisson_ratio = p.poisson_ratio;
  m.mohr_coulomb.cohesion = table(p.cohesion, 1.0);
  m.mohr_coulomb.friction_angle = table(p.friction_angle, M_PI / 180.0);
  m.mohr_coulomb.dilatancy_angle = table(p.dilatancy_angle, M_PI / 180.0);
  m.drucker_prager_matching = p.dp_matching == "inner"   ? continuum::DruckerPragerMatching::inner_cone
                              : p.dp_matching == "outer" ? continuum::DruckerPragerMatching::outer_cone
                                                         : continuum::DruckerPragerMatching::plane_strain;
  try {
    m.mohr_coulomb.validate();
  } catch (const std::invalid_argument &e) {
    throw CaseError(c.file, "continuum", e.what());
  }
  return m;
}

namespace {
/// Cube edge of the specimen: given, or from N, eta and R (S0: L0^3 eta = N 4/3 pi R^3).
double box_size(const SpecimenParameters &s)
{
  if (s.box_size > 0.0)
    return s.box_size;
  return std::cbrt(s.particles * 4.0 / 3.0 * M_PI * std::pow(s.radius, 3) / s.packing_fraction);
}
} // namespace

const std::vector<std::string> &engine_names()
{
  static const std::vector<std::string> names = {"material-point", "continuum", "dem"};
  return names;
}

std::string results_file(const std::string &engine) { return engine + ".h5"; }

std::unique_ptr<LoadingEngine> make_engine(const std::string &name, const CaseDescription &c,
                                           const std::string &output_dir, MPI_Comm communicator)
{
  const double initial_stress = -c.specimen.isotropic_pressure; // tension positive
  if (name == "material-point") {
    continuum::MaterialPointParameters p;
    p.initial_stress = initial_stress;
    p.substeps_per_advance = c.continuum.point_substeps;
    return std::make_unique<continuum::MaterialPointEngine>(continuum_material(c), p);
  }
  if (name == "continuum") {
    continuum::CubeParameters p;
    p.side = box_size(c.specimen);
    p.cells_per_side = c.continuum.cells_per_edge;
    p.degree = c.continuum.degree;
    p.initial_stress = initial_stress;
    p.imperfection_radius = c.continuum.imperfection_radius;
    p.imperfection_cohesion_factor = c.continuum.imperfection_factor;
    for (int a = 0; a < 3; ++a)
      p.imperfection_centre[a] = c.continuum.imperfection_centre[a] * p.side;
    p.regularization = c.continuum.regularization;
    p.linear_solver = c.continuum.linear_solver;
    p.preconditioner = c.continuum.preconditioner;
    p.newton_tolerance = c.continuum.newton_tolerance;
    p.steps_per_advance = c.continuum.load_steps_per_sample;
    p.band_reference_width = c.continuum.reference_element_size;
    if (c.output.fields)
      p.output_directory = output_dir + "/continuum-fields";
    return std::make_unique<continuum::CubeEngine>(p, continuum_material(c), communicator);
  }
  throw CaseError(c.file, "engines", "the '" + name + "' engine is not available in this build");
}

} // namespace geocomp::cli
