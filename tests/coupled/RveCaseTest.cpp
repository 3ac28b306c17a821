// The fem-dem engine through the case file and the command line's engine factory: the
// single-element cube the case makes equals the case's RVE driven alone, at small and at
// finite strain.
#include "compare/case/CaseDescription.h"
#include "compare/cli/CaseValidation.h"
#include "compare/cli/Engines.h"
#include "coupled/case/RveSection.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace geocomp;

namespace {

const char *rve_case = R"(
set engines = fem-dem
subsection specimen
  set particles          = 60
  set radius             = 1e-3
  set size distribution  = uniform
  set radius spread      = 0.2
  set density            = 2650
  set isotropic pressure = 1e5
end
subsection contact
  set normal stiffness   = 1e5
  set restitution        = 0.5
  set particle friction  = 0.5
end
subsection continuum
  set kinematics            = small strain
  set cells per edge        = 1
  set load steps per sample = 1
end
subsection dem rve
  set particles           = 60
  set steps per increment = 100
end
subsection program
  set sampling interval = 0.25
  subsection stage 1
    set name         = every axis kinematic
    set x            = rate 1.5e-3
    set y            = rate 1e-3
    set z            = rate -5e-3
    set stop when    = time >= 0.5
    set max duration = 1
  end
end
)";

} // namespace

TEST(RveCase, TheCasesSingleElementCubeOfRvesEqualsTheCasesRveDrivenAlone)
{
  const CaseDescription c = parse_case(rve_case, "rve.prm");
  const auto scratch = std::filesystem::temp_directory_path();
  const auto engine = cli::make_engine("fem-dem", c, scratch.string(), MPI_COMM_SELF);
  StageControl control;
  control.stage = &c.program.stages.at(0);
  engine->begin_control(control);

  const auto rve = coupled::make_rve_material(c, c.rve); // the same preparation: the same cell
  dem::PeriodicCell alone = rve->prepared();
  continuum::Vector6 previous = continuum::Vector6::Zero();
  for (int k = 1; k <= 2; ++k) {
    engine->advance_to(0.25 * k);
    const ResponseSample s = engine->measure();
    continuum::Vector6 eps = continuum::Vector6::Zero();
    for (int a = 0; a < 3; ++a)
      eps[a] = control.strain(a, 0.25 * k);
    alone.set_velocity_gradient(coupled::RveMaterial::velocity_gradient(eps - previous, c.rve.steps_per_increment,
                                                                        alone.parameters().time_step));
    alone.run(c.rve.steps_per_increment);
    previous = eps;
    const dem::Mat3 expected = alone.stress().total();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        EXPECT_NEAR(s.stress(a, b), expected(a, b), 1e-11 * c.specimen.isotropic_pressure)
          << "sample " << k << " (" << a << b << ")";
  }
  EXPECT_LT(alone.stress().total()(2, 2), -1.05 * c.specimen.isotropic_pressure); // loaded
}

TEST(RveCase, FemDemRunsOnTheCubeAndIsRefusedWhereTheCaseCannotPrepareItsRve)
{
  const CaseDescription c = parse_case(rve_case, "rve.prm");
  EXPECT_NO_THROW(cli::validate_engine("fem-dem", c));
  std::string lognormal = rve_case;
  lognormal.replace(lognormal.find("uniform"), 7, "lognormal-mass");
  try {
    cli::validate_engine("fem-dem", parse_case(lognormal, "rve.prm"));
    FAIL() << "a lognormal RVE accepted";
  } catch (const CaseError &e) {
    EXPECT_NE(std::string(e.what()).find("dem rve"), std::string::npos) << e.what();
  }
}
