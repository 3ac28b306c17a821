// Reading a study file (StudyFile.h): its own entries, then every case it makes, parsed by
// the case reader before anything is written.
#include "compare/case/StudyFile.h"

#include "common/case/ParseParameters.h"
#include "common/case/SectionReader.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

namespace geocomp {

namespace fs = std::filesystem;
using namespace dealii;

namespace {
void declare_study(ParameterHandler &prm)
{
  prm.declare_entry("title", "", Patterns::Anything(), "A title for the study's report.");
  prm.enter_subsection("study");
  prm.declare_entry("cases", "", Patterns::Anything(),
                    "Case files, separated by commas, relative to the study file's folder (or give 'base case').");
  prm.declare_entry("base case", "", Patterns::Anything(),
                    "One case file (relative to the study file's folder) whose 'swept entry' takes each of 'values'.");
  prm.declare_entry("swept entry", "", Patterns::Anything(),
                    "The entry of the base case to sweep, as 'section/entry' (geocomp print-parameters lists them).");
  prm.declare_entry("values", "", Patterns::Anything(),
                    "The swept entry's values, separated by commas (by semicolons when a value holds commas).");
  prm.declare_entry("against", "", Patterns::Anything(),
                    "The entry whose value (a number) is the abscissa of the summary plots; empty: the swept entry.");
  prm.declare_entry("engines", "", Patterns::Anything(),
                    "Engines every case runs (dem, continuum, material-point); empty: each case's own.");
  prm.declare_entry("overrides", "", Patterns::Anything(),
                    "Parameter files (relative to the study file's folder, separated by commas) included into every "
                    "case after its own text, e.g. a loading program for specimens prepared without one.");
  prm.declare_entry("output directory", "results/study", Patterns::Anything(),
                    "Where the cases' folders (cases/<name>) and the report go, relative to the working directory.");
  prm.leave_subsection();
}

/// "a, b" or, when the text holds a semicolon, "a; b": the trimmed non-empty items.
std::vector<std::string> split_values(const std::string &text)
{
  const char separator = text.find(';') != std::string::npos ? ';' : ',';
  std::vector<std::string> items;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, separator);) {
    const auto begin = item.find_first_not_of(" \t"), end = item.find_last_not_of(" \t");
    if (begin != std::string::npos)
      items.push_back(item.substr(begin, end - begin + 1));
  }
  return items;
}

