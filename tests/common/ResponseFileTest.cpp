#include "common/ProgramRunner.h"
#include "common/ResponseFile.h"
#include "HystereticShearEngine.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace geocomp;
namespace fs = std::filesystem;

namespace {
Response sample_response()
{
  LoadingProgram p = geocomp::testing::shear_program({"peak"}, 0.1);
  p.sample_interval = 0.02;
  geocomp::testing::HystereticShearEngine engine;
  return ProgramRunner(p, engine).run();
}
fs::path scratch(const std::string &name)
{
  const fs::path dir = fs::temp_directory_path() / "geocomp-tests";
  fs::create_directories(dir);
  return dir / (name + "-" + std::to_string(::getpid()) + ".h5");
}
} // namespace

TEST(ResponseFile, RoundTripIsExact)
{
  const Response r = sample_response();
  const fs::path path = scratch("roundtrip");
  RunMeta meta;
  meta.case_text = "set x = 1\n";
  meta.seed = 42;
  write_response(path, r, meta);
  RunMeta back;
  const Response q = read_response(path, &back);
  fs::remove(path);
  EXPECT_EQ(back.case_text, meta.case_text);
  EXPECT_EQ(back.seed, 42u);
  EXPECT_FALSE(back.version.empty());
  EXPECT_EQ(q.engine, r.engine);
  ASSERT_EQ(q.samples.size(), r.samples.size());
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    EXPECT_EQ(q.samples[i].time, r.samples[i].time);
    EXPECT_EQ(q.samples[i].strain, r.samples[i].strain);
    EXPECT_EQ(q.samples[i].stress, r.samples[i].stress);
    EXPECT_EQ(q.samples[i].branch, r.samples[i].branch);
    EXPECT_EQ(q.samples[i].extras, r.samples[i].extras);
  }
  ASSERT_EQ(q.branches.size(), r.branches.size());
  EXPECT_EQ(q.branches[0].residual_gamma, r.branches[0].residual_gamma);
  EXPECT_EQ(q.branches[0].trigger, "peak");
  EXPECT_EQ(q.stage_end_reasons, r.stage_end_reasons);
  ASSERT_EQ(q.extras.size(), 1u);
  EXPECT_EQ(q.extras[0].name, "g_hist");
}

// A writer that fails half way leaves neither the final file nor the temporary one.
TEST(ResponseFile, FailedWriteLeavesNoFile)
{
  const fs::path path = scratch("failed");
  Response r = sample_response();
  r.extras.push_back({"bad/name", "1", "a slash is not a valid dataset name"});
  EXPECT_ANY_THROW(write_response(path, r, RunMeta{}));
  EXPECT_FALSE(fs::exists(path));
  for (const auto &entry : fs::directory_iterator(path.parent_path()))
    EXPECT_EQ(entry.path().string().find(path.filename().string() + ".tmp"), std::string::npos);
}
