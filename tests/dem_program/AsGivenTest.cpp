// `specimen/preparation = as given` (issue 30): an imported packing starts the program
// exactly as read. Run for zero steps, its first sample carries the stress of the file
// itself - the wall stress and the Love-Weber stress evaluated here from the positions,
// radii and k_n alone - with no rest, no consolidation and no isotropic pressure; a LAMMPS
// data file's velocities come with it. An ordered array of touching spheres, consolidated,
// rests for no time (nothing touches), where each rest ran its full second before. Entries
// the source does not use are named.
#include "PreparationCase.h"

#include "common/ProgramRunner.h"
#include "dem/program/LatticePacking.h"
#include "dem/program/SpecimenExchange.h"
#include "dem/program/SpecimenPreparation.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;
namespace fs = std::filesystem;

namespace {
struct Scratch
{
  fs::path dir = fs::temp_directory_path() / ("geocomp-as-given-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

/// A text-source case on `file`, taken as given.
CaseDescription as_given_case(const fs::path &file)
{
  CaseDescription c = preparation_case(1, 0.6);
  c.specimen = SpecimenParameters{};
  c.specimen.source = "text";
  c.specimen.text_file = file.string();
  c.specimen.preparation = "as given";
  c.specimen.isotropic_pressure = 0.0; // not needed
  return c;
}

/// The wall stress and the Love-Weber stress of a packing with the linear law at rest:
/// every overlap delta carries k_n delta along the centre line (no velocity, so no dashpot;
/// no history, so no tangential force). DEM-NOTES section 6: sigma = -(1/V) sum l (x) f over
/// pairs (l = x_j - x_i, f on j) and wall contacts (l = x_p - x_c, f on the particle).
struct FileStress
{
  Tensor3 wall = Tensor3::Zero(), love_weber = Tensor3::Zero();
};

FileStress stress_of(const Packing &p, double k_n)
{
  FileStress s;
  const Eigen::Vector3d L = p.box_max - p.box_min;
  const double V = L.prod();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const Eigen::Vector3d d = p.position[j] - p.position[i];
      const double delta = p.radius[i] + p.radius[j] - d.norm();
      if (delta > 0.0)
        s.love_weber -= d * (k_n * delta * d.normalized()).transpose() / V;
    }
    for (int a = 0; a < 3; ++a)
      for (int side = 0; side < 2; ++side) {
        const double h = side == 0 ? p.position[i][a] - p.box_min[a] : p.box_max[a] - p.position[i][a];
        const double delta = p.radius[i] - h;
        if (delta <= 0.0)
          continue;
        Eigen::Vector3d n = Eigen::Vector3d::Zero(); // into the specimen
        n[a] = side == 0 ? 1.0 : -1.0;
        s.love_weber -= (h * n) * (k_n * delta * n).transpose() / V;
        s.wall(a, a) -= k_n * delta / (2.0 * L[(a + 1) % 3] * L[(a + 2) % 3]);
      }
  }
  return s;
}

LoadingProgram short_triaxial()
{
  LoadingProgram p;
  p.stages = {triaxial_stage(kPressure, 0.5, 0.001)};
  p.sample_interval = 0.001;
  return p;
}
} // namespace

TEST(AsGiven, ImportedPackingRunForZeroStepsSamplesTheStressOfTheFile)
{
  Scratch scratch;
  const fs::path file = scratch.dir / "consolidated.xyzr";
  const Packing exported = packing_of(consolidated().system, 2650.0);
  write_packing_file(file, exported);
  const CaseDescription c = as_given_case(file);
  PreparedSpecimen s = prepare_specimen(c);
  EXPECT_EQ(s.system.n_steps(), 0u); // no rest, no consolidation
  DemEngine engine(std::move(s.system), engine_parameters());
  const LoadingProgram program = short_triaxial();
  const Response r = ProgramRunner(program, engine).run();
  const ResponseSample &first = r.samples.front();
  ASSERT_EQ(first.time, 0.0);
  const FileStress expected = stress_of(read_packing_file(file), contact_parameters().normal_stiffness);
  const double p = -expected.love_weber.trace() / 3.0;
  ASSERT_GT(p, 0.5 * kPressure);
  const Tensor3 lw{{first.extras[DemEngine::kLoveWeberXX], first.extras[DemEngine::kLoveWeberXY],
                    first.extras[DemEngine::kLoveWeberXZ]},
                   {first.extras[DemEngine::kLoveWeberXY], first.extras[DemEngine::kLoveWeberYY],
                    first.extras[DemEngine::kLoveWeberYZ]},
                   {first.extras[DemEngine::kLoveWeberXZ], first.extras[DemEngine::kLoveWeberYZ],
                    first.extras[DemEngine::kLoveWeberZZ]}};
  const Tensor3 lw_expected = 0.5 * (expected.love_weber + expected.love_weber.transpose());
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(lw(i, j), lw_expected(i, j), 1e-9 * p) << "Love-Weber " << i << j;
    EXPECT_NEAR(first.stress(i, i), expected.wall(i, i), 1e-9 * p) << "wall " << i;
    // The file was a specimen at rest: its walls and its contacts tell the same stress.
    EXPECT_NEAR(first.stress(i, i), lw(i, i), 0.02 * p) << i;
  }
  EXPECT_EQ(first.stress_mean, first.stress); // no step yet: the mean is the instant
  std::printf("[as given] p_LW of the file %.6g Pa, first sample wall stress %.6g %.6g %.6g Pa\n", p,
              first.stress(0, 0), first.stress(1, 1), first.stress(2, 2));
}

