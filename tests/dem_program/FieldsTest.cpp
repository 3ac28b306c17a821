// Particle snapshots: written to HDF5 with an XDMF sidecar, read back bit for bit; the
// mid-section displacement map shows the imposed shear.
#include "Specimen.h"

#include "dem/program/Fields.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;

TEST(DemFields, SnapshotsRoundTripThroughHdf5WithXdmfSidecar)
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "geocomp_dem_fields_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "fields.h5";

  DemEngine engine(consolidated().system, engine_parameters());
  Stage stage;
  stage.isochoric = true;
  stage.lambda = 0.0;
  stage.isochoric_rate = 2.0;
  StageControl control;
  control.stage = &stage;
  engine.begin_control(control);
  const ParticleFields f0 = engine.snapshot(0.0);
  engine.advance_to(0.01); // eps_xx = -2 %
  const ParticleFields f1 = engine.snapshot(gamma_max(engine.measure().strain));
  EXPECT_EQ(append_snapshot(file, f0), 0u);
  EXPECT_EQ(append_snapshot(file, f1), 1u);

  const std::vector<ParticleFields> back = read_snapshots(file);
  ASSERT_EQ(back.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const ParticleFields &a = k ? f1 : f0, &b = back[k];
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.label, b.label);
    EXPECT_EQ(a.ids, b.ids);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.displacements, b.displacements);
    EXPECT_EQ(a.velocities, b.velocities);
    EXPECT_EQ(a.angular_velocities, b.angular_velocities);
    EXPECT_EQ(a.radii, b.radii);
    EXPECT_EQ(a.contact_pairs, b.contact_pairs);
    EXPECT_EQ(a.contact_forces, b.contact_forces);
    EXPECT_EQ(a.contact_normal_forces, b.contact_normal_forces);
    EXPECT_EQ(a.wall_contacts, b.wall_contacts);
    EXPECT_EQ(a.wall_contact_forces, b.wall_contact_forces);
    EXPECT_EQ(a.box_min, b.box_min);
    EXPECT_EQ(a.box_size0, b.box_size0);
  }
  EXPECT_GT(f1.contact_pairs.size(), f1.ids.size()); // Z > 2
  EXPECT_FALSE(f1.wall_contacts.empty());
  for (const Vector3 &u : f0.displacements)
    EXPECT_EQ(u, Vector3::Zero());

  // The sidecar names every snapshot, its time, particles and contact lines.
  std::ifstream in(xdmf_path(file));
  std::stringstream xml;
  xml << in.rdbuf();
  const std::string x = xml.str();
  EXPECT_NE(x.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(x.find("fields.h5:/snapshots/s000001/positions"), std::string::npos);
  EXPECT_NE(x.find("TopologyType=\"Polyvertex\" NumberOfElements=\"343\""), std::string::npos);
  EXPECT_NE(x.find("TopologyType=\"Polyline\" NumberOfElements=\"" + std::to_string(f1.contact_pairs.size())),
            std::string::npos);
  EXPECT_NE(x.find("</Xdmf>"), std::string::npos);
  // No temporary files are left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto &e : std::filesystem::directory_iterator(dir))
    ++entries;
  EXPECT_EQ(entries, 2);

  std::filesystem::remove_all(dir);
}
