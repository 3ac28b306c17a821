// The `dem rve` case section and the RVE it prepares from the case's grains.
#include "coupled/case/RveSection.h"
#include "dem/DemSystem.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp;

namespace {

/// The grains of the periodic-cell tests: R = 1 mm +- 20 %, k_n = 1e5 N/m, friction 0.5.
dem::DemCase small_grains()
{
  dem::DemCase c;
  c.specimen.radius = 1e-3;
  c.specimen.size_distribution = "uniform";
  c.specimen.radius_spread = 0.2;
  c.specimen.density = 2650.0;
  c.contact.normal_stiffness = 1e5;
  c.contact.restitution = 0.5;
  c.contact.particle_friction = 0.5;
  c.dem.time_step_safety = 0.2;
  c.specimen.isotropic_pressure = 1e5;
  return c;
}

} // namespace

TEST(RveSection, TheSectionIsReadWithItsDefaultsAndTheGivenValues)
{
  dealii::ParameterHandler prm;
  sections::declare_dem_rve(prm);
  prm.parse_input_from_string(
    "subsection dem rve\n  set particles = 80\n  set steps per increment = 50\n  set growth pressure fraction = 1\nend\n");
  const coupled::RveCaseParameters p = sections::parse_dem_rve(prm, sections::Reader{"test.prm"});
  EXPECT_EQ(p.particles, 80u);
  EXPECT_EQ(p.steps_per_increment, 50u);
  EXPECT_EQ(p.growth_pressure_fraction, 1.0);
  EXPECT_EQ(p.local_damping, coupled::RveCaseParameters{}.local_damping);
  EXPECT_EQ(p.seed, coupled::RveCaseParameters{}.seed);
  EXPECT_EQ(p.tangent, "branch secant");
}

TEST(RveSection, TheTangentEntryReachesTheRveMaterial)
{
  dealii::ParameterHandler prm;
  sections::declare_dem_rve(prm);
  prm.parse_input_from_string("subsection dem rve\n  set particles = 60\n  set tangent = contact stiffness\nend\n");
  const coupled::RveCaseParameters p = sections::parse_dem_rve(prm, sections::Reader{"test.prm"});
  EXPECT_EQ(coupled::make_rve_material(small_grains(), p)->parameters().tangent,
            coupled::RveTangent::contact_stiffness);
  coupled::RveCaseParameters q = p;
  q.tangent = "branch secant";
  EXPECT_EQ(coupled::make_rve_material(small_grains(), q)->parameters().tangent, coupled::RveTangent::branch_secant);
}

TEST(RveSection, TheCasesGrainsArePreparedToTheSpecimensPressureWithTheWallBoxEnginesTimeStep)
{
  const dem::DemCase c = small_grains();
  const double pressure = c.specimen.isotropic_pressure;
  coupled::RveCaseParameters p;
  p.particles = 60;
  const auto rve = coupled::make_rve_material(c, p);
  const dem::PeriodicCell &cell = rve->prepared();
  EXPECT_EQ(cell.n_particles(), 60u);
  // Servo tolerance of the preparation: 1 % on every normal stress.
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(cell.stress().elastic(a, a), -pressure, 0.011 * pressure) << "axis " << a;
  // The wall-box engine's step: safety times sqrt(m_min / max(k_n, 3.5 k_t)) for the smallest sphere.
  const double r_min = 0.8e-3, m_min = 2650.0 * 4.0 / 3.0 * M_PI * r_min * r_min * r_min;
  EXPECT_NEAR(cell.parameters().time_step, 0.2 * std::sqrt(m_min / 1e5), 1e-12 * cell.parameters().time_step);
  EXPECT_EQ(cell.parameters().friction, 0.5);
  EXPECT_EQ(rve->parameters().steps_per_increment, p.steps_per_increment);
  for (std::size_t i = 0; i < cell.n_particles(); ++i) {
    EXPECT_GT(cell.particles().radius[i], 0.8e-3 * 0.9) << i; // grown from R(1 +- 0.2)
  }
}

// The growth fraction sets the density: grown frictionless all the way to p, the grains settle
// into a denser packing than when friction takes the last 90 % of the pressure (frictional
// contacts lock the looser arrangement); both cells carry the pressure.
TEST(RveSection, ACellGrownFrictionlessToTheFullPressureIsDenserThanOneGrownToATenth)
{
  const dem::DemCase c = small_grains();
  coupled::RveCaseParameters p;
  p.particles = 60;
  const auto loose = coupled::make_rve_material(c, p);
  p.growth_pressure_fraction = 1.0;
  const auto dense = coupled::make_rve_material(c, p);
  for (const auto *rve : {loose.get(), dense.get()})
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(rve->prepared().stress().elastic(a, a), -c.specimen.isotropic_pressure,
                  0.011 * c.specimen.isotropic_pressure);
  EXPECT_GT(dense->prepared().packing_fraction(), loose->prepared().packing_fraction() + 0.01);
}

TEST(RveSection, ASizeDistributionThePeriodicPlacementDoesNotDrawIsRefused)
{
  dem::DemCase c = small_grains();
  c.specimen.size_distribution = "lognormal-mass";
  EXPECT_THROW(coupled::rve_grains(c), std::invalid_argument);
}
