// Programs started from an argument vector: a folder or an argument holding quotes,
// spaces, `$(...)`, back quotes or ';' arrives as it is and runs nothing else.
#include "common/Subprocess.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using geocomp::run_subprocess;

namespace {
/// A folder whose name a shell would take for several commands.
const std::string hostile = "it's a \"dir\" $(touch pwned1) ; touch pwned2 `touch pwned3` & touch pwned4";

std::string read(const fs::path &p)
{
  std::stringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

std::size_t files_named_pwned(const fs::path &root)
{
  std::size_t n = 0;
  for (const auto &e : fs::recursive_directory_iterator(root))
    n += e.path().filename().string().rfind("pwned", 0) == 0;
  return n;
}
} // namespace

TEST(Subprocess, AFolderAndArgumentsWithShellSyntaxReachTheProgramAsTheyAre)
{
  const fs::path root = fs::temp_directory_path() / ("geocomp-spawn-" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path dir = root / hostile;
  fs::create_directories(dir);
  const fs::path out = dir / "out.txt";
  const auto r = run_subprocess({"printf", "%s|%s", hostile, "; touch pwned5"}, {dir, out, out});
  ASSERT_TRUE(r.started) << r.error;
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(read(out), hostile + "|; touch pwned5");
  // The working directory is the hostile folder: `pwd` prints it.
  const auto p = run_subprocess({"pwd"}, {dir, root / "pwd.txt", {}});
  EXPECT_EQ(read(root / "pwd.txt"), fs::canonical(dir).string() + "\n");
  EXPECT_EQ(files_named_pwned(root), 0u);
  EXPECT_EQ(files_named_pwned(fs::current_path()), 0u);
  fs::remove_all(root);
}

TEST(Subprocess, AMissingProgramIsReportedAsNotStartedAndAFailureByItsExitCode)
{
  const auto missing = run_subprocess({"geocomp-no-such-program"});
  EXPECT_FALSE(missing.started);
  EXPECT_FALSE(missing.error.empty());
  EXPECT_FALSE(geocomp::program_available("geocomp-no-such-program"));
  EXPECT_TRUE(geocomp::program_available("sh"));
  const auto failed = run_subprocess({"false"});
  EXPECT_TRUE(failed.started);
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_FALSE(failed.succeeded());
}

TEST(Subprocess, AProgramThatRunsPastItsTimeoutIsKilled)
{
  geocomp::SubprocessOptions o;
  o.timeout_seconds = 0.2;
  const auto r = run_subprocess({"sleep", "30"}, o);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.signal, 9);
}
