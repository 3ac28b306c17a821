// The rate-sweep case file: the shipped cases read, and bad input names file, parameter
// and expectation.
#include "continuum/dynamics/RateSweepCase.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace geocomp::dynamics;

namespace {
std::string source_dir()
{
  const char *d = std::getenv("GEOCOMP_SOURCE_DIR");
  return d ? d : ".";
}
void expect_case_error(const std::string &text, const std::string &parameter, const std::string &fragment)
{
  try {
    parse_rate_sweep_case(text, "bad.prm");
    FAIL() << "no error for: " << text;
  } catch (const geocomp::CaseError &e) {
    EXPECT_EQ(e.file, "bad.prm");
    EXPECT_NE(e.parameter.find(parameter), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}
} // namespace

TEST(S1RateSweepCase, ShippedCasesReadWithS1TableValues)
{
  for (const std::string material : {"concrete", "sandstone"})
    for (const std::string mode : {"compression", "tension"}) {
      const auto c = read_rate_sweep_case(source_dir() + "/cases/s1_" + material + "_" + mode + ".prm");
      EXPECT_EQ(c.setup.material.name, material);
      EXPECT_EQ(c.setup.mode == geocomp::kinetic::LoadingMode::tension, mode == "tension");
      EXPECT_DOUBLE_EQ(c.setup.geometry.width, 6e-3);
      EXPECT_DOUBLE_EQ(c.setup.geometry.height, 9e-3);
      EXPECT_DOUBLE_EQ(c.setup.strain_rates.front(), 1e-3);
      EXPECT_DOUBLE_EQ(c.setup.strain_rates.back(), 1e3);
      const auto table = S1Material::preset(material);
      EXPECT_DOUBLE_EQ(c.setup.material.compressive_strength, table.compressive_strength);
    }
}

TEST(S1RateSweepCase, OverridesAreReadInCaseUnits)
{
  const auto c = parse_rate_sweep_case("subsection material\n set preset = concrete\n set youngs modulus = 30\n"
                                       " set tensile strength = 25\nend\n",
                                       "ok.prm");
  EXPECT_DOUBLE_EQ(c.setup.material.youngs_modulus, 30e9);
  EXPECT_DOUBLE_EQ(c.setup.material.tensile_strength, 25e6);
  EXPECT_DOUBLE_EQ(c.setup.material.compressive_strength, 45.8e6);
}

TEST(S1RateSweepCase, BadInputNamesParameterAndExpectation)
{
  expect_case_error("subsection material\n set density = heavy\nend\n", "material/density", "not a number");
  expect_case_error("subsection material\n set compressive strength = 10\nend\n", "material/compressive strength",
                    "above the yield stress");
  expect_case_error("subsection specimen\n set cells in x = 5\nend\n", "specimen/cells in x", "even");
  expect_case_error("subsection loading\n set strain rates = 1, 1e6\nend\n", "loading/strain rates", "(0, 1e4]");
  expect_case_error("subsection loading\n set mode = shear\nend\n", "mode", "");
  expect_case_error("subsection loading\n set speed = 3\nend\n", "speed", "");
}
