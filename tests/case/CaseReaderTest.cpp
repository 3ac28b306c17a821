// The case reader under hostile input: includes (cycles, depth, devices, balance), size
// and line bounds, UTF-8, JSON nesting and syntax that .prm cannot carry. Each input is
// refused with one CaseError naming the file (and the entry or the included file), never
// a crash, a hang or a read without end. Also: the program stage's elastic-limit entries.
#include "compare/case/CaseDescription.h"
#include "common/case/InputLimits.h"
#include "tests/common/ScratchFolder.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using geocomp::CaseError;
using geocomp::parse_case;
using geocomp::read_case;

namespace {
const std::string program = "subsection program\n  subsection stage 1\n    set z = rate -1\n"
                            "    set stop when = eps_zz <= -0.01\n    set max duration = 1\n  end\nend\n";

/// A fresh folder for one test's files, removed afterwards, and a way to write them.
struct Folder : geocomp::test::ScratchFolder {
  explicit Folder(const std::string &name) : ScratchFolder("case-" + name) {}
  fs::path write(const std::string &name, const std::string &text) const
  {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
  }
};

/// The CaseError that reading `path` throws (fails the test when none is thrown).
CaseError refusal_of_file(const fs::path &path)
{
  try {
    read_case(path.string());
  } catch (const CaseError &e) {
    return e;
  }
  ADD_FAILURE() << path << " was accepted";
  return CaseError("", "", "");
}

CaseError refusal_of_text(const std::string &text, const std::string &name)
{
  try {
    parse_case(text, name);
  } catch (const CaseError &e) {
    return e;
  }
  ADD_FAILURE() << name << " was accepted";
  return CaseError("", "", "");
}

bool contains(const std::string &s, const std::string &part) { return s.find(part) != std::string::npos; }
} // namespace

TEST(CaseIncludes, ACaseThatIncludesItselfIsRefusedNamingTheFile)
{
  const Folder f("self");
  const fs::path c = f.write("self.prm", "set title = loop\ninclude self.prm\n" + program);
  const CaseError e = refusal_of_file(c);
  EXPECT_EQ(e.file, c.string());
  EXPECT_EQ(e.parameter, "(file)");
  EXPECT_TRUE(contains(e.what(), "line 2 includes")) << e.what();
  EXPECT_TRUE(contains(e.what(), "cycle")) << e.what();
}

TEST(CaseIncludes, ACycleThroughAnotherFileIsRefusedWhereItCloses)
{
  const Folder f("cycle");
  const fs::path a = f.write("a.prm", "include parts/b.prm\n" + program);
  f.write("parts/b.prm", "set title = b\ninclude ../a.prm\n");
  const CaseError e = refusal_of_file(a);
  EXPECT_EQ(e.file, a.string());
  EXPECT_TRUE(contains(e.what(), "line 2 of '" + (f.dir / "parts/b.prm").string() + "' includes")) << e.what();
}

TEST(CaseIncludes, EightLevelsAreReadAndANinthIsRefused)
{
  const Folder f("depth");
  // level k includes level k + 1; the last one sets the title.
  auto chain = [&](int levels) {
    for (int k = 1; k < levels; ++k)
      f.write("level" + std::to_string(k) + ".prm", "include level" + std::to_string(k + 1) + ".prm\n");
    f.write("level" + std::to_string(levels) + ".prm", "set title = deepest\n");
    return f.write("case.prm", "include level1.prm\n" + program);
  };
  const fs::path eight = chain(int(geocomp::input_limits::max_include_depth));
  EXPECT_EQ(read_case(eight.string()).title, "deepest");
  const fs::path nine = chain(int(geocomp::input_limits::max_include_depth) + 1);
  const CaseError e = refusal_of_file(nine);
  EXPECT_TRUE(contains(e.what(), "nested more than 8 deep")) << e.what();
}

