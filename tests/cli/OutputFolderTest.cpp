// The output folder of a run: locked while the run writes (a second run is refused naming
// the holder, a stale lock is taken over with a warning), an output path that cannot be a
// folder is bad input, and a folder name holding quotes, spaces, `$()`, back quotes or ';'
// is only a name - results, report and plots land in it and no command runs.
#include "tests/cli/PointCase.h"
#include "tests/common/CommandRun.h"
#include "tests/common/ScratchFolder.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using geocomp::test::run_program;
using geocomp::test::write_point_case;
using Scratch = geocomp::test::ScratchFolder;

namespace {

std::size_t files_named_pwned(const fs::path &root)
{
  std::size_t n = 0;
  for (const auto &e : fs::recursive_directory_iterator(root))
    n += e.path().filename().string().rfind("pwned", 0) == 0; // a file the shell would have made
  return n;
}

/// Holds the lock of `dir` the way a running geocomp does: flock on .geocomp.lock, whose
/// text names the holder.
struct HeldLock {
  int fd = -1;
  HeldLock(const fs::path &dir, const std::string &holder)
  {
    fd = ::open((dir / ".geocomp.lock").c_str(), O_RDWR | O_CREAT, 0644);
    EXPECT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    EXPECT_EQ(::write(fd, holder.data(), holder.size()), ssize_t(holder.size()));
  }
  ~HeldLock() { ::close(fd); }
};
} // namespace

TEST(OutputFolder, ASecondRunIntoALockedFolderExitsTwoNamingTheHolderAndWritesNothing)
{
  const Scratch s("output-locked");
  const fs::path out = s.dir / "results";
  fs::create_directories(out);
  const std::string holder = "process " + std::to_string(::getpid()) + " on test-host: geocomp pair other.prm\n";
  const HeldLock lock(out, holder);
  const fs::path c = write_point_case(s.dir, out.string());
  for (const char *command : {"material-point", "pair", "report"}) {
    const auto r = run_program({GEOCOMP_EXE, command, c.string()}, s.dir);
    EXPECT_EQ(r.code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("in use by another run (process " + std::to_string(::getpid()) + " on test-host"),
              std::string::npos)
      << command << ": " << r.err;
    EXPECT_NE(r.err.find("parameter 'output/directory'"), std::string::npos) << r.err;
  }
  const auto r = run_program({GEOCOMP_EXE, "material-point", c.string(), "--output", out.string()}, s.dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("parameter '--output'"), std::string::npos) << r.err;
  std::size_t files = 0;
  for ([[maybe_unused]] const auto &e : fs::directory_iterator(out))
    ++files;
  EXPECT_EQ(files, 1u) << "only the held lock file";
}

