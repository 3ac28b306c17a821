// The band in the report (docs/coupled.md): both FE engines record their mid-plane on a box mesh
// (compare/cli/MidPlane.h), a homogeneous box's strain field stays at round-off, and a tiny
// FEM x DEM + Mohr-Coulomb pair on a box writes maps with an FE cube and a FEM x DEM panel (no
// DEM panel) and a verdict table with each FE engine's strain-field row.
#include "compare/SectionLocalization.h"
#include "compare/cli/Engines.h"
#include "compare/cli/MidPlane.h"
#include "compare/cli/Pair.h"
#include "compare/cli/PairSections.h"
#include "common/Subprocess.h"
#include "tests/common/FileText.h"
#include "tests/common/ScratchFolder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace {
using namespace geocomp;
namespace fs = std::filesystem;

/// A 2.5 x 1.25 x 5 cm plane-strain box of 60-sphere RVEs and its Mohr-Coulomb twin, x at
/// 100 kPa, z shortened by 0.75 % in 3 samples; `more` adds continuum entries.
std::string box_case(const std::string &engines, const std::string &cells, const std::string &more,
                     const fs::path &out)
{
  return "set engines = " + engines + R"(
set seed = 11
subsection specimen
  set particles          = 60
  set radius             = 1e-3
  set size distribution  = uniform
  set radius spread      = 0.2
  set isotropic pressure = 1e5
end
subsection contact
  set normal stiffness  = 1e5
  set particle friction = 0.5
end
subsection dem rve
  set particles           = 60
  set steps per increment = 10
end
subsection continuum
  set box edges             = 0.025, 0.0125, 0.05
  set box cells             = )" + cells + R"(
  set youngs modulus        = 30e6
  set poisson ratio         = 0.25
  set cohesion              = 0:5e3
  set friction angle        = 0:20, 0.02:28, 0.1:24
  set dilatancy angle       = 0:0, 0.02:8, 0.1:0
  set load steps per sample = 1
)" + more + R"(
end
subsection program
  set sampling interval = 0.0025
  subsection stage 1
    set x            = stress -1e5
    set y            = rate 0
    set z            = rate -1
    set stop when    = eps_zz <= -0.0075
    set max duration = 0.2
  end
end
subsection output
  set directory = )" + out.string() + "\nend\n";
}

cli::RunSettings quiet_settings()
{
  cli::RunSettings s;
  s.reuse = false;
  s.signal_checkpoints = false;
  s.progress = [](const std::string &, const RunProgress &) {};
  return s;
}
} // namespace

// Mohr-Coulomb on a box of 2 x 1 x 2 cells (point spacings 4.2 and 8.3 mm), no imperfection:
// its mid-plane file holds the 36 points of the 4 cut cells at every sample, read back about
// the box centre with the per-axis tiles, and the homogeneous field's index stays at round-off.
TEST(BandReport, AHomogeneousBoxRecordsItsMidPlaneAboutTheBoxCentreWithAnIndexOfRoundOff)
{
  const test::ScratchFolder scratch("band-homogeneous");
  const fs::path dir = scratch.dir / "out";
  const CaseDescription c = parse_case(box_case("continuum", "2, 1, 2", "", dir), "box.prm");
  const Response r = cli::run_engine("continuum", c, dir, quiet_settings());
  const std::optional<compare::SectionSeries> s =
    cli::read_cube_section(dir, "continuum", "FE cube", cli::cube_parameters(c, dir.string()));
  ASSERT_TRUE(s);
  ASSERT_EQ(s->x.size(), 36u);
  EXPECT_EQ(s->times.size(), r.samples.size());
  EXPECT_DOUBLE_EQ(s->centre_x, 0.0125);
  EXPECT_DOUBLE_EQ(s->centre_z, 0.025);
  EXPECT_DOUBLE_EQ(s->marker, 0.025 / 12);
  EXPECT_DOUBLE_EQ(s->marker_z, 0.05 / 12);
  EXPECT_DOUBLE_EQ(s->strain_radius, 1.5 * 0.05 / 6);
  // The box is compressed about its rollers (x = 0, z = 0): the point at the centre moves by half
  // the top's displacement, and the fit of the field there says so.
  const std::size_t last = s->times.size() - 1;
  const double uz_top = r.samples.back().strain(2, 2) * 0.05;
  EXPECT_NEAR(compare::centre_displacement(s->x, s->z, s->uz[last], s->centre_x, s->centre_z), 0.5 * uz_top,
              1e-6 * std::abs(uz_top));
  const compare::StrainedSection strained =
    compare::strained_section(*s, r, compare::curve_kind_for(c.program), -1, compare::axial_axis_for(c.program));
  compare::LocalizationOptions o;
  o.strain.radius = s->strain_radius;
  const compare::SectionLocalization loc = compare::detect_section_localization(strained, o);
  double largest = 0.0;
  for (double h : loc.index)
    largest = std::max(largest, h);
  EXPECT_LT(largest, 1e-6) << "a homogeneous FE field's index is far below the threshold 1";
  EXPECT_FALSE(loc.onset.found);
  std::printf("[homogeneous box] largest heterogeneity index %.3g over %zu increments\n", largest, loc.index.size());
}

