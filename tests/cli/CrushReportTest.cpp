// `geocomp crush` writes its report (compare/CrushReport.h) from every run in its output
// folder: three tiny runs (a single-particle test over three seeds, uniaxial compressions
// with the cube and the 4-ball mode) give one index.html with the stress-strain,
// force-approach, gradation (S2 Fig. 7) and fragment-size (S2 Fig. 3) plots and the roses.
// What the plots read must be what S2's figures show: a gradation rises monotonically to
// 100 %, the 4-ball's in steps (at most its five sizes 40 / 4^(g/3) = 40, 25.2, 15.9, 10,
// 6.3 mm: a 10 mm child still reaches d_L = 10 mm), the cube's continuously; each seed's
// fragment percentages sum to 100.
#include "common/Subprocess.h"
#include "tests/common/CommandRun.h"
#include "tests/common/ScratchFolder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using geocomp::test::run_program;
using Scratch = geocomp::test::ScratchFolder;

namespace {

fs::path uniaxial_case(const fs::path& dir, const std::string& mode)
{
  const fs::path p = dir / ("uniaxial_" + mode + ".prm");
  std::ofstream(p) << "set title = tiny uniaxial " << mode << "\n"
                   << "subsection program\n  set mode = uniaxial\n  set record interval = 50\nend\n"
                   << "subsection material\n  set density scaling = 100\nend\n"
                   << "subsection breakage\n  set mode = " << mode
                   << "\n  set minimum size = 2.5\n  set breakage limit = 10\n  set characteristic strength = 10\nend\n"
                   << "subsection uniaxial\n  set particles per edge = 2\n  set seating stress = 50\n"
                   << "  set seating speed = 0.05\n  set lid speed = 0.1\n  set final strain = 0.05\nend\n";
  return p;
}

fs::path single_case(const fs::path& dir)
{
  const fs::path p = dir / "single.prm";
  std::ofstream(p) << "set title = tiny single particle, three seeds\n"
                   << "subsection material\n  set density scaling = 100\nend\n"
                   << "subsection single particle\n  set particles = 4\n  set seeds = 3\nend\n"
                   << "subsection output\n  set gradation bin = 1\nend\n";
  return p;
}

/// The two columns of a report data file (comment lines skipped).
std::vector<std::pair<double, double>> columns(const fs::path& file)
{
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::vector<std::pair<double, double>> v;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream r(line);
    double x = 0.0, y = 0.0;
    r >> x >> y;
    v.emplace_back(x, y);
  }
  return v;
}

/// Checks a gradation curve (monotone, from >= 0 to 100 %) and returns the number of sieve
/// intervals over which it rises.
int rises_of_a_gradation(const fs::path& file)
{
  const auto g = columns(file);
  EXPECT_GE(g.size(), 2u) << file;
  if (g.empty()) return 0;
  EXPECT_GE(g.front().second, 0.0) << file;
  EXPECT_NEAR(g.back().second, 100.0, 1e-9) << file << ": the largest sieve passes everything";
  int rises = 0;
  for (std::size_t k = 1; k < g.size(); ++k) {
    EXPECT_GT(g[k].first, g[k - 1].first) << file;
    EXPECT_GE(g[k].second, g[k - 1].second) << file << " falls at " << g[k].first << " mm";
    rises += g[k].second > g[k - 1].second + 1e-9;
  }
  return rises;
}

}  // namespace

TEST(CrushReport, OverlaysTheModesGradationsAndTheSeedsFragmentSizesOfTheRunsInOneFolder)
{
  const Scratch s("crush-report");
  const fs::path out = s.dir / "results";
  // Sorted by name in the report: single (data/*0), uniaxial_4-ball (1), uniaxial_cube (2).
  for (const fs::path& c : {single_case(s.dir), uniaxial_case(s.dir, "cube"), uniaxial_case(s.dir, "4-ball")}) {
    const auto r = run_program({GEOCOMP_EXE, "crush", c.string(), "--output", out.string()}, s.dir);
    ASSERT_EQ(r.code, 0) << c << ": " << r.err;
  }
  const fs::path report = out / "report";
  std::ifstream html_in(report / "index.html");
  ASSERT_TRUE(html_in);
  const std::string html((std::istreambuf_iterator<char>(html_in)), std::istreambuf_iterator<char>());
  for (const std::string name : {"single", "uniaxial_cube", "uniaxial_4-ball"})
    EXPECT_NE(html.find(name), std::string::npos) << name;
  for (const std::string mode : {"cube", "4-ball"})
    for (const std::string state : {"seated", "peak", "final"}) {
      const std::string svg = "uniaxial_" + mode + "_polar_" + state + ".svg";
      EXPECT_NE(html.find("<img src=\"" + svg + "\""), std::string::npos) << svg << " embedded";
      EXPECT_TRUE(fs::exists(report / svg)) << svg << " copied beside index.html";
    }
  if (geocomp::program_available("gnuplot"))
    for (const std::string png : {"stress_strain.png", "force_approach.png", "gradation.png", "fig3.png"}) {
      EXPECT_TRUE(fs::exists(report / png) && fs::file_size(report / png) > 1000) << png;
      EXPECT_NE(html.find("<img src=\"" + png + "\""), std::string::npos) << png;
    }

  // Fig. 7: every gradation monotone to 100 %; the 4-ball's stepped, the cube's continuous.
  const int single_rises = rises_of_a_gradation(report / "data/gradation0.dat");
  const int ball_rises = rises_of_a_gradation(report / "data/gradation1.dat");
  const int cube_rises = rises_of_a_gradation(report / "data/gradation2.dat");
  std::printf("sieve intervals with a rise: 4-ball %d (at most 5 sizes), cube %d, single-particle fragments %d\n",
              ball_rises, cube_rises, single_rises);
  EXPECT_GE(ball_rises, 1) << "the 4-ball run broke something";
  EXPECT_LE(ball_rises, 5) << "4-ball sizes are 40 / 4^(g/3) mm: 40, 25.2, 15.9, 10, 6.3";
  EXPECT_GT(cube_rises, 5) << "the cube mode's random cut points give a continuous gradation";

  // Fig. 3: one distribution per seed, each summing to 100 % of that seed's fragments.
  for (int seed = 0; seed < 3; ++seed) {
    double sum = 0.0;
    for (const auto& [d, percent] : columns(report / ("data/fig3_0_" + std::to_string(seed) + ".dat"))) sum += percent;
    EXPECT_NEAR(sum, 100.0, 1e-6) << "seed " << seed << " (data written to 10 digits)";
  }
  EXPECT_FALSE(fs::exists(report / "data/fig3_0_3.dat")) << "three seeds, three curves";

  // --report rewrites the report alone; a path that is not a folder is bad input.
  fs::remove_all(report);
  const auto again = run_program({GEOCOMP_EXE, "crush", "--report", out.string()}, s.dir);
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_TRUE(fs::exists(report / "index.html"));
  EXPECT_EQ(run_program({GEOCOMP_EXE, "crush", "--report", (out / "single_summary.tsv").string()}, s.dir).code, 2);
}
