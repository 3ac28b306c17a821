// The command line's messages at its three levels (compare/cli/Log.h, spdlog) and its
// parsing (CLI11, compare/cli/Arguments.cpp): --quiet leaves warnings and errors alone and
// no progress, --verbose adds the "debug:" details, both given before or after the command;
// a malformed line is refused with exit 2 and the command's usage, whatever the level.
#include "tests/cli/PointCase.h"
#include "tests/common/CommandRun.h"
#include "tests/common/ScratchFolder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using geocomp::test::run_program;
using geocomp::test::write_point_case;
using Scratch = geocomp::test::ScratchFolder;

TEST(Verbosity, NormalSaysWhatItWroteQuietSaysNothingAndBothWriteTheSameResults)
{
  Scratch s("verbosity-levels");
  const fs::path c = write_point_case(s.dir, "out");
  const auto normal = run_program({GEOCOMP_EXE, "material-point", c.string(), "--output", "normal"}, s.dir);
  ASSERT_EQ(normal.code, 0) << normal.err;
  EXPECT_NE(normal.out.find("material-point: "), std::string::npos) << normal.out;
  EXPECT_NE(normal.out.find("normal/material-point.h5"), std::string::npos) << normal.out;
  EXPECT_EQ(normal.err.find("debug:"), std::string::npos) << normal.err;

  for (const auto &argv : {std::vector<std::string>{GEOCOMP_EXE, "material-point", c.string(), "--output", "quiet", "--quiet"},
                           std::vector<std::string>{GEOCOMP_EXE, "-q", "material-point", c.string(), "--output", "quiet"}}) {
    fs::remove_all(s.dir / "quiet");
    const auto quiet = run_program(argv, s.dir);
    ASSERT_EQ(quiet.code, 0) << quiet.err;
    EXPECT_EQ(quiet.out, "");
    EXPECT_EQ(quiet.err, "");
    EXPECT_TRUE(fs::exists(s.dir / "quiet/material-point.h5"));
  }
}

TEST(Verbosity, VerboseAddsTheDetailsOnStandardErrorBeforeOrAfterTheCommand)
{
  Scratch s("verbosity-verbose");
  const fs::path c = write_point_case(s.dir, "out");
  for (const auto &argv : {std::vector<std::string>{GEOCOMP_EXE, "material-point", c.string(), "--verbose", "--force"},
                           std::vector<std::string>{GEOCOMP_EXE, "--verbose", "material-point", c.string(), "--force"}}) {
    const auto r = run_program(argv, s.dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("debug: case " + c.string() + " read and validated: engines material-point"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("debug: material-point: writing out/material-point.h5 (status complete)"), std::string::npos)
        << r.err;
    EXPECT_NE(r.out.find("material-point: "), std::string::npos) << r.out;
  }
}

TEST(Verbosity, QuietStillReportsErrorsAndExitsTwoOnBadInput)
{
  Scratch s("verbosity-errors");
  fs::create_directories(s.dir);
  std::ofstream(s.dir / "bad.prm") << "set engines = material-point\nset no such entry = 1\n";
  const auto r = run_program({GEOCOMP_EXE, "check", "bad.prm", "--quiet"}, s.dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("bad.prm"), std::string::npos) << r.err;
}

TEST(CommandLine, MalformedLinesAreRefusedWithExitTwoAndTheCommandsUsage)
{
  Scratch s("command-line");
  const fs::path c = write_point_case(s.dir, "out");
  struct Line {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Line> lines = {
      {{"material-point", c.string(), "--no-such-option"}, "--no-such-option"},
      {{"material-point", c.string(), "--output"}, "--output"},
      {{"material-point", c.string(), "-q", "-v"}, "exclude each other"},
      {{"check"}, "expected"},
  };
  for (const Line &l : lines) {
    std::vector<std::string> argv{GEOCOMP_EXE};
    argv.insert(argv.end(), l.args.begin(), l.args.end());
    const auto r = run_program(argv, s.dir);
    EXPECT_EQ(r.code, 2) << l.says;
    EXPECT_NE(r.err.find(l.says), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("usage: geocomp " + l.args[0]), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(s.dir / "out"));
  const auto unknown = run_program({GEOCOMP_EXE, "no-such-command"}, s.dir);
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("unknown command 'no-such-command'"), std::string::npos) << unknown.err;
  const auto level_alone = run_program({GEOCOMP_EXE, "-q"}, s.dir);
  EXPECT_EQ(level_alone.code, 2) << "a level without a command is bad input";
  const auto unknown_after_level = run_program({GEOCOMP_EXE, "-q", "no-such-command"}, s.dir);
  EXPECT_EQ(unknown_after_level.code, 2);
  EXPECT_NE(unknown_after_level.err.find("unknown command 'no-such-command'"), std::string::npos) << unknown_after_level.err;
  const auto inline_value = run_program({GEOCOMP_EXE, "material-point", c.string(), "--output=given"}, s.dir);
  EXPECT_EQ(inline_value.code, 0) << inline_value.err;
  EXPECT_TRUE(fs::exists(s.dir / "given/material-point.h5"));
}
