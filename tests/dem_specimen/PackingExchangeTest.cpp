#include "dem/specimen/Packing.h"
#include "dem/specimen/SizeDistribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace geocomp::dem;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string &name)
{
  const fs::path dir = fs::temp_directory_path() / ("geocomp-packing-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}
fs::path shared_bench(const std::string &file)
{
  const char *src = std::getenv("GEOCOMP_SOURCE_DIR");
  return fs::path(src ? src : ".") / ".." / "shared" / "bench" / "data" / file;
}
Packing random_packing(std::size_t n)
{
  SizeDistribution d;
  d.kind = SizeDistribution::Kind::Uniform;
  d.spread = 0.3;
  Packing p;
  p.radius = d.sample(n, 99);
  p.box_max = {0.4, 0.5, 0.6};
  for (std::size_t i = 0; i < n; ++i)
    p.position.emplace_back(0.001 * i + 1.0 / 3.0, std::sqrt(2.0) * 0.1, M_PI / 30.0 + 1e-9 * i);
  return p;
}
} // namespace

// Text import -> export -> import is exact to the printed precision (17 digits: exact).
TEST(PackingExchange, TextRoundTripIsExactAtPrintedPrecision)
{
  const Packing p = random_packing(257);
  const fs::path a = scratch("a.xyzr"), b = scratch("b.xyzr");
  write_xyzr(a, p);
  const Packing q = read_xyzr(a);
  write_xyzr(b, q);
  const Packing r = read_xyzr(b);
  ASSERT_EQ(r.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(r.position[i], p.position[i]);
    EXPECT_EQ(r.radius[i], p.radius[i]);
  }
  EXPECT_EQ(r.box_min, p.box_min);
  EXPECT_EQ(r.box_max, p.box_max);
  // At 8 digits the second export reproduces the first byte for byte.
  write_xyzr(a, p, 8);
  write_xyzr(b, read_xyzr(a), 8);
  std::ifstream fa(a), fb(b);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(fa), {}), std::string(std::istreambuf_iterator<char>(fb), {}));
  fs::remove_all(a.parent_path());
}

TEST(PackingExchange, LammpsDataRoundTripIsExact)
{
  Packing p = random_packing(100);
  p.density = 2550;
  const fs::path a = scratch("a.data");
  write_lammps_data(a, p);
  const Packing q = read_lammps_data(a);
  ASSERT_EQ(q.size(), p.size());
  EXPECT_EQ(q.density, 2550);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(q.position[i], p.position[i]);
    EXPECT_DOUBLE_EQ(q.radius[i], p.radius[i]); // through the diameter: one rounding
  }
  fs::remove_all(a.parent_path());
}

// The shared benchmark specimen reads the same from its two formats.
TEST(PackingExchange, SharedBenchmarkSpecimenAgreesAcrossFormats)
{
  const fs::path xyzr = shared_bench("bench_10000.xyzr"), data = shared_bench("bench_10000.data");
  if (!fs::exists(xyzr) || !fs::exists(data))
    GTEST_SKIP() << "shared benchmark data not found next to the repository";
  const Packing a = read_xyzr(xyzr), b = read_lammps_data(data);
  ASSERT_EQ(a.size(), 10000u);
  ASSERT_EQ(b.size(), 10000u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((a.position[i] - b.position[i]).norm(), 0.0, 1e-9);
    EXPECT_NEAR(a.radius[i], b.radius[i], 1e-12);
  }
  EXPECT_NEAR(a.packing_fraction(), 0.625, 0.005); // the README's figure
  EXPECT_EQ(b.density, 2650);
}

TEST(PackingExchange, MalformedFilesNameFileAndLine)
{
  const fs::path a = scratch("bad.xyzr");
  std::ofstream(a) << "# x y z r box [0,1]^3\n0.1 0.2 0.3 0.01\n0.1 0.2 oops 0.01\n";
  try {
    read_xyzr(a);
    FAIL();
  } catch (const PackingFileError &e) {
    EXPECT_NE(std::string(e.what()).find(a.string() + ":3"), std::string::npos) << e.what();
  }
  std::ofstream(a) << "0.1 0.2 0.3 0.01\n";
  EXPECT_THROW(read_xyzr(a), PackingFileError); // no box
  std::ofstream(a) << "# box [0,1]^3\n0.1 0.2 0.3 -0.01\n";
  EXPECT_THROW(read_xyzr(a), PackingFileError); // negative radius
  EXPECT_THROW(read_xyzr(scratch("missing.xyzr")), PackingFileError);
  fs::remove_all(a.parent_path());
}

TEST(SizeDistribution, SameSeedSameRadiiAndStatedStatistics)
{
  SizeDistribution d;
  d.kind = SizeDistribution::Kind::LognormalMass;
  d.mean_radius = 0.01;
  d.sigma = 0.432;
  const auto a = d.sample(20000, 5), b = d.sample(20000, 5), c = d.sample(20000, 6);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // ln m = 3 ln r + const has standard deviation sigma.
  double mean = 0, var = 0;
  for (double r : a)
    mean += 3 * std::log(r);
  mean /= a.size();
  for (double r : a)
    var += std::pow(3 * std::log(r) - mean, 2);
  var /= a.size() - 1;
  EXPECT_NEAR(std::sqrt(var), 0.432, 0.01);
  d.kind = SizeDistribution::Kind::Uniform;
  d.spread = 0.2;
  for (double r : d.sample(1000, 1)) {
    EXPECT_GE(r, 0.008);
    EXPECT_LE(r, 0.012);
  }
}
