// `geocomp dem` on runs that go wrong (issue 30): a program that squeezes the box shut, or
// whose stress runs away, stops with exit 1, says why on stderr, and leaves a readable
// results file with the samples so far and /meta/status saying where and why; a stage
// that ends on its max duration before its stop condition writes everything, warns, says
// so in /meta/status and exits 1. The report of a DEM run reads the interval-mean stresses
// and says so. A small generated specimen (250 spheres) keeps each run to a few seconds.
#include "common/ResponseFile.h"
#include "tests/common/CommandRun.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {
struct Scratch
{
  fs::path dir = fs::temp_directory_path() / ("geocomp-guards-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

/// A DEM case of 250 spheres consolidated to 100 kPa, with the given stage and dem entries.
fs::path write_case(const fs::path &dir, const std::string &name, const std::string &stage,
                    const std::string &dem_entries = "")
{
  const fs::path file = dir / (name + ".prm");
  std::ofstream(file) << "set engines = dem\nset seed = 3\n"
                         "subsection specimen\n  set particles = 250\n  set packing fraction = 0.62\n"
                         "  set radius = 0.005\n  set isotropic pressure = 1e5\nend\n"
                         "subsection contact\n  set normal stiffness = 2e5\n  set particle friction = 0.4\nend\n"
                         "subsection dem\n  set threads = 1\n  set snapshots = 0\n" +
                           dem_entries +
                           "end\n"
                           "subsection program\n  set sampling interval = 0.002\n  subsection stage 1\n" +
                           stage +
                           "  end\nend\n"
                           "subsection output\n  set directory = " +
                           (dir / name).string() + "\nend\n";
  return file;
}

geocomp::test::CommandResult run_dem(const fs::path &c)
{
  return geocomp::test::run_program({GEOCOMP_EXE, "dem", c.string()}, {}, 300.0);
}
} // namespace

TEST(RunGuards, ABoxSqueezedShutStopsTheRunWithExitOneStatusAndTheSamplesSoFar)
{
  // Isochoric at 20/s: L_x would reach zero at t = 0.05 s; the stop condition is legal
  // (gamma_max grows without bound) but the box-edge guard comes first.
  Scratch s;
  const fs::path c = write_case(s.dir, "squeeze",
                                "    set mode = isochoric\n    set isochoric rate = 20\n"
                                "    set stop when = gamma_max >= 50\n    set max duration = 1\n");
  const auto r = run_dem(c);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("guard: the box edge along x"), std::string::npos) << r.err;
  geocomp::RunMeta meta;
  const geocomp::Response q = geocomp::read_response(s.dir / "squeeze/dem.h5", &meta);
  EXPECT_EQ(meta.status.rfind("failed in stage 1", 0), 0u) << meta.status;
  EXPECT_NE(meta.status.find("below 3 particle diameters"), std::string::npos) << meta.status;
  EXPECT_GT(q.samples.size(), 5u);
  EXPECT_LT(q.samples.back().time, 0.05);
}

TEST(RunGuards, ARunawayStressStopsTheRunWithExitOneStatusAndTheSamplesSoFar)
{
  // All three axes shortened at 1/s: the stress passes 10 times the 100 kPa reference
  // (the guard's ratio lowered from its 1000 for a short run) long before the box closes.
  Scratch s;
  const fs::path c = write_case(s.dir, "crush",
                                "    set x = rate -1\n    set y = rate -1\n    set z = rate -1\n"
                                "    set stop when = eps_vol <= -0.9\n    set max duration = 1\n",
                                "  set guard stress ratio = 10\n");
  const auto r = run_dem(c);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("times the reference stress"), std::string::npos) << r.err;
  geocomp::RunMeta meta;
  const geocomp::Response q = geocomp::read_response(s.dir / "crush/dem.h5", &meta);
  EXPECT_NE(meta.status.find("guard: the wall stress reached"), std::string::npos) << meta.status;
  ASSERT_FALSE(q.samples.empty());
  EXPECT_LT(q.samples.back().stress(0, 0), -1e5);
}

TEST(RunGuards, AStageEndedByItsMaxDurationWarnsWritesItsStatusAndExitsOne)
{
  Scratch s;
  const fs::path c = write_case(s.dir, "cut",
                                "    set x = stress -1e5\n    set y = stress -1e5\n    set z = rate -0.5\n"
                                "    set stop when = tau_max >= 1e9\n    set max duration = 0.01\n");
  const auto r = run_dem(c);
  EXPECT_EQ(r.code, 1) << r.err;
  const std::string why = "stage 1 ended on its max duration (0.01 s) before its stop condition 'tau_max >= 1e9'";
  EXPECT_NE(r.err.find("warning: dem: " + why), std::string::npos) << r.err;
  geocomp::RunMeta meta;
  const geocomp::Response q = geocomp::read_response(s.dir / "cut/dem.h5", &meta);
  EXPECT_EQ(meta.status, why);
  EXPECT_EQ(q.samples.size(), 6u); // t = 0, 0.002, ..., 0.01: all of it
  // The same command again does not take these results for up to date: it runs again.
  const auto again = run_dem(c);
  EXPECT_EQ(again.code, 1);
  EXPECT_NE(again.err.find("warning: dem: " + why), std::string::npos) << again.err;
}

TEST(RunGuards, TheReportOfADemRunReadsTheIntervalMeansAndSaysSo)
{
  Scratch s;
  const fs::path c = write_case(s.dir, "means",
                                "    set x = stress -1e5\n    set y = stress -1e5\n    set z = rate -0.5\n"
                                "    set stop when = eps_zz <= -0.01\n    set max duration = 1\n");
  ASSERT_EQ(run_dem(c).code, 0);
  const auto r = geocomp::test::run_program({GEOCOMP_EXE, "report", c.string()}, {}, 120.0);
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(s.dir / "means/report/index.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("DEM: stresses in the curves, tables and metrics are means over each sampling interval"),
            std::string::npos);
  const geocomp::Response q = geocomp::read_response(s.dir / "means/dem.h5");
  EXPECT_TRUE(q.interval_means);
  EXPECT_NE(q.samples.back().stress_mean, q.samples.back().stress);
  const geocomp::Response m = geocomp::with_interval_means(q);
  EXPECT_EQ(m.samples.back().stress, q.samples.back().stress_mean);
}
