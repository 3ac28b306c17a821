// Case-file entries of the optional contact parts reach the DEM law: rolling resistance
// (S2), S3 bonds, adhesion and stick-slip friction; a case without them gets the base law.
#include "ContactCase.h"

#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"

#include <gtest/gtest.h>

#include <string>

using namespace geocomp;
using namespace geocomp::dem;

namespace {
CaseDescription case_with(const std::string &contact) { return test::contact_case(contact, "parts.prm"); }
} // namespace

TEST(ContactPartsCase, NoPartsGivesTheBaseLaw)
{
  const CaseDescription c = case_with("");
  EXPECT_EQ(c.contact.rolling_friction, 0.0);
  EXPECT_TRUE(std::holds_alternative<LinearSpringDashpot>(make_contact_model(c.contact)));
}

TEST(ContactPartsCase, RollingFrictionSwitchesOnS2RollingResistance)
{
  const CaseDescription c = case_with("  set rolling friction = 0.7\n");
  const ContactModel m = make_contact_model(c.contact);
  ASSERT_TRUE(std::holds_alternative<LinearRollingResistance>(m));
  EXPECT_EQ(std::get<LinearRollingResistance>(m).rolling().parameters().mu_r, 0.7);
  ContactParameters hertz = c.contact;
  hertz.model = "hertz-mindlin";
  EXPECT_TRUE(std::holds_alternative<HertzMindlinRolling>(make_contact_model(hertz)));
}

TEST(ContactPartsCase, CohesionAdhesionAndStickSlipReachTheS3Law)
{
  const CaseDescription c = case_with("  set cohesion = 2e4\n  set cohesion modulus = 3e6\n  set adhesion = 1e3\n"
                                      "  set tangential model = s3-stick-slip\n  set slip retention = 0\n"
                                      "  set slip displacement = 2e-5\n  set wall bonding = true\n");
  const ContactModel m = make_contact_model(c.contact);
  ASSERT_TRUE(std::holds_alternative<S3Soil>(m));
  const S3Soil &law = std::get<S3Soil>(m);
  EXPECT_EQ(law.cohesion().parameters().cohesion, 2e4);
  EXPECT_EQ(law.cohesion().parameters().cohesion_modulus, 3e6);
  EXPECT_EQ(law.cohesion().parameters().adhesion, 1e3);
  EXPECT_EQ(law.tangential().parameters().retention, 0.0);
  EXPECT_EQ(law.tangential().parameters().slip_displacement, 2e-5);
  EXPECT_TRUE(c.contact.wall_bonding);
  ContactParameters coulomb = c.contact;
  coulomb.tangential_model = "coulomb";
  EXPECT_TRUE(std::holds_alternative<LinearCohesive>(make_contact_model(coulomb)));
}

TEST(ContactPartsCase, BondsOnHertzMindlinAreRefusedNamingTheParameter)
{
  try {
    case_with("  set model = hertz-mindlin\n  set cohesion = 1e4\n");
    FAIL() << "expected a CaseError";
  } catch (const CaseError &e) {
    EXPECT_EQ(e.parameter, "contact/cohesion");
  }
}

TEST(ContactPartsCase, AClumpSectionIsRefusedForNoEngineOfTheMainCaseReadsIt)
{
  // Clumped grains are the shear-box case's (`grains`); the wall-box engine packs spheres, so
  // a `clumps` section would be silently ignored: refused instead, naming the entry.
  try {
    parse_case("set engines = dem\nsubsection clumps\n  set shape = s4-clumps\nend\n"
               "subsection program\n  subsection stage 1\n    set z = rate -1\n    set stop when = eps_zz <= -0.01\n"
               "    set max duration = 1\n  end\nend\n",
               "clumps.prm");
    FAIL() << "expected a CaseError";
  } catch (const CaseError &e) {
    EXPECT_NE(std::string(e.what()).find("clumps"), std::string::npos) << e.what();
  }
}