TEST(CaseIncludes, AnIncludedSectionIsReadRelativeToTheIncludingFileAndItsStagesCount)
{
  const Folder f("relative");
  f.write("sections/continuum.prm", "subsection continuum\n  set youngs modulus = 3e8\nend\n");
  f.write("sections/program.prm", program);
  const fs::path c = f.write("case.prm", "include sections/continuum.prm\ninclude sections/program.prm\n");
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::temp_directory_path()); // the working directory plays no part
  const geocomp::CaseDescription d = read_case(c.string());
  fs::current_path(cwd);
  EXPECT_EQ(d.continuum.youngs_modulus, 3e8);
  EXPECT_EQ(d.program.stages.size(), 1u);
}

TEST(CaseIncludes, AnErrorInsideAnIncludedFileNamesThatFileAndItsLine)
{
  const Folder f("line");
  f.write("part.prm", "# a comment\nsubsection specimen\n  set particles = many\nend\n");
  const fs::path c = f.write("case.prm", "set title = t\n\ninclude part.prm\n" + program);
  const CaseError e = refusal_of_file(c);
  EXPECT_EQ(e.file, c.string());
  EXPECT_EQ(e.parameter, "specimen/particles");
  EXPECT_TRUE(contains(e.what(), "line 3 of '" + (f.dir / "part.prm").string() + "'")) << e.what();
  // A line of the case after the include keeps its own number.
  const fs::path d = f.write("case2.prm", "include part2.prm\nsubsection specimen\n  set radius = -1\nend\n" + program);
  f.write("part2.prm", "set title = a\nset seed = 3\n");
  const CaseError e2 = refusal_of_file(d);
  EXPECT_EQ(e2.parameter, "specimen/radius");
  EXPECT_TRUE(contains(e2.what(), "line 3:")) << e2.what();
}

TEST(CaseIncludes, AnIncludedFileThatLeavesASubsectionOpenIsRefused)
{
  const Folder f("balance");
  f.write("open.prm", "subsection continuum\n  set youngs modulus = 3e8\n");
  const fs::path c = f.write("case.prm", "include open.prm\nend\n" + program);
  const CaseError e = refusal_of_file(c);
  EXPECT_TRUE(contains(e.what(), "does not close every subsection")) << e.what();
}

TEST(CaseIncludes, DirectoriesFifosAndDevicesAreRefusedWithoutBlockingOrReading)
{
  const Folder f("devices");
  fs::create_directories(f.dir / "folder.prm");
  const fs::path fifo = f.dir / "pipe.prm";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // As the case itself.
  EXPECT_TRUE(contains(refusal_of_file(f.dir / "folder.prm").what(), "is a directory"));
  EXPECT_TRUE(contains(refusal_of_file(fifo).what(), "is a FIFO"));
  EXPECT_TRUE(contains(refusal_of_file("/dev/zero").what(), "is a character device"));
  // As an included file.
  for (const std::string target : {"folder.prm", "pipe.prm", "/dev/zero", "/dev/urandom"}) {
    const fs::path c = f.write("case.prm", "include " + target + "\n" + program);
    const CaseError e = refusal_of_file(c);
    EXPECT_EQ(e.file, c.string());
    EXPECT_TRUE(contains(e.what(), "expected a regular file")) << e.what();
  }
  const CaseError missing = refusal_of_file(f.write("case.prm", "include nowhere.prm\n" + program));
  EXPECT_TRUE(contains(missing.what(), "cannot be read")) << missing.what();
}

TEST(CaseLimits, AFileOverOneMebibyteIsRefusedAndSoIsACaseThatIncludesOneTwice)
{
  const Folder f("size");
  std::string filler;
  while (filler.size() <= (1u << 20))
    filler += "# a comment line of the kind a case file holds, repeated\n";
  const fs::path big = f.write("big.prm", filler + program);
  EXPECT_TRUE(contains(refusal_of_file(big).what(), "at most 1 MiB")) << refusal_of_file(big).what();
  std::string half;
  for (int k = 0; k < 12000; ++k)
    half += std::string(49, '#') + "\n";
  f.write("half.prm", half);
  const fs::path twice = f.write("case.prm", "include half.prm\ninclude half.prm\n" + program);
  EXPECT_TRUE(contains(refusal_of_file(twice).what(), "more than 1 MiB"));
}

