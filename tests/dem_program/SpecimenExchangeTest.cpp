// Specimen exchange (SpecimenExchange.h): a stored specimen exported to xyzr text and to a
// LAMMPS/LIGGGHTS data file reads back exactly (17 digits), in the box of its walls, and
// an exported packing made into a specimen again (`source = text`) consolidates to the
// same sigma_0 and nearly the same packing fraction: a specimen leaves and returns.
#include "compare/case/CaseDescription.h"
#include "dem/program/SpecimenExchange.h"
#include "dem/program/SpecimenPreparation.h"
#include "dem/program/SpecimenStore.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace geocomp;
using namespace geocomp::dem;
namespace fs = std::filesystem;

namespace {

struct ExchangeDir
{
  fs::path path;
  ExchangeDir() : path(fs::temp_directory_path() / ("geocomp-exchange-" + std::to_string(::getpid())))
  {
    fs::create_directories(path);
  }
  ~ExchangeDir() { fs::remove_all(path); }
};

const StoredSpecimen &committed_specimen()
{
  static const StoredSpecimen s = [] {
    const fs::path store = fs::path(GEOCOMP_SOURCE_DIR) / "cases/store/small.h5";
    return read_stored_specimen(store, stored_specimen_names(store).front());
  }();
  return s;
}

void expect_same_packing(const Packing &a, const Packing &b)
{
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.box_min, b.box_min);
  EXPECT_EQ(a.box_max, b.box_max);
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.position[i], b.position[i]) << "sphere " << i;
    ASSERT_EQ(a.radius[i], b.radius[i]) << "sphere " << i;
  }
}

} // namespace

TEST(SpecimenExchange, StoredSpecimenExportsToBothFormatsAndReadsBackExactly)
{
  const StoredSpecimen &s = committed_specimen();
  const Packing p = packing_of(s.system, s.metadata.density);
  ASSERT_EQ(p.size(), s.system.n_particles());
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(p.box_min[a], s.system.wall(2 * a).point[a]);
    EXPECT_EQ(p.box_max[a], s.system.wall(2 * a + 1).point[a]);
  }
  for (ParticleId id = 0; id < s.system.n_particles(); ++id)
    ASSERT_EQ(p.position[id], s.system.position(id));

  ExchangeDir dir;
  for (const char *name : {"specimen.xyzr", "specimen.data"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir.path / name;
    write_packing_file(file, p);
    expect_same_packing(read_packing_file(file), p);
  }
  EXPECT_TRUE(is_lammps_data_file("a/b.data"));
  EXPECT_FALSE(is_lammps_data_file("a/b.xyzr"));
}

TEST(SpecimenExchange, ExportedPackingConsolidatesAgainToTheSameStressAndDensity)
{
  const StoredSpecimen &s = committed_specimen();
  ExchangeDir dir;
  const fs::path data = dir.path / "small.data", prm = dir.path / "small.prm";
  write_packing_file(data, packing_of(s.system, s.metadata.density));
  std::ofstream(prm) << s.metadata.case_text;
  CaseDescription c = read_case(prm.string());
  c.specimen.source = "text";
  c.specimen.text_file = data.string();

  const PreparedSpecimen again = prepare_specimen(c);
  EXPECT_EQ(again.system.n_particles(), s.system.n_particles());
  const double p0 = s.metadata.isotropic_pressure;
  EXPECT_TRUE(again.record.consolidated.converged);
  EXPECT_LE(again.record.consolidated.stress_error, 0.005) << "sigma_0 = " << p0;
  // The exported state was at rest at sigma_0. It comes back without its tangential
  // springs and relaxes frictionless first (`source = text`), so it settles near, not at,
  // the stored state (measured: 0.6396 against 0.6420, 0.4 % looser).
  EXPECT_NEAR(again.record.final_packing_fraction, s.record.final_packing_fraction, 0.005);
  EXPECT_NE(again.record.method.find(data.string()), std::string::npos);
}