// The pair: material point, FE cube and FEM x DEM on a 2 x 1 x 4 box with its weak zone; each FE
// engine writes its own mid-plane file; every map row has the FE cube and the FEM x DEM panels in
// that order (no DEM ran; a box would have none anyway), and the verdict table has a strain-field
// row per FE engine, after the FE cube's acoustic-tensor row (the cells of FEM x DEM have no
// plastic tangent to scan: its response has no indicator, so no acoustic-tensor row), in the
// HTML and in metrics.json.
TEST(BandReport, ATinyFemDemAndContinuumPairOnABoxReportsBothFePanelsAndTheStrainFieldRows)
{
  const test::ScratchFolder scratch("band-pair");
  const fs::path dir = scratch.dir / "out";
  // The weak zone; the Newton tolerance loose (the cells' answer is not smooth below it,
  // docs/coupled.md: 2 iterations a step instead of 13).
  const std::string more = "  set imperfection radius = 0.01\n  set imperfection factor = 0.8\n"
                           "  set newton tolerance = 1e-4\n";
  const CaseDescription c =
    parse_case(box_case("material-point, continuum, fem-dem", "2, 1, 4", more, dir), "tiny-box.prm");
  const cli::PairOutcome out = cli::pair_case(c, dir, quiet_settings());
  EXPECT_TRUE(fs::exists(dir / "continuum-midplane.h5"));
  EXPECT_TRUE(fs::exists(dir / "fem-dem-midplane.h5"));
  const nlohmann::json m = nlohmann::json::parse(test::file_text(dir / "report" / "metrics.json"));
  const std::string html = test::file_text(dir / "report" / "index.html");

  ASSERT_FALSE(m["named_states"].empty());
  std::size_t drawn = 0;
  for (const auto &state : m["named_states"]) {
    if (!state["found"].get<bool>())
      continue;
    ASSERT_EQ(state["panels"].size(), 2u) << state.dump();
    EXPECT_EQ(state["panels"][0]["engine"], "FE cube");
    EXPECT_EQ(state["panels"][1]["engine"], "FEM x DEM");
    EXPECT_TRUE(state["panels"][1]["present"].get<bool>()) << state.dump();
    ++drawn;
  }
  EXPECT_GE(drawn, 1u);
  EXPECT_TRUE(fs::exists(dir / "report" / "data" / "state0_0_fem-x-dem.dat"));
  EXPECT_TRUE(fs::exists(dir / "report" / "data" / "state0_2_fe-cube.dat"));
  if (program_available("gnuplot")) {
    EXPECT_NE(html.find("src=\"state0_2_fem-x-dem.png\""), std::string::npos);
  }

  std::vector<std::string> sources;
  for (const auto &row : m["rudnicki_rice"]["rows"]) {
    sources.push_back(row["source"]);
    if (sources.back().find("(strain field)") != std::string::npos) {
      EXPECT_NE(row["note"].get<std::string>().find("mid-plane states"), std::string::npos) << row.dump();
    }
  }
  const std::vector<std::string> expected{"material point (acoustic tensor)", "FE cube (acoustic tensor)",
                                          "FE cube (strain field)", "FEM x DEM (strain field)"};
  EXPECT_EQ(sources, expected);
  for (const char *row : {"<td>FE cube (strain field)</td>", "<td>FEM x DEM (strain field)</td>"})
    EXPECT_NE(html.find(row), std::string::npos) << row;
  for (const auto &[engine, response] : out.runs) {
    std::printf("[tiny pair] %s: %zu samples\n", engine.c_str(), response.samples.size());
    EXPECT_EQ(response.extra_index("localization_q") < 0, engine == "fem-dem") << engine;
    if (engine != "material-point") {
      const int updates = response.extra_index("material_updates");
      ASSERT_GE(updates, 0) << engine;
      EXPECT_GT(response.samples.back().extras[updates], 0.0) << engine;
    }
  }
  for (const auto &row : m["rudnicki_rice"]["rows"])
    std::printf("[tiny pair] %s: %s\n", row["source"].get<std::string>().c_str(),
                row["note"].get<std::string>().c_str());
}

// Which sections a pair maps, before anything is read: beside a box mesh the DEM (a cube) has
// no panel, beside a cube it comes first; each FE engine that runs has its own.
TEST(BandReport, ADemBesideABoxMeshHasNoPanelAndBesideACubeItComesFirst)
{
  const test::ScratchFolder scratch("band-sections");
  const auto engines = [&](const std::string &names, const std::string &more) {
    std::vector<std::string> out;
    const CaseDescription c = parse_case(box_case(names, "2, 1, 4", more, scratch.dir), "sections.prm");
    for (const cli::PairSection &s : cli::recorded_sections(c, scratch.dir)) {
      EXPECT_FALSE(s.series) << s.engine << ": nothing was recorded";
      out.push_back(s.engine);
    }
    return out;
  };
  EXPECT_EQ(engines("dem, continuum, fem-dem", ""), (std::vector<std::string>{"continuum", "fem-dem"}));
  EXPECT_EQ(engines("dem, fem-dem", ""), (std::vector<std::string>{"fem-dem"}));
  // The same case on the cube (no box edges): DEM | FE cube | FEM x DEM.
  const auto cube = [&](const std::string &names) {
    std::string text = box_case(names, "2, 2, 2", "", scratch.dir);
    text.erase(text.find("  set box edges"), text.find("  set youngs") - text.find("  set box edges"));
    std::vector<std::string> out;
    for (const cli::PairSection &s : cli::recorded_sections(parse_case(text, "cube.prm"), scratch.dir))
      out.push_back(s.engine);
    return out;
  };
  EXPECT_EQ(cube("fem-dem, dem, continuum"), (std::vector<std::string>{"dem", "continuum", "fem-dem"}));
  EXPECT_EQ(cube("dem, material-point"), (std::vector<std::string>{"dem"}));
}