/// A value as a folder name: letters, digits, '.', '-' and '_'; anything else as '_'.
std::string folder_name(const std::string &text)
{
  std::string s = text;
  for (char &c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_')
      c = '_';
  return s;
}

/// The overrides of entry `entry` ('a/b/name') as .prm lines.
std::string set_line(const std::string &entry, const std::string &value)
{
  std::vector<std::string> names;
  std::stringstream ss(entry);
  for (std::string name; std::getline(ss, name, '/');)
    names.push_back(name);
  std::string open, close;
  for (std::size_t k = 0; k + 1 < names.size(); ++k) {
    open += std::string(2 * k, ' ') + "subsection " + names[k] + "\n";
    close = std::string(2 * k, ' ') + "end\n" + close;
  }
  return open + std::string(2 * (names.size() - 1), ' ') + "set " + names.back() + " = " + value + "\n" + close;
}

/// The text of a study's case: the source included, then the study's overrides.
std::string case_text(const Study &s, const StudyCase &c, const std::string &swept_value)
{
  std::string text = "# Written by `geocomp study " + s.file + "`: the case " + c.source +
                     "\n# with the study's overrides. `geocomp pair` runs it alone into this folder.\n" +
                     "include " + c.source + "\n";
  for (const auto &file : s.overrides)
    text += "include " + file + "\n";
  if (!swept_value.empty())
    text += set_line(s.parameters.swept_entry, swept_value);
  if (!s.parameters.engines.empty()) {
    std::string engines;
    for (const auto &e : s.parameters.engines)
      engines += (engines.empty() ? "" : ", ") + e;
    text += "set engines = " + engines + "\n";
  }
  return text + "subsection output\n  set directory = " + c.folder + "\nend\n";
}

/// The case a study makes from `source`: named, written nowhere yet, parsed, its abscissa read.
StudyCase make_case(const Study &s, const std::string &source, const std::string &name,
                    const std::string &swept_value, const std::string &parameter)
{
  StudyCase c;
  c.name = name;
  c.source = source;
  c.folder = (fs::path(s.output) / "cases" / name).string();
  c.file = (fs::path(c.folder) / (name + ".prm")).string();
  const std::string text = case_text(s, c, swept_value);
  std::string x;
  try {
    c.description = parse_case(text, c.file);
  } catch (const CaseError &e) {
    throw CaseError(s.file, e.parameter == "engines" ? "study/engines" : parameter,
                    "case '" + name + "' (from " + source + "): " + e.what());
  }
  try {
    x = case_entry_value(text, c.file, s.parameters.against);
  } catch (const CaseError &e) {
    throw CaseError(s.file, "study/against", "case '" + name + "' (from " + source + "): " + e.what());
  }
  c.label = swept_value.empty() ? s.parameters.against + " = " + x : s.parameters.swept_entry + " = " + swept_value;
  std::size_t used = 0;
  try {
    c.x = std::stod(x, &used);
  } catch (const std::exception &) {
    used = 0;
  }
  if (used == 0 || x.find_first_not_of(" \t", used) != std::string::npos || !std::isfinite(c.x))
    throw CaseError(s.file, "study/against",
                    "'" + s.parameters.against + "' of case '" + name + "' is '" + x + "': expected an entry with a number");
  return c;
}

/// A case path of the study file, relative to its folder; refused when it is no file.
std::string source_path(const Study &s, const std::string &given, const std::string &parameter)
{
  const fs::path p = fs::path(given).is_absolute() ? fs::path(given) : fs::path(s.file).parent_path() / given;
  std::error_code ec;
  if (!fs::is_regular_file(p, ec))
    throw CaseError(s.file, parameter, "'" + given + "' (" + p.string() + ") is not a file");
  if (p.extension() != ".prm") // the study's case files include it, in .prm syntax
    throw CaseError(s.file, parameter, "'" + given + "': expected a .prm file");
  return fs::weakly_canonical(p).string();
}

void make_cases(Study &s)
{
  const StudyParameters &p = s.parameters;
  for (const auto &given : p.overrides)
    s.overrides.push_back(source_path(s, given, "study/overrides"));
  std::set<std::string> names;
  auto add = [&](StudyCase c) {
    if (!names.insert(c.name).second)
      throw CaseError(s.file, p.cases.empty() ? "study/values" : "study/cases",
                      "two cases named '" + c.name + "': expected distinct case file names or values");
    s.cases.push_back(std::move(c));
  };
  if (!p.cases.empty()) {
    for (const auto &given : p.cases) {
      const std::string source = source_path(s, given, "study/cases");
      add(make_case(s, source, fs::path(source).stem().string(), "", "study/cases"));
    }
    // Cases of a list are labelled by their abscissa, or by their name where two share it.
    for (StudyCase &c : s.cases)
      if (std::count_if(s.cases.begin(), s.cases.end(), [&](const StudyCase &o) { return o.x == c.x; }) > 1)
        c.label = c.name + " (" + c.label + ")";
    return;
  }
  const std::string base = source_path(s, p.base_case, "study/base case");
  try {
    case_entry_value(read_parameter_file(base, ".prm or .json case file"), base, p.swept_entry);
  } catch (const CaseError &e) {
    throw CaseError(s.file, "study/swept entry", e.what());
  }
  for (const auto &value : p.values)
    add(make_case(s, base, fs::path(base).stem().string() + "_" + folder_name(value), value, "study/values"));
}

/// The study's own entries, with the checks between them.
StudyParameters parse_study_parameters(ParameterHandler &prm, const std::string &path)
{
  const sections::Reader reader{path};
  StudyParameters p;
  p.title = prm.get("title");
  sections::read_section(prm, reader, "study", p);
  prm.enter_subsection("study");
  p.values = split_values(prm.get("values"));
  prm.leave_subsection();
  const bool swept = !p.base_case.empty() || !p.swept_entry.empty() || !p.values.empty();
  if (p.cases.empty() == !swept)
    reader.fail("study/cases", "expected either 'cases' or 'base case' with 'swept entry' and 'values'");
  if (swept && (p.base_case.empty() || p.swept_entry.empty() || p.values.empty()))
    reader.fail(p.base_case.empty() ? "study/base case" : p.swept_entry.empty() ? "study/swept entry" : "study/values",
                "a swept study needs 'base case', 'swept entry' and at least one of 'values'");
  if (p.against.empty() && !swept)
    reader.fail("study/against", "expected the entry the summary plots are drawn against, e.g. contact/particle friction");
  if (p.against.empty())
    p.against = p.swept_entry;
  if (p.output_directory.empty())
    reader.fail("study/output directory", "expected a folder");
  return p;
}
} // namespace

Study read_study(const std::string &path)
{
  if (path.size() < 4 || path.substr(path.size() - 4) != ".prm")
    throw CaseError(path, "(file)", "expected a study file ending in .prm");
  ParameterHandler prm;
  declare_study(prm);
  parse_parameter_text(prm, read_parameter_file(path, ".prm study file"), path);
  Study s;
  s.file = path;
  s.parameters = parse_study_parameters(prm, path);
  s.output = fs::absolute(s.parameters.output_directory).lexically_normal().string();
  make_cases(s);
  return s;
}

std::string describe_study_parameters()
{
  ParameterHandler prm;
  declare_study(prm);
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::OutputStyle(ParameterHandler::OutputStyle::PRM |
                                                          ParameterHandler::OutputStyle::KeepDeclarationOrder));
  return out.str();
}

} // namespace geocomp