TEST(CaseLimits, AValueLongerThanTheLineLimitIsRefusedNamingItsEntry)
{
  const std::string title(geocomp::input_limits::max_line_bytes + 1, 'x');
  CaseError e = refusal_of_text("set title = " + title + "\n" + program, "long.prm");
  EXPECT_EQ(e.parameter, "title");
  e = refusal_of_text("subsection output\n  set directory = a\\\n" + title + "\nend\n" + program, "long.prm");
  EXPECT_EQ(e.parameter, "output/directory") << "continued lines count as one";
  EXPECT_EQ(parse_case("set title = " + std::string(1000, 'x') + "\n" + program, "ok.prm").title.size(), 1000u);
}

TEST(CaseText, InvalidUtf8IsRefusedWithItsLineAndValidUtf8IsKept)
{
  for (const std::string &bad : {std::string("\xff"), std::string("\xc0\xaf"), std::string("\xed\xa0\x80"),
                                std::string("\xf4\x90\x80\x80"), std::string("\xe2\x82")}) {
    const CaseError e = refusal_of_text("# case\nset title = a" + bad + "b\n" + program, "utf.prm");
    EXPECT_EQ(e.parameter, "(file)");
    EXPECT_TRUE(contains(e.what(), "line 2 is not valid UTF-8")) << e.what();
  }
  EXPECT_EQ(parse_case("set title = Mohr\xe2\x80\x93" "Coulomb \xcf\x83\n" + program, "ok.prm").title,
            "Mohr\xe2\x80\x93" "Coulomb \xcf\x83");
  EXPECT_TRUE(contains(refusal_of_text("set title = a\n" + std::string(1, '\0'), "nul.prm").what(), "NUL byte at line 2"));
}

TEST(CaseJson, OneHundredThousandNestedBracketsAreRefusedWithoutOverflowingTheStack)
{
  const std::string arrays = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(refusal_of_text(arrays, "deep.json").parameter, "(file)");
  std::string objects;
  for (int k = 0; k < 100000; ++k)
    objects += "{\"a\":";
  objects += "1" + std::string(100000, '}');
  EXPECT_TRUE(contains(refusal_of_text(objects, "deep.json").what(), "nested more than 32 deep"));
}

TEST(CaseJson, NestingUpToTheLimitIsParsedOnlyBeyondItRefused)
{
  auto nested = [](unsigned int depth) {
    std::string s = "{";
    for (unsigned int k = 1; k < depth; ++k)
      s += "\"a\": {";
    return s + "\"x\": 1" + std::string(depth, '}');
  };
  // Within the limit the nesting is fine; the sections are then unknown to the case.
  EXPECT_EQ(refusal_of_text(nested(geocomp::input_limits::max_json_depth), "n.json").parameter, "a");
  EXPECT_TRUE(contains(refusal_of_text(nested(geocomp::input_limits::max_json_depth + 1), "n.json").what(),
                       "nested more than"));
}

