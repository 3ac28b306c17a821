// geocomp-bench-packing (bench/bench_packing.cpp) makes the benchmark's larger specimens the
// way the shared ones were made. Its file must be a jammed packing at the asked packing
// fraction, the same for the same seed and any thread count; bad arguments are refused with
// exit code 2, naming the argument, and write nothing.
#include "dem/specimen/Packing.h"
#include "tests/common/CommandRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace geocomp::dem;

namespace {

/// Runs geocomp-bench-packing with `args`; captures stderr.
geocomp::test::CommandResult run_packing(const std::string& args)
{
  return geocomp::test::run_command(std::string("'") + GEOCOMP_BENCH_PACKING + "' " + args);
}

fs::path scratch(const std::string& name)
{
  return fs::temp_directory_path() / ("bench-packing-" + std::to_string(::getpid()) + "-" + name);
}

std::string bytes(const fs::path& f)
{
  std::ifstream in(f, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(BenchPacking, SameSeedGivesTheSameJammedPackingAtTheAskedFraction)
{
  const int n = 500;
  const double eta = 0.636;  // the shared 50 000 packing's
  const fs::path a = scratch("a.xyzr"), b = scratch("b.xyzr"), c = scratch("c.xyzr");
  const std::string head = std::to_string(n) + " 0.636 ";
  ASSERT_EQ(run_packing(head + "5 '" + a.string() + "'").code, 0);
  ASSERT_EQ(run_packing(head + "5 '" + b.string() + "' 2").code, 0);
  ASSERT_EQ(run_packing(head + "6 '" + c.string() + "'").code, 0);
  EXPECT_EQ(bytes(a), bytes(b)) << "the same seed (1 and 2 threads) must give the same file";
  EXPECT_NE(bytes(a), bytes(c)) << "another seed, another packing";

  const Packing p = read_xyzr(a);
  ASSERT_EQ(p.size(), std::size_t(n));
  const double R = 0.0118;  // the shared benchmark's spheres
  const double L = p.box_max[0] - p.box_min[0];
  EXPECT_NEAR(double(n) * 4.0 / 3.0 * M_PI * R * R * R / (L * L * L), eta, 1e-6);
  std::size_t touching = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.radius[i], R);
    for (int d = 0; d < 3; ++d) {  // inside the box, pressed into its walls by less than R / 5
      EXPECT_GT(p.position[i][d] - p.box_min[d], 0.8 * R);
      EXPECT_GT(p.box_max[d] - p.position[i][d], 0.8 * R);
    }
    for (std::size_t j = i + 1; j < p.size(); ++j) touching += (p.position[j] - p.position[i]).norm() < 2.0 * R ? 1 : 0;
  }
  // Grown without friction to eta = 0.636 and relaxed: a jammed packing, whose mean
  // coordination is near the isostatic 6 of frictionless spheres (the shared packings: 6.3-6.4;
  // an unjammed or exploded one has far fewer contacts, an overlapping heap far more).
  const double z = 2.0 * double(touching) / double(n);
  EXPECT_GT(z, 5.5);
  EXPECT_LT(z, 7.5);
  for (const fs::path& f : {a, b, c}) fs::remove(f);
}

TEST(BenchPacking, BadArgumentsExitTwoNamingTheArgumentAndWriteNothing)
{
  const fs::path out = scratch("bad.xyzr");
  const struct
  {
    std::string args, names;
  } cases[] = {{"3 0.636 5 '" + out.string() + "'", "N:"},
               {"500 0.9 5 '" + out.string() + "'", "ETA:"},
               {"500 0.636 five '" + out.string() + "'", "SEED:"},
               {"500 0.636 5 '" + out.string() + "' 0", "THREADS:"},
               {"500 0.636", "expected 4 or 5 arguments"}};
  for (const auto& c : cases) {
    const geocomp::test::CommandResult r = run_packing(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}