TEST(AsGiven, LammpsDataVelocitiesStartTheProgram)
{
  Scratch scratch;
  Packing moving = fcc_lattice(2, 0.005, 2650.0);
  moving.velocity.resize(moving.size());
  moving.angular_velocity.resize(moving.size());
  for (std::size_t k = 0; k < moving.size(); ++k) {
    moving.velocity[k] = Eigen::Vector3d(0.01 * double(k), -0.02, 0.003 * double(k % 3));
    moving.angular_velocity[k] = Eigen::Vector3d(1.0, double(k), -2.0);
  }
  const fs::path file = scratch.dir / "moving.data";
  write_packing_file(file, moving);
  const Packing back = read_packing_file(file);
  ASSERT_EQ(back.velocity.size(), moving.size());
  PreparedSpecimen s = prepare_specimen(as_given_case(file));
  for (std::size_t k = 0; k < moving.size(); ++k) {
    const Index i = s.system.index_of(ParticleId(k));
    EXPECT_EQ(s.system.particles().v[i], moving.velocity[k]) << k;
    EXPECT_EQ(s.system.particles().omega[i], moving.angular_velocity[k]) << k;
  }
}

TEST(AsGiven, AnOrderedArrayOfTouchingSpheresRestsForNoTime)
{
  // Consolidated (not as given): both rests end at once, since nothing touches; the
  // servo then consolidates the array to sigma_0. Each rest used to run its whole 1 s.
  Scratch scratch;
  const fs::path file = scratch.dir / "fcc.xyzr";
  write_packing_file(file, fcc_lattice(4, 0.005, 2650.0));
  CaseDescription c = as_given_case(file);
  c.specimen.preparation = "consolidate";
  c.specimen.isotropic_pressure = kPressure;
  c.contact = contact_parameters();
  c.dem = dem_parameters();
  std::vector<std::string> phases;
  const PreparedSpecimen s =
    prepare_specimen(c, {}, [&](const std::string &phase, double, double) { phases.push_back(phase); });
  EXPECT_EQ(s.record.frictionless.steps, 0u);
  EXPECT_EQ(s.record.frictional.steps, 0u);
  EXPECT_NE(std::find(phases.begin(), phases.end(), "rest (frictionless): nothing touches, ended at once"),
            phases.end());
  EXPECT_LT(s.record.consolidated.stress_error, 0.005);
  std::printf("[as given] FCC array of %zu spheres consolidated in %llu steps, %.2f s\n", s.system.n_particles(),
              (unsigned long long)s.record.consolidation.steps, s.record.wall_seconds);
}

TEST(AsGiven, EntriesTheSourceDoesNotUseAreNamed)
{
  CaseDescription c = as_given_case("packing.xyzr");
  c.specimen.particles = 5000;
  c.specimen.radius = 0.01;
  c.specimen.isotropic_pressure = 1e5;
  const std::vector<std::string> unused = ignored_specimen_entries(c);
  ASSERT_EQ(unused.size(), 3u);
  EXPECT_EQ(unused[0],
            c.file + ": specimen/particles = 5000 is not used: the packing file gives the spheres and the box");
  EXPECT_NE(unused[1].find("specimen/radius = 0.01 is not used"), std::string::npos);
  EXPECT_NE(unused[2].find("specimen/isotropic pressure = 100000 is not used: the packing is taken as given"),
            std::string::npos);
  CaseDescription g = preparation_case(100, 0.6);
  EXPECT_TRUE(ignored_specimen_entries(g).empty());
  g.specimen.text_file = "left-over.xyzr";
  ASSERT_EQ(ignored_specimen_entries(g).size(), 1u);
  EXPECT_NE(ignored_specimen_entries(g)[0].find("specimen/text file = left-over.xyzr is not used: source = generate"),
            std::string::npos);
}