TEST(CaseJson, ArraysNullAndValuesThatPrmCannotCarryAreRefusedNamingTheEntry)
{
  EXPECT_EQ(refusal_of_text(R"({"specimen": {"particles": [1, 2]}})", "a.json").parameter, "specimen/particles");
  EXPECT_EQ(refusal_of_text(R"({"seed": null})", "n.json").parameter, "seed");
  EXPECT_EQ(refusal_of_text(R"({"title": "case #3"})", "h.json").parameter, "title");
  EXPECT_EQ(refusal_of_text(R"({"title": "two\nlines"})", "l.json").parameter, "title");
  EXPECT_EQ(refusal_of_text(R"({"title": "goes on\\"})", "c.json").parameter, "title");
  EXPECT_EQ(refusal_of_text(R"({"output": {"a=b": 1}})", "k.json").parameter, "output");
  EXPECT_EQ(refusal_of_text(R"([1])", "t.json").parameter, "(file)");
  EXPECT_EQ(refusal_of_text(R"("just a string")", "s.json").parameter, "(file)");
  EXPECT_TRUE(contains(refusal_of_text(R"({"title": "x"} trailing)", "g.json").what(), "not valid JSON"));
}

TEST(CaseJson, AJsonCaseReadsAsTheSamePrmCase)
{
  const std::string json = R"({"title": "same", "seed": 7, "engines": "material-point",
    "continuum": {"youngs modulus": 2.5e8, "poisson ratio": 0.3},
    "program": {"stage 1": {"z": "rate -1", "stop when": "eps_zz <= -0.01", "max duration": 1}}})";
  const geocomp::CaseDescription j = parse_case(json, "same.json");
  const geocomp::CaseDescription p = parse_case("set title = same\nset seed = 7\nset engines = material-point\n"
                                                "subsection continuum\n  set youngs modulus = 2.5e8\n"
                                                "  set poisson ratio = 0.3\nend\n" + program, "same.prm");
  EXPECT_EQ(j.title, p.title);
  EXPECT_EQ(j.seed, p.seed);
  EXPECT_EQ(j.engines, p.engines);
  EXPECT_EQ(j.continuum.youngs_modulus, p.continuum.youngs_modulus);
  EXPECT_EQ(j.continuum.poisson_ratio, p.continuum.poisson_ratio);
  EXPECT_EQ(j.program.stages.size(), p.program.stages.size());
}

TEST(CaseLimits, SubsectionsNestedBeyondTheLimitAreRefusedAndReenteringOnesCostsNothing)
{
  std::string deep;
  for (unsigned int k = 0; k <= geocomp::input_limits::max_section_depth; ++k)
    deep += "subsection a\n";
  EXPECT_TRUE(contains(refusal_of_text(deep, "deep.prm").what(), "nested more than 32 deep"));
  // 31 levels of long names, then 40 000 subsections entered and left inside them: the
  // reader keeps one record per distinct subsection, not one path per line (that would
  // be tens of gigabytes); deal.II then refuses the first unknown subsection.
  std::string wide;
  for (int k = 0; k < 31; ++k)
    wide += "subsection " + std::string(8000, char('a' + k % 26)) + "\n";
  for (int k = 0; k < 40000; ++k)
    wide += "subsection b\nend\n";
  ASSERT_LT(wide.size(), std::size_t(1) << 20);
  EXPECT_EQ(refusal_of_text(wide, "wide.prm").parameter, std::string(8000, 'a'));
}

// The program stage's `locate elastic limit` (docs/metrics.md): read with its tolerance,
// written into the canonical parameters only when on (older cases keep their text), and
// refused without unloading branches, naming the entry.
TEST(CaseProgram, LocateElasticLimitIsReadWrittenWhenOnAndRefusedWithoutBranches)
{
  const std::string stage = "subsection program\n  subsection stage 1\n    set z = rate -1\n"
                            "    set stop when = eps_zz <= -0.01\n    set max duration = 1\n";
  const std::string branches = "    set unload at = eps_zz <= -0.002; eps_zz <= -0.008\n";
  const std::string locate = "    set locate elastic limit = true\n    set elastic limit tolerance = 0.0005\n";
  const auto on = parse_case(stage + branches + locate + "  end\nend\n", "locate.prm");
  EXPECT_TRUE(on.program.stages[0].locate_elastic_limit);
  EXPECT_EQ(on.program.stages[0].elastic_limit_tolerance, 0.0005);
  EXPECT_NE(geocomp::parameters_text(on).find("locate elastic limit"), std::string::npos);
  const auto off = parse_case(stage + branches + "  end\nend\n", "plain.prm");
  EXPECT_FALSE(off.program.stages[0].locate_elastic_limit);
  EXPECT_EQ(geocomp::parameters_text(off).find("locate elastic limit"), std::string::npos);
  const CaseError e = refusal_of_text(stage + locate + "  end\nend\n", "no-branches.prm");
  EXPECT_EQ(e.parameter, "program/stage 1/locate elastic limit");
}
