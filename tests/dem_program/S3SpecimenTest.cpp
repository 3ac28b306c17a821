// S3 (Lanis & Khan) in a specimen (issue 33, item 3): the shipped cases
// cases/s3_bonded_{compression,tension}.prm, s3_bonded_compression_cc2.prm and
// s3_stick_slip_kphi{0,1}.prm (their contact laws and programs), on one packing of 216
// spheres instead of 1 000: each run takes a copy and the case's contact law, whose bonds
// form at the prepared state as in a case run.
// S3's claims asserted: the bonded packing carries tension, its tensile strength is below its
// compressive strength (S3: "the strength in compression is much greater than in tension"),
// the strength rises with C_c, and bonds break for good as the specimen strains; in shear,
// S3's friction with k_phi = 0 leaves the packing weaker than with k_phi = 1; and through a
// tension - re-contact - tension cycle (cases/s3_{adhesion,bonded}_cycle.prm) adhesion C_a
// carries tension again after its crack closed, where cohesion C_c of the same strength does not.
#include "common/ProgramRunner.h"
#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"
#include "dem/program/LatticePacking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
  c.dem.threads = 1;
  return c;
}

/// The packing every case shares, built once per process: 6^3 spheres of the cases' radii on
/// a loose jittered lattice, compacted by the servo walls to the cases' 10 kPa without
/// friction, then held with the cases' friction (as tests/dem_program/Specimen.h; the cases'
/// radius growth at 10 kPa takes minutes). Without S3's parts, as prepare_specimen() makes it:
/// the bonds form on its touching pairs at the program's first step.
const DemSystem &packing()
{
  static const DemSystem s = [] {
    const CaseDescription c = small_case("s3_bonded_compression");
    const double p0 = c.specimen.isotropic_pressure;
    ContactParameters base = c.contact;
    base.cohesion = 0.0;
    base.particle_friction = 0.0;
    DemSystem loose = make_system(jittered_lattice(6, c.specimen.radius, 0.1, 0.3, c.specimen.density, c.seed), base,
                                  c.dem);
    loose.set_local_damping(0.5);  // preparation only
    DemEngine compact(std::move(loose), DemEngineParameters::from_case(c.dem));
    hold_isotropic(compact, p0, 0.005, 1e-2, 2.0, 0.002);
    DemSystem dense = compact.system();
    dense.set_friction(c.contact.particle_friction);
    dense.set_local_damping(0.0);
    DemEngine hold(std::move(dense), DemEngineParameters::from_case(c.dem));
    const HoldResult h = hold_isotropic(hold, p0, 0.005, 1e-3, 2.0, 0.002);
    std::printf("packing: %zu spheres at %.0f Pa, converged %d (error %.2e, UFR %.2e)\n", hold.system().n_particles(),
                p0, int(h.converged), h.stress_error, h.unbalanced);
    DemSystem out = hold.system();
    for (int w = 0; w < 6; ++w)
      out.set_wall_velocity(w, Vec3::Zero());
    return out;
  }();
  return s;
}

struct Outcome {
  double peak = 0.0;            ///< [Pa] largest |sigma_zz| in the loading sense
  double late_mean = 0.0;       ///< [Pa] mean of the loading-sense sigma_zz past half the program's strain
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
  double last = 0.0;
  int n_late = 0;
  const double half = 0.5 * std::abs(r.samples.back().strain(2, 2));
  for (const ResponseSample &s : r.samples) {
    const double stress = sense * s.stress(2, 2);
    if (std::abs(s.strain(2, 2)) >= half) {
      out.late_mean += stress;
      ++n_late;
    }
    out.peak = std::max(out.peak, stress);
    out.broken_never_fall = out.broken_never_fall && s.extras[broken] >= last;
    last = s.extras[broken];
  }
  out.broken_end = last;
  out.late_mean /= std::max(n_late, 1);
  std::printf("%s: peak %.1f kPa, late mean %.1f kPa, bonds %.0f at the start, %.0f broken at the end\n",
              name.c_str(), out.peak * 1e-3, out.late_mean * 1e-3, out.bonds0, out.broken_end);
  return out;
}

