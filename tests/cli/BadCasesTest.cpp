// Every malformed case file in tests/bad_cases/ is refused by every command that reads a
// case: one message naming the file and the parameter, exit code 2, and nothing written.
#include "tests/common/CommandRun.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace {
fs::path source_dir() { return fs::path(std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : "."); }
fs::path geocomp_exe() { return fs::path(GEOCOMP_EXE); }

using Result = geocomp::test::CommandResult;

/// Runs geocomp in `cwd` with the arguments (no shell); captures stdout and stderr.
Result run(const fs::path &cwd, std::vector<std::string> args)
{
  args.insert(args.begin(), geocomp_exe().string());
  return geocomp::test::run_program(args, cwd);
}

/// Subcommands that take a case file, read from `geocomp --help`.
std::vector<std::string> case_commands()
{
  std::vector<std::string> out;
  std::istringstream help(run(fs::temp_directory_path(), {"--help"}).out);
  for (std::string line; std::getline(help, line);) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    for (const char *c : {"check", "dem", "continuum", "material-point", "pair", "pack", "calibrate", "report", "compare"})
      if (name == c)
        out.push_back(name);
  }
  return out;
}

std::map<std::string, std::string> expected()
{
  std::map<std::string, std::string> m;
  std::ifstream in(source_dir() / "tests/bad_cases/expected.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    const auto tab = line.find('\t');
    m[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return m;
}
} // namespace

TEST(BadCases, AtLeastThirtyAndEveryOneListed)
{
  const auto exp = expected();
  int n = 0;
  for (const auto &e : fs::directory_iterator(source_dir() / "tests/bad_cases")) {
    // includes/ holds the files the include cases include; they are not cases themselves.
    if (e.path().filename() == "expected.txt" || e.is_directory())
      continue;
    ++n;
    EXPECT_TRUE(exp.count(e.path().filename().string())) << e.path() << " has no line in expected.txt";
  }
  EXPECT_GE(n, 30);
}

// One test per command (ctest runs them in parallel): every bad case, refused by that command.
class BadCasesFor : public ::testing::TestWithParam<std::string> {};

TEST_P(BadCasesFor, EachIsRefusedWithFileParameterExitTwoAndNoOutput)
{
  const std::string command = GetParam();
  const auto commands = case_commands();
  ASSERT_NE(std::find(commands.begin(), commands.end(), command), commands.end())
    << command << " is not listed by geocomp --help";
  for (const auto &[file, parameter] : expected()) {
    const fs::path path = fs::absolute(source_dir() / "tests/bad_cases" / file);
    const fs::path cwd = fs::temp_directory_path() / ("geocomp-bad-" + std::to_string(::getpid()));
    fs::remove_all(cwd);
    fs::create_directories(cwd);
    const Result r = run(cwd, {command, path.string()});
    EXPECT_EQ(r.code, 2) << command << " " << file << ": " << r.err;
    EXPECT_NE(r.err.find(path.string()), std::string::npos) << command << " " << file << ": " << r.err;
    EXPECT_NE(r.err.find("parameter '" + parameter), std::string::npos)
      << command << " " << file << " should name '" << parameter << "': " << r.err;
    // One message: a single line on stderr.
    EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    std::size_t left = 0;
    for ([[maybe_unused]] const auto &e : fs::recursive_directory_iterator(cwd))
      ++left;
    EXPECT_EQ(left, 0u) << command << " " << file << " left files behind";
    fs::remove_all(cwd);
  }
}

INSTANTIATE_TEST_SUITE_P(BadCases, BadCasesFor,
                         ::testing::Values("check", "dem", "continuum", "material-point", "pair", "pack", "calibrate",
                                           "report", "compare"),
                         [](const ::testing::TestParamInfo<std::string> &info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(CommandLine, UnreadableCaseAndUnknownOptionsAreBadInput)
{
  const fs::path cwd = fs::temp_directory_path();
  EXPECT_EQ(run(cwd, {"check", "/nonexistent/case.prm"}).code, 2);
  EXPECT_EQ(run(cwd, {"check"}).code, 2);
  EXPECT_EQ(run(cwd, {"check", "--frobnicate", "x.prm"}).code, 2);
  EXPECT_EQ(run(cwd, {"no-such-command"}).code, 2);
  EXPECT_EQ(run(cwd, {"--version"}).code, 0);
  EXPECT_EQ(run(cwd, {"check", "--help"}).code, 0);
}

TEST(CommandLine, ShippedCasesPassCheck)
{
  // S1's rate-sweep cases (cases/s1_*.prm without a loading program) have their own format
  // and checker; an s1_ case with a program (continuum/model = nikolaevsky) is a case file.
  // A case on a specimen of the core store passes once the store is packed; before, check
  // refuses it as the DEM would, naming the store file and the command that builds it.
  for (const auto &e : fs::recursive_directory_iterator(source_dir() / "cases"))
    if (e.path().extension() == ".prm" || e.path().extension() == ".json") {
      std::stringstream text;
      text << std::ifstream(e.path()).rdbuf();
      const bool s1 = e.path().filename().string().rfind("s1_", 0) == 0 &&
                      text.str().find("subsection program") == std::string::npos;
      const bool s2 = e.path().filename().string().rfind("s2_", 0) == 0;  // S2 crush cases
      const bool s4 = e.path().filename().string().rfind("s4_", 0) == 0;  // S4 shear-box cases
      const bool study = e.path().parent_path().filename() == "studies"; // study files (docs/studies.md)
      if (study && text.str().find("subsection study") == std::string::npos)
        continue; // a part the studies include (their `overrides`), checked through them
      const std::string file = fs::absolute(e.path()).string();
      // Store files are named relative to the repository root, where the cases are run.
      const Result r = run(source_dir(), s1   ? std::vector<std::string>{"rate-sweep", file, "--check"}
                                         : s2 ? std::vector<std::string>{"crush", file, "--check"}
                                         : s4 ? std::vector<std::string>{"shear-box", file, "--check"}
                                         : study ? std::vector<std::string>{"study", file, "--check"}
                                              : std::vector<std::string>{"check", file});
      static const std::regex store_source(R"(\n\s*set\s+source\s*=\s*store)");
      const bool unpacked = std::regex_search(text.str(), store_source) && !fs::exists(source_dir() / "cases/store/s0.h5");
      // A case whose calibration/scatter names the results of another case's run passes
      // once that run is made; before, check refuses it naming the entry.
      static const std::regex scatter_entry(R"(\n\s*set\s+scatter\s*=\s*(\S+))");
      const std::string case_text = text.str();
      std::smatch scatter;
      const bool unmade = std::regex_search(case_text, scatter, scatter_entry) &&
                          !fs::exists(source_dir() / scatter[1].str());
      if (unmade) {
        EXPECT_EQ(r.code, 2) << e.path();
        EXPECT_NE(r.err.find("calibration/scatter"), std::string::npos) << r.err;
      } else if (unpacked) {
        EXPECT_EQ(r.code, 2) << e.path();
        EXPECT_NE(r.err.find("parameter 'specimen/store file'"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("geocomp pack"), std::string::npos) << r.err;
      } else {
        EXPECT_EQ(r.code, 0) << e.path() << ": " << r.err;
      }
    }
}

TEST(CommandLine, CalibrateRefusesTheNikolaevskyModelNamingContinuumModel)
{
  // The case is valid (check accepts it) but calibrate fits Mohr-Coulomb parameters only.
  const fs::path cwd = fs::temp_directory_path();
  const std::string file = fs::absolute(source_dir() / "cases/s1_sandstone_isochoric.prm").string();
  EXPECT_EQ(run(cwd, {"check", file}).code, 0);
  const Result r = run(cwd, {"calibrate", file});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("parameter 'continuum/model'"), std::string::npos) << r.err;
}

TEST(CommandLine, CrushChecksTheShippedS2CasesAndRefusesBadInputWithExitTwo)
{
  const fs::path cwd = fs::temp_directory_path();
  for (const char *name : {"s2_single_particle", "s2_single_particle_ten_seeds", "s2_uniaxial_cube", "s2_uniaxial_4ball",
                           "s2_uniaxial_18ball"}) {
    const fs::path file = fs::absolute(source_dir() / "cases" / (std::string(name) + ".prm"));
    ASSERT_TRUE(fs::exists(file)) << file;
    const Result r = run(cwd, {"crush", file.string(), "--check"});
    EXPECT_EQ(r.code, 0) << name << ": " << r.err;
  }
  struct Bad {
    const char *text, *parameter;
  };
  const Bad bad[] = {{"subsection breakage\n  set mode = 5-ball\nend\n", "mode"},
                     {"subsection breakage\n  set characteristic strength = 0\nend\n", "characteristic strength"},
                     {"subsection breakage\n  set minimum size = 8\n  set breakage limit = 5\nend\n", "minimum size"},
                     {"subsection single particle\n  set maximum diameter = 20\nend\n", "maximum diameter"},
                     {"subsection single particle\n  set seeds = 0\nend\n", "seeds"},
                     {"subsection uniaxial\n  set lid speed = fast\nend\n", "lid speed"},
                     {"subsection uniaxial\n  set packing = hexagonal\nend\n", "packing"},
                     {"subsection output\n  set polar bins = 35\nend\n", "polar bins"},
                     {"set no such entry = 1\n", "no such entry"}};
  const fs::path file = cwd / "geocomp_bad_crush.prm";
  for (const Bad &b : bad) {
    std::ofstream(file) << b.text;
    const Result r = run(cwd, {"crush", file.string(), "--check"});
    EXPECT_EQ(r.code, 2) << b.text;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(b.parameter), std::string::npos) << r.err;
  }
  fs::remove(file);
  EXPECT_EQ(run(cwd, {"crush", "/nonexistent/case.prm", "--check"}).code, 2);
}

TEST(CommandLine, ShearBoxRefusesBadInputNamingFileAndParameterWithExitTwo)
{
  const fs::path cwd = fs::temp_directory_path();
  struct Bad {
    const char *text, *parameter;
  };
  const Bad bad[] = {{"subsection loading\n  set max shear = 0.5\nend\n", "max shear"},
                     {"subsection loading\n  set normal stress = high\nend\n", "normal stress"},
                     {"subsection grains\n  set mass min = 3\nend\n", "mass min"},
                     {"subsection box\n  set gap fraction = -1\nend\n", "gap fraction"},
                     {"subsection loading\n  set upper box = floating\nend\n", "upper box"},
                     {"subsection loading\n  set box mass = 0\nend\n", "box mass"},
                     {"subsection loading\n  set box max rise = 0.05\nend\n", "box max rise"},
                     {"set no such entry = 1\n", "no such entry"}};
  const fs::path file = cwd / "geocomp_bad_shear_box.prm";
  for (const Bad &b : bad) {
    std::ofstream(file) << b.text;
    const Result r = run(cwd, {"shear-box", file.string(), "--check"});
    EXPECT_EQ(r.code, 2) << b.text;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(b.parameter), std::string::npos) << r.err;
  }
  fs::remove(file);
  EXPECT_EQ(run(cwd, {"shear-box", "/nonexistent/case.prm", "--check"}).code, 2);
}

TEST(CommandLine, ExportRefusesMissingStoresAndNamesWithExitTwo)
{
  const fs::path cwd = fs::temp_directory_path();
  const std::string store = fs::absolute(source_dir() / "cases/store/small.h5").string();
  Result r = run(cwd, {"export", "/nonexistent/store.h5"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/store.h5"), std::string::npos) << r.err;
  r = run(cwd, {"export", store, "no-such-specimen", "/tmp/x.xyzr"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no-such-specimen"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists("/tmp/x.xyzr"));
  EXPECT_EQ(run(cwd, {"export", store, "a-name"}).code, 2) << "a name without an output file is a usage error";
}
