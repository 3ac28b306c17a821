// Inputs a file in tests/bad_cases cannot hold, made at test time: a FIFO, /dev/zero, a
// folder given as the case, 100 000 nested JSON brackets, a 2 MiB case and a 50 MB title.
// Every command that reads a case refuses each one at once - no hang, no crash, no read
// without end: exit code 2, the file named, nothing written.
#include "tests/common/CommandRun.h"
#include "tests/common/ScratchFolder.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using geocomp::test::run_program;
using Scratch = geocomp::test::ScratchFolder;

namespace {
std::size_t entries(const fs::path &dir)
{
  std::size_t n = 0;
  for ([[maybe_unused]] const auto &e : fs::recursive_directory_iterator(dir))
    ++n;
  return n;
}

const char *const commands[] = {"check", "dem",      "continuum", "material-point", "pair",   "pack",
                                "calibrate", "report", "compare",   "sweep"};
} // namespace

TEST(HostileInput, EveryCommandRefusesAFifoADeviceAndAFolderAtOnceNamingThemAndWritingNothing)
{
  const Scratch s("hostile-special");
  const fs::path fifo = s.dir / "inputs" / "pipe.prm", folder = s.dir / "inputs" / "folder.prm";
  fs::create_directories(folder);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path cwd = s.dir / "cwd";
  for (const fs::path &input : {fifo, folder, fs::path("/dev/zero")})
    for (const char *command : commands) {
      fs::create_directories(cwd);
      const auto r = run_program({GEOCOMP_EXE, command, input.string()}, cwd, 30.0);
      EXPECT_EQ(r.code, 2) << command << " " << input << (r.code == -2 ? " hung" : "") << ": " << r.err;
      EXPECT_NE(r.err.find(input.string() + ": parameter '(file)'"), std::string::npos) << command << ": " << r.err;
      EXPECT_EQ(entries(cwd), 0u) << command << " " << input << " wrote into the working directory";
      fs::remove_all(cwd);
    }
}

TEST(HostileInput, HundredThousandNestedBracketsATwoMebibyteCaseAndAFiftyMegabyteTitleAreRefused)
{
  const Scratch s("hostile-large");
  const fs::path brackets = s.dir / "brackets.json", big = s.dir / "big.prm", title = s.dir / "title.prm";
  std::ofstream(brackets) << std::string(100000, '[') << std::string(100000, ']');
  {
    std::ofstream out(big);
    for (int k = 0; k < 40000; ++k)
      out << "# a comment line of the sort a case file holds, 50 bytes\n";
  }
  std::ofstream(title) << "set title = " << std::string(50u << 20, 'x') << "\n";
  const fs::path cwd = s.dir / "cwd";
  for (const fs::path &input : {brackets, big, title})
    for (const char *command : {"check", "pair", "dem", "calibrate"}) {
      fs::create_directories(cwd);
      const auto r = run_program({GEOCOMP_EXE, command, input.string()}, cwd, 60.0);
      EXPECT_EQ(r.code, 2) << command << " " << input << ": " << r.err;
      EXPECT_NE(r.err.find(input.string()), std::string::npos) << r.err;
      EXPECT_LT(r.err.size(), 2000u) << "the message does not echo the input";
      EXPECT_EQ(entries(cwd), 0u) << command << " " << input;
      fs::remove_all(cwd);
    }
}
