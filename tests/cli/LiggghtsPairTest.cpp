// LIGGGHTS as an engine of `pair` (issue 34 items 2-4): a case naming `dem, liggghts` runs
// both DEM engines on the same specimen from one command, the report's cross-engine section
// gives rms differences that this test recomputes from the two results files on its own, and
// the engines agree within the bound the contact histories allow; a deck LIGGGHTS refuses
// fails with LIGGGHTS' ERROR line; a machine without LIGGGHTS refuses the case with exit 2
// before anything runs; unloading branches, which the deck does not play, are refused.
// A generated specimen of 250 spheres keeps each run to seconds.
#include "common/ResponseFile.h"
#include "common/Subprocess.h"
#include "compare/cli/LiggghtsEngine.h"
#include "tests/common/CommandRun.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path &scratch()
{
  static const fs::path dir = fs::temp_directory_path() / ("geocomp-liggghts-pair-" + std::to_string(::getpid()));
  return dir;
}

/// A case of 250 spheres consolidated to 100 kPa for `engines`, its output in scratch()/name;
/// S0's lateral-pressure program: lateral walls held at 100 kPa, axial rate -0.5/s to 2 %.
fs::path write_case(const std::string &name, const std::string &engines, const std::string &stage_extra = "")
{
  fs::create_directories(scratch());
  const fs::path file = scratch() / (name + ".prm");
  std::ofstream(file) << "set engines = " << engines << "\nset seed = 3\n"
                      << "subsection specimen\n  set particles = 250\n  set packing fraction = 0.62\n"
                         "  set radius = 0.005\n  set isotropic pressure = 1e5\nend\n"
                         "subsection contact\n  set normal stiffness = 2e5\n  set particle friction = 0.4\nend\n"
                         "subsection dem\n  set threads = 1\n  set snapshots = 0\nend\n"
                         "subsection program\n  set sampling interval = 0.002\n  subsection stage 1\n"
                         "    set x = stress -1e5\n    set y = stress -1e5\n    set z = rate -0.5\n"
                         "    set stop when = eps_zz <= -0.02\n    set max duration = 0.2\n"
                      << stage_extra << "  end\nend\nsubsection output\n  set directory = "
                      << (scratch() / name).string() << "\nend\n";
  return file;
}

/// The curves of CrossEngine.h recomputed from a results file, on its own: the main path;
/// x = -ln((1 + eps_zz)/(1 + eps_zz,0)), eta = q/p' with q the von Mises stress and
/// p' = -tr(sigma)/3, eps_v = sum_a ln((1 + eps_aa)/(1 + eps_aa,0)); instantaneous stresses.
struct Curves {
  std::vector<double> x, eta, eps_v;
};

Curves curves_of(const geocomp::Response &r)
{
  Curves c;
  const geocomp::ResponseSample *first = nullptr;
  for (const auto &s : r.samples) {
    if (s.branch != 0)
      continue;
    if (!first)
      first = &s;
    const auto &e = s.strain, &e0 = first->strain;
    const auto &t = s.stress;
    const double p = t.trace() / 3.0;
    const double j2 = ((t(0, 0) - t(1, 1)) * (t(0, 0) - t(1, 1)) + (t(1, 1) - t(2, 2)) * (t(1, 1) - t(2, 2)) +
                       (t(2, 2) - t(0, 0)) * (t(2, 2) - t(0, 0))) / 6.0 +
                      t(0, 1) * t(0, 1) + t(1, 2) * t(1, 2) + t(0, 2) * t(0, 2);
    c.x.push_back(-std::log((1.0 + e(2, 2)) / (1.0 + e0(2, 2))));
    c.eta.push_back(std::sqrt(3.0 * j2) / -p);
    double ev = 0.0;
    for (int a = 0; a < 3; ++a)
      ev += std::log((1.0 + e(a, a)) / (1.0 + e0(a, a)));
    c.eps_v.push_back(ev);
  }
  return c;
}

/// rms of g (sampled at gx) - f (at fx), on f's samples inside g's range, over f's scale.
double relative_rms(const std::vector<double> &fx, const std::vector<double> &f, const std::vector<double> &gx,
                    const std::vector<double> &g, double floor)
{
  double sum2 = 0.0, scale = floor;
  int n = 0;
  for (std::size_t i = 0; i < fx.size(); ++i) {
    scale = std::max(scale, std::abs(f[i]));
    for (std::size_t j = 0; j + 1 < gx.size(); ++j)
      if (fx[i] >= std::min(gx[j], gx[j + 1]) && fx[i] <= std::max(gx[j], gx[j + 1])) {
        const double w = gx[j + 1] == gx[j] ? 0.0 : (fx[i] - gx[j]) / (gx[j + 1] - gx[j]);
        const double v = (1.0 - w) * g[j] + w * g[j + 1];
        sum2 += (v - f[i]) * (v - f[i]);
        ++n;
        break;
      }
  }
  return std::sqrt(sum2 / n) / scale;
}

