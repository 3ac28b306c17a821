// One home per parameter (issue 31): each engine's sections list their entries once, in a
// `visit` beside the struct's fields; the canonical text, the specimen record (the key of a
// prepared specimen's reuse) and /meta/parameters are written from those lists. These tests
// prove the lists name exactly the declared entries, and that the record changes with every
// DEM entry except those that cannot change a prepared specimen.
#include "common/case/CanonicalText.h"
#include "common/case/SectionReader.h"
#include "compare/calibrate/CalibrationSection.h"
#include "compare/case/CaseDescription.h"
#include "continuum/case/ContinuumSections.h"
#include "coupled/case/RveSection.h"
#include "dem/case/DemSections.h"
#include "dem/case/SpecimenRecord.h"
#include "tests/common/ScratchFolder.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {
using namespace geocomp;

/// The declared entries of every section, as `section/entry`, in declaration order, from
/// deal.II's own description of the ParameterHandler.
std::vector<std::string> declared_entries()
{
  dealii::ParameterHandler prm;
  sections::declare_head(prm);
  sections::declare_dem_sections(prm);
  sections::declare_continuum(prm);
  sections::declare_dem_rve(prm);
  sections::declare_output(prm);
  sections::declare_calibration(prm);
  std::ostringstream json;
  prm.print_parameters(json, dealii::ParameterHandler::OutputStyle(dealii::ParameterHandler::OutputStyle::JSON |
                                                                   dealii::ParameterHandler::OutputStyle::KeepDeclarationOrder));
  std::vector<std::string> entries;
  const auto walk = [&entries](const auto &self, const nlohmann::ordered_json &tree, const std::string &prefix) -> void {
    for (const auto &[key, node] : tree.items())
      if (node.is_object() && node.contains("default_value"))
        entries.push_back(prefix + key);
    for (const auto &[key, node] : tree.items())
      if (node.is_object() && !node.contains("default_value"))
        self(self, node, prefix + key + "/");
  };
  walk(walk, nlohmann::ordered_json::parse(json.str()), "");
  return entries;
}

/// The entries the visit lists name, as `section/entry`, from the canonical text of a
/// default case.
std::vector<std::string> visited_entries()
{
  CaseDescription c;
  std::istringstream lines(parameters_text(c));
  std::vector<std::string> entries;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("program", 0) != 0) // the program has stages of its own (ProgramSection.cpp)
      entries.push_back(line.substr(0, line.find(" = ")));
  return entries;
}

/// Changes the `target`-th field a visit list names to another valid-looking value.
struct ChangeOne {
  std::size_t target, seen = 0;
  std::string changed;
  std::string section;

  static void change(std::string &s) { s += "-changed"; }
  static void change(double &v) { v = v * 1.5 + 0.25; }
  static void change(unsigned int &v) { v += 1; }
  static void change(bool &v) { v = !v; }
  template <class T>
  void operator()(const char *entry, T &value)
  {
    if (seen++ == target) {
      change(value);
      changed = section + "/" + entry;
    }
  }
};

bool independent(const std::string &entry)
{
  const auto &list = dem::specimen_independent_entries();
  return std::any_of(list.begin(), list.end(), [&](const dem::SpecimenIndependentEntry &e) { return entry == e.entry; });
}
} // namespace

TEST(ParameterHome, EverySectionsVisitListNamesExactlyItsDeclaredEntriesInDeclarationOrder)
{
  // The continuum's subsection comes after the continuum's own entries in both lists.
  const std::vector<std::string> declared = declared_entries();
  EXPECT_EQ(visited_entries(), declared);
  EXPECT_GT(declared.size(), 90u); // every section took part
}

TEST(SpecimenRecord, ChangingAnyDemEntryChangesTheRecordUnlessTheEntryCannotAffectThePreparedSpecimen)
{
  const dem::DemCase base;
  const std::string record = dem::specimen_record(base, "build");
  std::vector<std::string> unchanged;
  std::size_t n = 0;
  for (std::size_t k = 0;; ++k) {
    dem::DemCase c = base;
    ChangeOne change{k, 0, "", ""};
    dem::DemCase::visit_sections(c, [&change](const char *section, auto &p) {
      change.section = section;
      std::decay_t<decltype(p)>::visit(p, change);
    });
    if (change.changed.empty())
      break;
    ++n;
    if (dem::specimen_record(c, "build") == record)
      unchanged.push_back(change.changed);
    else
      EXPECT_FALSE(independent(change.changed)) << change.changed << " is listed as independent but is in the record";
  }
  const std::vector<std::string> declared = declared_entries();
  EXPECT_EQ(n, std::size_t(std::count_if(declared.begin(), declared.end(), [](const std::string &e) {
              return e.rfind("specimen/", 0) == 0 || e.rfind("contact/", 0) == 0 || e.rfind("dem/", 0) == 0;
            }))); // every declared DEM entry was changed once
  std::vector<std::string> listed;
  for (const dem::SpecimenIndependentEntry &e : dem::specimen_independent_entries()) {
    listed.push_back(e.entry);
    EXPECT_GT(std::string(e.reason).size(), 20u) << e.entry << ": the reason is the point";
  }
  EXPECT_EQ(unchanged, listed);
  std::cout << n << " DEM entries changed one at a time: " << n - unchanged.size() << " change the record, "
            << unchanged.size() << " cannot affect the specimen\n";
}

TEST(SpecimenRecord, HoldsTheBuildAndTheSeed)
{
  dem::DemCase c;
  const std::string a = dem::specimen_record(c, "build-a");
  EXPECT_NE(a, dem::specimen_record(c, "build-b"));
  c.seed += 1;
  EXPECT_NE(a, dem::specimen_record(c, "build-a"));
}

TEST(ParametersText, ChangesWhenAnIncludedFileChangesThoughTheCaseTextDoesNot)
{
  test::ScratchFolder scratch("parameters-text");
  const std::filesystem::path dir = scratch.dir;
  const auto write = [](const std::filesystem::path &p, const std::string &text) { std::ofstream(p) << text; };
  write(dir / "contact.prm", "subsection contact\n  set rolling friction = 0.1\nend\n");
  write(dir / "case.prm", "set engines = dem\ninclude contact.prm\nsubsection program\n  subsection stage 1\n"
                                 "    set z = rate -1\n    set stop when = eps_zz <= -0.01\n  end\nend\n");
  const CaseDescription a = read_case((dir / "case.prm").string());
  write(dir / "contact.prm", "subsection contact\n  set rolling friction = 0.2\nend\n");
  const CaseDescription b = read_case((dir / "case.prm").string());
  EXPECT_EQ(a.text, b.text);
  EXPECT_NE(parameters_text(a), parameters_text(b));
  EXPECT_NE(parameters_text(b).find("contact/rolling friction = 0.2\n"), std::string::npos) << parameters_text(b);
  EXPECT_NE(parameters_text(b).find("program/stage 1/z = rate -1\n"), std::string::npos) << parameters_text(b);
}

TEST(CanonicalNumber, IsTheShortestTextThatReadsBackToTheSameBits)
{
  EXPECT_EQ(canonical_number(0.1), "0.1");
  EXPECT_EQ(canonical_number(2e6), "2e+06");
  EXPECT_EQ(canonical_number(1.0 / 3.0), "0.3333333333333333"); // 16 digits suffice
  EXPECT_EQ(std::strtod(canonical_number(2.0 / 7.0).c_str(), nullptr), 2.0 / 7.0);
}
