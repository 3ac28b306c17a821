// The digital core store (SpecimenStore.h): a stored specimen is restored exactly and
// continues bit for bit; the store keeps many specimens; `source = store` goes through
// prepare_specimen; the committed small store (cases/store/small.h5) loads and is at rest.
#include "PreparationCase.h"

#include "common/Hdf5.h"
#include "dem/program/SpecimenStore.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <array>
#include <sstream>
#include <unistd.h>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;
namespace fs = std::filesystem;

namespace {

::testing::AssertionResult identical(const DemSystem &a, const DemSystem &b)
{
  if (a.n_particles() != b.n_particles() || a.n_walls() != b.n_walls())
    return ::testing::AssertionFailure() << "sizes differ";
  if (a.time() != b.time() || a.n_steps() != b.n_steps() || a.time_step() != b.time_step())
    return ::testing::AssertionFailure() << "clock differs";
  for (ParticleId id = 0; id < a.n_particles(); ++id) {
    const Index i = a.index_of(id), j = b.index_of(id);
    const ParticleStore &p = a.particles(), &q = b.particles();
    if (p.x[i] != q.x[j] || p.v[i] != q.v[j] || p.omega[i] != q.omega[j] || p.force[i] != q.force[j] ||
        p.radius[i] != q.radius[j] || p.mass[i] != q.mass[j] || !(p.orientation[i].coeffs() == q.orientation[j].coeffs()))
      return ::testing::AssertionFailure() << "particle " << id << " differs";
  }
  for (std::size_t w = 0; w < a.n_walls(); ++w)
    if (a.wall(w).point != b.wall(w).point || a.wall(w).force != b.wall(w).force)
      return ::testing::AssertionFailure() << "wall " << w << " differs";
  const auto ca = a.export_contact_state(), cb = b.export_contact_state();
  if (ca.size() != cb.size())
    return ::testing::AssertionFailure() << "contact counts differ";
  for (std::size_t k = 0; k < ca.size(); ++k)
    if (ca[k].i != cb[k].i || ca[k].j != cb[k].j || ca[k].overlap != cb[k].overlap || ca[k].shear != cb[k].shear)
      return ::testing::AssertionFailure() << "contact " << k << " differs";
  return ::testing::AssertionSuccess();
}

struct TempDir
{
  fs::path path;
  TempDir() : path(fs::temp_directory_path() / ("geocomp-store-" + std::to_string(::getpid())))
  {
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

const CaseDescription &stored_case()
{
  static const CaseDescription c = [] {
    CaseDescription d = preparation_case(120, 0.69, 21);
    d.text = "# the case text travels with the specimen\n";
    return d;
  }();
  return c;
}

const PreparedSpecimen &specimen()
{
  static const PreparedSpecimen s = prepare_specimen(stored_case());
  return s;
}

/// Squeezes the box along z for n steps (walls moving, contacts sliding).
void squeeze(DemSystem &s, std::size_t n)
{
  s.set_wall_velocity(4, Vec3(0, 0, 0.01));
  s.set_wall_velocity(5, Vec3(0, 0, -0.01));
  s.run(n);
}

} // namespace

TEST(SpecimenStore, RoundTripRestoresTheStateAndContinuesBitForBit)
{
  TempDir dir;
  const fs::path store = dir.path / "store.h5";
  write_stored_specimen(store, "a", specimen(), SpecimenMetadata::from_case(stored_case(), specimen()));
  const StoredSpecimen back = read_stored_specimen(store, "a");
  EXPECT_TRUE(back.exact);
  EXPECT_TRUE(identical(back.system, specimen().system));
  DemSystem original = specimen().system, restored = back.system;
  squeeze(original, 400);
  squeeze(restored, 400);
  EXPECT_TRUE(identical(original, restored));
  EXPECT_GT(original.wall(4).force.norm(), 0.0);
  // Metadata and record.
  EXPECT_EQ(back.metadata.particles, 120u);
  EXPECT_EQ(back.metadata.packing_fraction, 0.69);
  EXPECT_EQ(back.metadata.isotropic_pressure, kPressure);
  EXPECT_EQ(back.metadata.contact.particle_friction, stored_case().contact.particle_friction);
  EXPECT_EQ(back.metadata.seed, 21u);
  EXPECT_EQ(back.metadata.case_text, stored_case().text);
  EXPECT_EQ(back.record.describe(), specimen().record.describe());
}

TEST(SpecimenStore, PortableDatasetsRebuildTheSameSpecimen)
{
  // A build with another binary layout rebuilds from the portable datasets: same
  // positions, radii, velocities and contact histories (not the same bits later on).
  TempDir dir;
  const fs::path store = dir.path / "store.h5";
  write_stored_specimen(store, "a", specimen(), SpecimenMetadata::from_case(stored_case(), specimen()));
  {
    // Corrupt the binary state's tag, as another build's format would look.
    h5::Handle f = h5::open_file(store, true);
    h5::Handle g = h5::open_group(f.id(), "specimens/a");
    H5Ldelete(g.id(), "state", H5P_DEFAULT);
    h5::Handle space(H5Screate_simple(1, std::array<hsize_t, 1>{{8}}.data(), nullptr), H5Sclose);
    h5::Handle set(H5Dcreate2(g.id(), "state", H5T_NATIVE_UCHAR, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
    const char junk[8] = {'O', 'T', 'H', 'E', 'R', 'B', 'L', 'D'};
    H5Dwrite(set.id(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, junk);
  }
  const StoredSpecimen back = read_stored_specimen(store, "a");
  EXPECT_FALSE(back.exact);
  const DemSystem &a = specimen().system, &b = back.system;
  ASSERT_EQ(a.n_particles(), b.n_particles());
  for (ParticleId id = 0; id < a.n_particles(); ++id) {
    EXPECT_EQ(a.position(id), b.position(id));
    EXPECT_EQ(a.velocity(id), b.velocity(id));
    EXPECT_EQ(a.particles().radius[a.index_of(id)], b.particles().radius[b.index_of(id)]);
  }
  for (std::size_t w = 0; w < 6; ++w)
    EXPECT_EQ(a.wall(w).point, b.wall(w).point);
  EXPECT_EQ(a.time_step(), b.time_step());
  DemSystem c = b;
  c.step(); // histories imported, forces at the stored state
  EXPECT_EQ(c.n_touching_pairs(), a.n_touching_pairs());
}

TEST(SpecimenStore, HoldsManySpecimensAndReplacesByName)
{
  TempDir dir;
  const fs::path store = dir.path / "store.h5";
  const SpecimenMetadata m = SpecimenMetadata::from_case(stored_case(), specimen());
  write_stored_specimen(store, "first", specimen(), m);
  write_stored_specimen(store, "second", specimen(), m);
  write_stored_specimen(store, "first", specimen(), m); // replaced, the other kept
  EXPECT_EQ(stored_specimen_names(store), (std::vector<std::string>{"second", "first"}));
  EXPECT_TRUE(identical(read_stored_specimen(store, "second").system, specimen().system));
  try {
    read_stored_specimen(store, "third");
    FAIL() << "no error for an unknown name";
  } catch (const StoreError &e) {
    EXPECT_TRUE(e.missing_name);
    EXPECT_NE(std::string(e.what()).find("second"), std::string::npos) << "the message lists the names";
  }
  EXPECT_THROW(write_stored_specimen(store, "a/b", specimen(), m), StoreError);
  for (const auto &entry : fs::directory_iterator(dir.path))
    EXPECT_EQ(entry.path().filename(), "store.h5") << "no temporary file left behind";
}

TEST(SpecimenStore, SourceStoreGoesThroughPrepareSpecimen)
{
  TempDir dir;
  const fs::path store = dir.path / "store.h5";
  write_stored_specimen(store, "a", specimen(), SpecimenMetadata::from_case(stored_case(), specimen()));
  CaseDescription c = stored_case();
  c.specimen.source = "store";
  c.specimen.store_file = store.string();
  c.specimen.store_name = "a";
  const PreparedSpecimen s = prepare_specimen(c);
  EXPECT_TRUE(identical(s.system, specimen().system));
  c.contact.particle_friction = 0.5; // not what the specimen was made with
  try {
    prepare_specimen(c);
    FAIL() << "a friction other than the stored one was accepted";
  } catch (const CaseError &e) {
    EXPECT_EQ(e.parameter, "contact/particle friction");
  }
  c = stored_case();
  c.specimen.source = "store";
  c.specimen.store_file = (dir.path / "missing.h5").string();
  c.specimen.store_name = "a";
  EXPECT_THROW(prepare_specimen(c), CaseError);
}

TEST(SpecimenStore, CommittedSmallStoreLoadsAtRestAtSigma0)
{
  const fs::path store = fs::path(GEOCOMP_SOURCE_DIR) / "cases/store/small.h5";
  const std::vector<std::string> names = stored_specimen_names(store);
  ASSERT_FALSE(names.empty());
  for (const std::string &name : names) {
    const StoredSpecimen s = read_stored_specimen(store, name);
    SCOPED_TRACE(name);
    EXPECT_TRUE(s.exact) << "the committed store was written by another binary layout: re-pack it";
    EXPECT_EQ(s.system.n_particles(), s.metadata.particles);
    EXPECT_NEAR(s.record.grown_packing_fraction, s.metadata.packing_fraction, 0.002);
    const double p = s.metadata.isotropic_pressure;
    const double L[3] = {s.system.wall(1).point.x() - s.system.wall(0).point.x(),
                         s.system.wall(3).point.y() - s.system.wall(2).point.y(),
                         s.system.wall(5).point.z() - s.system.wall(4).point.z()};
    for (int a = 0; a < 3; ++a) {
      const double area = L[(a + 1) % 3] * L[(a + 2) % 3];
      const double sigma = -(s.system.wall(2 * a + 1).force[a] - s.system.wall(2 * a).force[a]) / (2.0 * area);
      EXPECT_NEAR(sigma, -p, 0.005 * p) << "axis " << a;
    }
    EXPECT_LE(rest_state(s.system).unbalanced, 1e-3);
  }
}