nlohmann::json read_json(const fs::path &file)
{
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::string read_text(const fs::path &file)
{
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class LiggghtsPair : public ::testing::Test {
protected:
  void SetUp() override
  {
    if (!geocomp::program_available("liggghts"))
      GTEST_SKIP() << "LIGGGHTS is not installed (Debian package 'liggghts')";
  }
};

struct ScratchCleanup : ::testing::Environment {
  void TearDown() override { fs::remove_all(scratch()); }
};
::testing::Environment *const kCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

} // namespace

TEST_F(LiggghtsPair, BothDemEnginesRunFromOneCommandAndTheCrossEngineSectionIsTheRmsOfTheirResults)
{
  const fs::path c = write_case("pair", "dem, liggghts");
  const auto run = geocomp::test::run_program({GEOCOMP_EXE, "pair", c.string()}, {}, 300.0);
  ASSERT_EQ(run.code, 0) << run.err;
  const fs::path out = scratch() / "pair";
  geocomp::RunMeta meta;
  const geocomp::Response dem = geocomp::read_response(out / "dem.h5");
  const geocomp::Response lg = geocomp::read_response(out / "liggghts.h5", &meta);
  EXPECT_EQ(lg.engine, "liggghts");
  EXPECT_EQ(meta.status, "complete");
  EXPECT_EQ(meta.case_text, read_text(c));
  ASSERT_EQ(lg.stage_end_reasons.size(), 1u);
  EXPECT_EQ(lg.stage_end_reasons[0], "eps_zz <= -0.02");
  EXPECT_TRUE(fs::exists(out / "liggghts" / "liggghts.out"));

  const nlohmann::json cross = read_json(out / "report" / "metrics.json").at("cross_engine");
  EXPECT_EQ(cross.at("reference"), "DEM");
  EXPECT_EQ(cross.at("other"), "LIGGGHTS");
  const Curves d = curves_of(dem), l = curves_of(lg);
  const double eta = relative_rms(d.x, d.eta, l.x, l.eta, 0.0);
  const double ev = relative_rms(d.x, d.eps_v, l.x, l.eps_v, 1e-3);
  const nlohmann::json &rows = cross.at("rows");
  ASSERT_EQ(rows.at(0).at("key"), "stress_ratio");
  ASSERT_EQ(rows.at(1).at("key"), "volumetric_strain");
  // metrics.json prints six significant digits.
  EXPECT_NEAR(rows.at(0).at("engines_pct").get<double>(), 100.0 * eta, 1e-5 * 100.0 * eta);
  EXPECT_NEAR(rows.at(1).at("engines_pct").get<double>(), 100.0 * ev, 1e-5 * 100.0 * ev);
  std::cout << "LIGGGHTS - DEM: stress ratio " << 100.0 * eta << " %, volumetric strain " << 100.0 * ev
            << " % rms over " << cross.at("common_samples") << " common samples\n";
  // The bound: a data file carries no contact history, so LIGGGHTS starts every tangential
  // spring of the consolidated packing at zero where geocomp keeps them; on this specimen that
  // makes LIGGGHTS' deviator 3.2 % rms stiffer over 2 % axial strain (docs/liggghts.md). The
  // stress ratio differs as the deviator does (p' is held by the servo on two axes); 5 % is
  // the bound docs/liggghts.md states for this specimen. The volumetric strain has the same origin.
  EXPECT_LT(eta, 0.05);
  EXPECT_LT(ev, 0.05);
  const std::string html = read_text(out / "report" / "index.html");
  EXPECT_NE(html.find("id=\"cross-engine\""), std::string::npos);
  EXPECT_NE(html.find(cross.at("verdict").get<std::string>()), std::string::npos);
  EXPECT_NE(html.find("LIGGGHTS"), std::string::npos);
}

TEST_F(LiggghtsPair, ADeckLiggghtsRefusesFailsWithLiggghtsErrorLine)
{
  const fs::path c = write_case("refused", "dem");
  const fs::path deck = scratch() / "refused-deck";
  const auto exported = geocomp::test::run_program({GEOCOMP_EXE, "export", "liggghts", c.string(), "--output", deck.string()}, {}, 300.0);
  ASSERT_EQ(exported.code, 0) << exported.err;
  const std::string text = read_text(deck / "in.geocomp");
  std::ofstream(deck / "in.geocomp") << "geocomp_no_such_command 1\n" << text; // corrupted
  try {
    geocomp::cli::run_liggghts_deck(deck, {});
    FAIL() << "LIGGGHTS accepted a corrupted deck";
  } catch (const geocomp::cli::LiggghtsRefused &e) {
    const std::string error = geocomp::cli::liggghts_error_line(deck / geocomp::cli::kLiggghtsScreenFile);
    ASSERT_NE(error.find("geocomp_no_such_command"), std::string::npos) << error;
    EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
  }
}

TEST(LiggghtsPairWithoutLiggghts, APairNamingLiggghtsIsRefusedWithExitTwoNamingThePackageBeforeAnythingRuns)
{
  const fs::path c = write_case("missing", "dem, liggghts");
  // No PATH at all: no liggghts; Open MPI's singleton start then needs no helper program.
  const auto run = geocomp::test::run_program({"/usr/bin/env", "PATH=/nonexistent", "OMPI_MCA_plm=isolated", GEOCOMP_EXE, "pair", c.string()}, {}, 120.0);
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find("Debian package 'liggghts'"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(scratch() / "missing" / "dem.h5"));
}

TEST(LiggghtsPairWithoutLiggghts, UnloadingBranchesAreRefusedWithExitTwoNamingTheEntry)
{
  const fs::path c = write_case("unload", "dem, liggghts", "    set unload at = eps_zz <= -0.01\n");
  const auto run = geocomp::test::run_program({GEOCOMP_EXE, "check", c.string()}, {}, 60.0);
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE((run.err + run.out).find("program/stage 1/unload at"), std::string::npos) << run.err << run.out;
}