/// The tensile strength of each tension stage of a tension - re-contact - tension cycle.
struct Cycle {
  double first = 0.0;   ///< [Pa] largest sigma_zz (tension positive) in stage 1
  double second = 0.0;  ///< [Pa] largest sigma_zz in stage 3, after the crack closed
  double closed = 0.0;  ///< [Pa] sigma_zz at the start of stage 3 (end of the re-compression)
};

Cycle run_cycle(const std::string &name)
{
  const CaseDescription c = small_case(name);
  DemSystem system = packing();
  set_contact_law(system, c.contact);
  DemEngine engine(std::move(system), DemEngineParameters::from_case(c.dem));
  const Response r = with_interval_means(ProgramRunner(c.program, engine).run());
  Cycle out;
  out.first = out.second = -1e30;
  // Each pull's strength is its largest sigma_zz after the stage's first sample: the first
  // sample of the program is taken in the step where every touching pair's adhesion forms
  // at once (the platens' too, four times a grain's: 766 kPa on the 216 spheres, gone by the
  // next sample); the third stage starts in compression.
  bool third = false;
  int previous_stage = -1;
  for (const ResponseSample &s : r.samples) {
    const bool stage_start = s.stage != previous_stage;
    previous_stage = s.stage;
    if (s.stage == 2 && !third) {
      out.closed = s.stress(2, 2);
      third = true;
    }
    if (stage_start)
      continue;
    if (s.stage == 0)
      out.first = std::max(out.first, s.stress(2, 2));
    if (s.stage == 2)
      out.second = std::max(out.second, s.stress(2, 2));
  }
  EXPECT_TRUE(third) << name << ": the program reached its third stage";
  std::printf("%s: tensile peak %.1f kPa, after re-contact %.1f kPa (%.0f %%), sigma_zz at re-contact %.1f kPa\n",
              name.c_str(), out.first * 1e-3, out.second * 1e-3, 100.0 * out.second / out.first, out.closed * 1e-3);
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
    EXPECT_GT(r->bonds0, 216.0) << "every touching pair bonded at the prepared state (Z > 2)";
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

TEST(S3Specimen, StickSlipFrictionWeakensTheShearedPackingBelowCoulombSliding)
{
  // S3 eq. (9): with k_phi = 0 every slip drops a contact's friction to zero and it climbs
  // back over delta*_tau (the saw-tooth, tests/dem/StickSlipShearTest.cpp), so a sliding
  // contact carries mu F_n / 2 on average; with k_phi = 1 it keeps mu F_n. The packing's
  // contacts slip out of step, so the specimen shows no saw-tooth at its sampling, but its
  // sliding strength drops.
  const Outcome stick_slip = run("s3_stick_slip_kphi0"), coulomb = run("s3_stick_slip_kphi1");
  EXPECT_LT(stick_slip.late_mean, 0.97 * coulomb.late_mean);
  EXPECT_EQ(stick_slip.bonds0, 0.0);
}

TEST(S3Specimen, AdhesionCarriesTensionAgainAfterTheCrackClosesWhereCohesionDoesNot)
{
  // S3 eq. (7)-(8): C = C_c + C_a, the bond C_c breaks for good, the capillary adhesion C_a
  // forms again whenever grains meet. The same packing, the same strength (1 MPa) and
  // spring (50 MPa) - one as a bond, one as adhesion - pulled until it cracks, closed by
  // compression and pulled again.
  const Cycle adhesion = run_cycle("s3_adhesion_cycle"), cohesion = run_cycle("s3_bonded_cycle");
  // Both carry net tension the first time (above the 10 kPa lateral confinement's share).
  EXPECT_GT(adhesion.first, 2.0 * 10e3);
  EXPECT_GT(cohesion.first, 2.0 * 10e3);
  // Restored: the re-contacted adhesive specimen is nearly as strong as at first.
  EXPECT_GT(adhesion.second, 0.7 * adhesion.first);
  // Not restored: the broken bonds across the crack stay broken; only bonds of first-time
  // contacts hold the second pull (few here: this lattice-built packing closes its crack onto
  // the old partners; the shipped 1 000-sphere cases bond many new pairs and recover 71 %,
  // docs/s3-bonded.md).
  EXPECT_LT(cohesion.second, 0.5 * cohesion.first);
  EXPECT_GT(adhesion.second / adhesion.first, cohesion.second / cohesion.first + 0.3);
}
