// Reading a case file: declare every section, parse with deal.II's ParameterHandler,
// convert to plain structs, validate, and turn every failure into one CaseError that
// names the file, the parameter and what was expected.
#include "compare/case/CaseDescription.h"
#include "common/case/CanonicalText.h"
#include "common/case/JsonCase.h"
#include "common/case/ParseParameters.h"
#include "common/case/TextEncoding.h"
#include "compare/calibrate/CalibrationSection.h"
#include "continuum/case/ContinuumSections.h"
#include "coupled/case/RveSection.h"
#include "dem/case/DemSections.h"
#include "dem/case/SpecimenRecord.h"

#include <deal.II/base/exceptions.h>

#include <nlohmann/json.hpp>

#include <cctype>
#include <sstream>

namespace geocomp {

namespace {
using namespace dealii;

void declare_all(ParameterHandler &prm, unsigned int stages)
{
  sections::declare_head(prm);
  sections::declare_dem_sections(prm);
  sections::declare_continuum(prm);
  sections::declare_dem_rve(prm);
  sections::declare_program(prm, stages);
  sections::declare_output(prm);
  sections::declare_calibration(prm);
}

/// The highest N of the `subsection stage N` entered in `program` (at most 1000).
unsigned int count_stages(const ParameterText &text)
{
  unsigned int n = 0;
  for (const ParameterText::Section &s : text.sections) {
    const ParameterText::Section &parent = text.sections[s.parent];
    if (s.parent == 0 || parent.parent != 0 || parent.name != "program" || s.name.rfind("stage ", 0) != 0)
      continue;
    const std::string number = s.name.substr(6, 4);
    if (!number.empty() &&
        std::all_of(number.begin(), number.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      n = std::max(n, std::min(1000u, static_cast<unsigned int>(std::stoul(number))));
  }
  return n;
}

/// The case text as ParameterHandler reads it: JSON turned into the equivalent .prm, includes
/// expanded (both syntaxes get the same line-based messages naming the parameter).
ParameterText case_parameter_text(const std::string &text, const std::string &path)
{
  const bool json = path.size() >= 5 && path.substr(path.size() - 5) == ".json";
  const bool prm_file = path.size() >= 4 && path.substr(path.size() - 4) == ".prm";
  if (!json && !prm_file)
    throw CaseError(path, "(file)", "expected a case file ending in .prm or .json");
  check_utf8_text(text, path);
  return expand_parameter_text(json ? json_to_prm(text, path) : text, path);
}

/// Declares every section (with the program's stages) into `prm` and parses `prm_text`;
/// returns the number of stages the text has.
unsigned int declare_and_parse(ParameterHandler &prm, const ParameterText &prm_text, const std::string &path)
{
  const unsigned int stages = count_stages(prm_text);
  if (stages > 200)
    throw CaseError(path, "program", "more than 200 stages: expected a smaller program");
  declare_all(prm, std::max(stages, 1u));
  parse_parameter_text(prm, prm_text, path);
  return stages;
}
} // namespace

CaseDescription read_case(const std::string &path)
{
  return parse_case(read_parameter_file(path, ".prm or .json case file"), path);
}

std::string case_entry_value(const std::string &text, const std::string &path, const std::string &entry)
{
  const ParameterText prm_text = case_parameter_text(text, path);
  ParameterHandler prm;
  declare_and_parse(prm, prm_text, path);
  // The declared tree as JSON (names as declared): an entry is a node with a "value".
  std::ostringstream json;
  prm.print_parameters(json, ParameterHandler::OutputStyle::JSON);
  nlohmann::json node = nlohmann::json::parse(json.str());
  std::stringstream ss(entry);
  for (std::string name; std::getline(ss, name, '/');) {
    if (!node.is_object() || !node.contains(name)) {
      node = nullptr;
      break;
    }
    node = nlohmann::json(node[name]);
  }
  if (!node.is_object() || !node.contains("value") || !node["value"].is_string())
    throw CaseError(path, entry,
                    "not an entry of a case file: expected 'section/entry' as `geocomp print-parameters` lists them");
  return node["value"].get<std::string>();
}

CaseDescription parse_case(const std::string &text, const std::string &path)
{
  CaseDescription c;
  c.file = path;
  c.text = text;
  const ParameterText prm_text = case_parameter_text(c.text, path);
  ParameterHandler prm;
  const unsigned int stages = declare_and_parse(prm, prm_text, path);
  if (stages == 0)
    throw CaseError(path, "program/stage 1",
                    "the loading program has no stage: expected 'subsection stage 1' in 'subsection program'");

  const sections::Reader reader{path};
  try {
    CaseHead::visit(static_cast<CaseHead &>(c), sections::ReadEntries{prm, reader, ""});
    if (c.engines.empty())
      reader.fail("engines", "expected at least one of dem, continuum, material-point, fem-dem, liggghts");
    sections::parse_dem_sections(prm, reader, c);
    c.continuum = sections::parse_continuum(prm, reader);
    c.rve = sections::parse_dem_rve(prm, reader);
    c.program = sections::parse_program(prm, stages, reader);
    c.output = sections::parse_output(prm, reader);
    c.calibration = sections::parse_calibration(prm, reader, c.continuum);
  } catch (const ExceptionBase &e) {
    throw parameter_error(e, prm_text, path);
  }
  return c;
}

namespace {
/// Walks deal.II's JSON description of the declared parameters and writes a .prm with,
/// for each entry, its help, the values it accepts and its default.
void print_tree(const nlohmann::ordered_json &tree, std::ostream &out, int depth)
{
  const std::string indent(2 * depth, ' ');
  for (const auto &[key, node] : tree.items()) {
    if (node.is_object() && node.contains("default_value")) {
      out << indent << "# " << node.value("documentation", "") << "\n"
          << indent << "# allowed: " << node.value("pattern_description", "") << "\n"
          << indent << "set " << key << " = " << node.value("default_value", "") << "\n\n";
    }
  }
  for (const auto &[key, node] : tree.items()) {
    if (node.is_object() && !node.contains("default_value") && !node.empty()) {
      out << indent << "subsection " << key << "\n";
      print_tree(node, out, depth + 1);
      out << indent << "end\n\n";
    }
  }
}
} // namespace

std::string describe_parameters()
{
  ParameterHandler prm;
  declare_all(prm, 1);
  std::ostringstream json;
  prm.print_parameters(json, ParameterHandler::OutputStyle(ParameterHandler::OutputStyle::JSON |
                                                           ParameterHandler::OutputStyle::KeepDeclarationOrder));
  const auto tree = nlohmann::ordered_json::parse(json.str());
  std::ostringstream out;
  out << "# geocomp case file parameters: every entry with its help, allowed values and default.\n"
      << "# SI units. Program stresses and rates are tension positive; 'pressure' entries are\n"
      << "# magnitudes, positive in compression. A program has 'subsection stage 1', 'stage 2', ...\n"
      << "# each with the entries shown for stage 1.\n\n";
  print_tree(tree, out, 0);
  return out.str();
}

std::string parameters_text(const CaseDescription &c)
{
  CanonicalText head("");
  CaseHead::visit(c, head);
  CanonicalText continuum("continuum");
  continuum::ContinuumParameters::visit(c.continuum, continuum);
  continuum.section("continuum/nikolaevsky");
  continuum::NikolaevskyParameters::visit(c.continuum.nikolaevsky, continuum);
  continuum.section("dem rve");
  coupled::RveCaseParameters::visit(c.rve, continuum);
  CanonicalText rest("output");
  OutputParameters::visit(c.output, rest);
  rest.section("calibration");
  CalibrationParameters::visit(c.calibration, rest);
  return head.text() + dem::dem_parameters_text(c) + continuum.text() + sections::program_text(c.program) +
         rest.text();
}

} // namespace geocomp