TEST(OutputFolder, APackIntoAStoreWhoseFolderIsLockedExitsTwoNamingTheHolderAndPreparesNothing)
{
  // Two packs into one store would each rename their copy over the other's.
  const Scratch s("output-pack-locked");
  const fs::path out = s.dir / "store";
  fs::create_directories(out);
  const std::string holder = "process " + std::to_string(::getpid()) + " on test-host: geocomp pack other.prm\n";
  const HeldLock lock(out, holder);
  const fs::path c = s.dir / "pack.prm";
  std::ofstream(c) << "set engines = dem\nsubsection specimen\n  set particles = 50\n  set store file = "
                   << (out / "s.h5").string() << "\n  set store name = small\nend\n"
                   << "subsection program\n  subsection stage 1\n    set z = rate -1\n"
                   << "    set stop when = eps_zz <= -0.01\n    set max duration = 1\n  end\nend\n";
  for (const bool option : {false, true}) {
    std::vector<std::string> argv{GEOCOMP_EXE, "pack", c.string()};
    if (option)
      argv.insert(argv.end(), {"--store", (out / "s.h5").string()});
    const auto r = run_program(argv, s.dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("in use by another run (process " + std::to_string(::getpid())), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(option ? "parameter '--store'" : "parameter 'specimen/store file'"), std::string::npos)
      << r.err;
    EXPECT_EQ(r.out.find("preparing"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(fs::exists(out / "s.h5"));
}

TEST(OutputFolder, AStaleLockOfAProcessThatIsGoneIsTakenOverWithAWarning)
{
  const Scratch s("output-stale");
  const fs::path out = s.dir / "results";
  fs::create_directories(out);
  // Written by a run that was killed: the file stays, its flock went with the process.
  std::ofstream(out / ".geocomp.lock") << "process 999999 on gone-host: geocomp pair killed.prm\n";
  const fs::path c = write_point_case(s.dir, out.string());
  const auto r = run_program({GEOCOMP_EXE, "material-point", c.string()}, s.dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: output folder '" + out.string() + "': took over the lock left by process 999999"),
            std::string::npos)
    << r.err;
  EXPECT_TRUE(fs::exists(out / "material-point.h5"));
  EXPECT_FALSE(fs::exists(out / ".geocomp.lock")) << "removed when the run ends";
}

TEST(OutputFolder, FoldersARunMadeAndLeftEmptyAreRemovedWithTheLock)
{
  const Scratch s("output-empty");
  const fs::path c = write_point_case(s.dir, "unused");
  // report finds no results to report (a run failure): the folders it made go again.
  const auto r = run_program({GEOCOMP_EXE, "report", c.string(), "--output", (s.dir / "a/b/c").string()}, s.dir);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("no results"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(s.dir / "a")) << "a/b/c left behind";
}

TEST(OutputFolder, AnOutputPathThatIsAFileOrCannotBeCreatedIsBadInputExitTwo)
{
  const Scratch s("output-path");
  const fs::path file = s.dir / "a-file";
  std::ofstream(file) << "not a folder\n";
  const fs::path c = write_point_case(s.dir, file.string());
  for (const char *command : {"material-point", "pair", "report"}) {
    const auto r = run_program({GEOCOMP_EXE, command, c.string()}, s.dir);
    EXPECT_EQ(r.code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("parameter 'output/directory': '" + file.string() + "' exists and is not a folder"),
              std::string::npos)
      << command << ": " << r.err;
  }
  const auto under_file = run_program({GEOCOMP_EXE, "pair", c.string(), "--output", (file / "sub").string()}, s.dir);
  EXPECT_EQ(under_file.code, 2) << under_file.err;
  EXPECT_NE(under_file.err.find("parameter '--output'"), std::string::npos) << under_file.err;
  EXPECT_EQ(std::ifstream(file).get(), 'n') << "the file is left as it was";
  // The commands with case formats of their own: refused before they run.
  const fs::path cases = fs::path(std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : ".") / "cases";
  for (const auto &[command, shipped] : {std::pair<std::string, std::string>{"crush", "s2_single_particle.prm"},
                                         {"rate-sweep", "s1_concrete_compression.prm"},
                                         {"shear-box", "s4_direct_shear_100kPa.prm"}}) {
    const auto r = run_program({GEOCOMP_EXE, command, fs::absolute(cases / shipped).string(), "--output", file.string()},
                               s.dir);
    EXPECT_EQ(r.code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("parameter '--output': '" + file.string() + "' exists and is not a folder"), std::string::npos)
      << command << ": " << r.err;
  }
}

TEST(OutputFolder, QuotesSpacesDollarParenBackQuotesAndSemicolonsInTheFolderNameRunNothing)
{
  const Scratch s("output-shell");
  // The second name closes the quotes a shell command line would have put around it.
  for (const std::string name : {"it's a \"run\" $(touch pwned1); touch pwned2 `touch pwned3` & touch pwned4",
                                 "a'; touch pwned5; echo '"}) {
    const fs::path out = s.dir / name;
    const fs::path c = write_point_case(s.dir, "unused");
    auto r = run_program({GEOCOMP_EXE, "pair", c.string(), "--output", out.string()}, s.dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out / "material-point.h5"));
    EXPECT_TRUE(fs::exists(out / "report" / "index.html"));
    if (geocomp::program_available("gnuplot"))
      EXPECT_TRUE(fs::exists(out / "report" / "stress_strain.png")) << "gnuplot ran in the folder";
    // calibrate: its target lies in the folder, its report (gnuplot too) goes under it.
    std::ofstream(s.dir / "cal.prm") << "set engines = material-point\n"
                                     << "subsection continuum\n  set youngs modulus = 150e6\nend\n"
                                     << "subsection program\n  set sampling interval = 0.002\n  subsection stage 1\n"
                                     << "    set x = stress -2e5\n    set y = stress -2e5\n    set z = rate -1\n"
                                     << "    set stop when = eps_zz <= -0.02\n    set max duration = 1\n  end\nend\n"
                                     << "subsection calibration\n  set targets = " << (out / "material-point.h5").string()
                                     << "\n  set free parameters = E\n  set quantities = q\nend\n";
    r = run_program({GEOCOMP_EXE, "calibrate", (s.dir / "cal.prm").string(), "--output", out.string()}, s.dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out / "calibration" / "calibrated.prm"));
    if (geocomp::program_available("gnuplot"))
      EXPECT_TRUE(fs::exists(out / "calibration" / "fit0.png")) << "gnuplot ran in the folder";
  }
  EXPECT_EQ(files_named_pwned(s.dir), 0u);
  EXPECT_EQ(files_named_pwned(fs::current_path()), 0u);
}
