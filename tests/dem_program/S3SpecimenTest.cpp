// S3 (Lanis & Khan) in a specimen (issue 33, item 3): the shipped cases
// cases/s3_bonded_{compression,tension}.prm, s3_bonded_compression_cc2.prm and
// s3_stick_slip_kphi{0,1}.prm, on 200 spheres
// instead of 1 000. The preparation has no bonds (they form at the prepared state), so one
// prepared packing serves every case: each run takes a copy and the case's contact law.
// S3's claims asserted: the bonded packing carries tension, its tensile strength is below its
// compressive strength (S3: "the strength in compression is much greater than in tension"),
// the strength rises with C_c, and bonds break for good as the specimen strains; in shear,
// S3's friction with k_phi = 0 drops the stress in steps where k_phi = 1 does not.
#include "common/ProgramRunner.h"
#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"
#include "dem/program/SpecimenPreparation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace geocomp;
using namespace geocomp::dem;

namespace {
std::string source_dir()
{
  return std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : GEOCOMP_SOURCE_DIR;
}

CaseDescription small_case(const std::string &name)
{
  CaseDescription c = read_case(source_dir() + "/cases/" + name + ".prm");
  c.specimen.particles = 200;
  c.dem.threads = 1;
  return c;
}

/// The packing every case shares: prepared once per process (no bonds in preparation).
const DemSystem &packing()
{
  static const DemSystem s = prepare_specimen(small_case("s3_bonded_compression")).system;
  return s;
}

struct Outcome {
  double peak = 0.0;            ///< [Pa] largest |sigma_zz| in the loading sense
  int drops = 0;                ///< samples at which sigma_zz fell by more than 5 % of its value
  double bonds0 = 0.0;          ///< intact bonds at the start
  double broken_end = 0.0;      ///< broken bonds at the end
  bool broken_never_fall = true;
};

Outcome run(const std::string &name)
{
  const CaseDescription c = small_case(name);
  DemSystem system = packing();
  set_contact_law(system, c.contact);
  DemEngine engine(std::move(system), DemEngineParameters::from_case(c.dem));
  const Response r = with_interval_means(ProgramRunner(c.program, engine).run());
  const int intact = r.extra_index("intact_bonds"), broken = r.extra_index("broken_bonds");
  const double sense = c.program.stages.front().axes[2].value > 0.0 ? 1.0 : -1.0;
  Outcome out;
  out.bonds0 = r.samples.front().extras[intact];
  double last = 0.0, previous = 0.0;
  for (const ResponseSample &s : r.samples) {
    const double stress = sense * s.stress(2, 2);
    out.drops += stress < 0.95 * previous ? 1 : 0;
    previous = stress;
    out.peak = std::max(out.peak, stress);
    out.broken_never_fall = out.broken_never_fall && s.extras[broken] >= last;
    last = s.extras[broken];
  }
  out.broken_end = last;
  std::printf("%s: peak %.1f kPa, %d drops > 5 %%, bonds %.0f at the start, %.0f broken at the end\n", name.c_str(),
              out.peak * 1e-3, out.drops, out.bonds0, out.broken_end);
  return out;
}
} // namespace

TEST(S3Specimen, TensileStrengthOfABondedPackingIsAFractionOfItsCompressiveStrength)
{
  const Outcome tension = run("s3_bonded_tension"), compression = run("s3_bonded_compression");
  // Net tension on the walls despite the 10 kPa lateral confinement: the bonds carry it.
  EXPECT_GT(tension.peak, 2.0 * 10e3);
  EXPECT_LT(tension.peak, 0.8 * compression.peak) << "S3: tension is the weaker sense";
  for (const Outcome *r : {&tension, &compression}) {
    EXPECT_GT(r->bonds0, 200.0) << "every touching pair bonded at the prepared state";
    EXPECT_TRUE(r->broken_never_fall) << "a broken bond never forms again";
    EXPECT_GT(r->broken_end, 0.02 * r->bonds0) << "the failure breaks bonds";
  }
  // A tensile failure is one crack across the specimen; the compressive one shears and
  // crushes bonds throughout.
  EXPECT_GT(compression.broken_end, 2.0 * tension.broken_end);
}

TEST(S3Specimen, CompressiveStrengthRisesWithTheBondStrengthCc)
{
  const Outcome weak = run("s3_bonded_compression"), strong = run("s3_bonded_compression_cc2");
  EXPECT_GT(strong.peak, 1.3 * weak.peak);
}

TEST(S3Specimen, StickSlipFrictionDropsTheStressWhereCoulombSlidingDoesNot)
{
  // S3 eq. (9): with k_phi = 0 every slip drops the contact's friction to zero, so the
  // sheared packing's stress falls in steps (saw-tooth); with k_phi = 1 it stays at the limit.
  const Outcome stick_slip = run("s3_stick_slip_kphi0"), coulomb = run("s3_stick_slip_kphi1");
  EXPECT_GT(stick_slip.drops, 2 * coulomb.drops + 2);
  EXPECT_EQ(stick_slip.bonds0, 0.0);
}
