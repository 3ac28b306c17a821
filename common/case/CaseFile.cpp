// Reading a case file: declare every section, parse with deal.II's ParameterHandler,
// convert to plain structs, validate, and turn every failure into one CaseError that
// names the file, the parameter and what was expected.
#include "common/case/CaseParameters.h"
#include "common/case/ParseParameters.h"
#include "common/case/Sections.h"

#include <deal.II/base/exceptions.h>

#include <boost/property_tree/json_parser.hpp>

#include <regex>
#include <set>
#include <sstream>

namespace geocomp {

namespace {
using namespace dealii;

void declare_top(ParameterHandler &prm)
{
  prm.declare_entry("title", "", Patterns::Anything(), "A title for reports.");
  prm.declare_entry("engines", "dem, continuum", Patterns::MultipleSelection("dem|continuum|material-point"),
                    "Engines that run the program: 'dem', 'continuum' (deal.II cube), 'material-point' "
                    "(the continuum model at one point).");
  prm.declare_entry("seed", "1", Patterns::Integer(0), "Random seed: the same seed gives the same specimen and curves.");
}

void declare_all(ParameterHandler &prm, unsigned int stages)
{
  declare_top(prm);
  sections::declare_specimen(prm);
  sections::declare_contact(prm);
  sections::declare_contact_parts(prm);
  sections::declare_clumps(prm);
  sections::declare_dem(prm);
  sections::declare_continuum(prm);
  sections::declare_program(prm, stages);
  sections::declare_output(prm);
  sections::declare_calibration(prm);
}

unsigned int count_stages(const std::string &text)
{
  const std::regex stage(R"(subsection\s+stage\s+([0-9]+))");
  unsigned int n = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), stage); it != std::sregex_iterator(); ++it)
    n = std::max(n, static_cast<unsigned int>(std::min(1000ul, std::stoul((*it)[1].str().substr(0, 6)))));
  return n;
}

void tree_to_prm(const boost::property_tree::ptree &tree, std::ostream &out, const std::string &path)
{
  for (const auto &[key, node] : tree) {
    if (key.empty())
      throw CaseError(path, "(file)", "JSON arrays are not case-file syntax: expected objects and values");
    if (key.find_first_of("\n#") != std::string::npos)
      throw CaseError(path, "(file)", "a JSON key contains a newline or '#'");
    if (node.empty()) {
      const std::string v = node.data();
      if (v.find('\n') != std::string::npos)
        throw CaseError(path, key, "a value must be on one line");
      out << "set " << key << " = " << v << "\n";
    } else {
      out << "subsection " << key << "\n";
      tree_to_prm(node, out, path);
      out << "end\n";
    }
  }
}

std::string json_to_prm(const std::string &text, const std::string &path)
{
  boost::property_tree::ptree tree;
  try {
    std::istringstream in(text);
    boost::property_tree::read_json(in, tree);
  } catch (const boost::property_tree::json_parser_error &e) {
    throw CaseError(path, "(file)", "not valid JSON at line " + std::to_string(e.line()) + ": " + e.message());
  }
  std::ostringstream out;
  tree_to_prm(tree, out, path);
  return out.str();
}
} // namespace

CaseDescription read_case(const std::string &path)
{
  return parse_case(read_parameter_file(path, ".prm or .json case file"), path);
}

CaseDescription parse_case(const std::string &text, const std::string &path)
{
  CaseDescription c;
  c.file = path;
  c.text = text;
  const bool json = path.size() >= 5 && path.substr(path.size() - 5) == ".json";
  const bool prm_file = path.size() >= 4 && path.substr(path.size() - 4) == ".prm";
  if (!json && !prm_file)
    throw CaseError(path, "(file)", "expected a case file ending in .prm or .json");
  if (c.text.find('\0') != std::string::npos)
    throw CaseError(path, "(file)", "contains a NUL byte: expected a text case file");

  // JSON is read as a tree and handed to ParameterHandler as the equivalent .prm, so
  // both syntaxes get the same line-based messages naming the parameter.
  std::string prm_text = c.text;
  if (json)
    prm_text = json_to_prm(c.text, path);

  const unsigned int stages = count_stages(prm_text);
  if (stages > 200)
    throw CaseError(path, "program", "more than 200 stages: expected a smaller program");

  ParameterHandler prm;
  declare_all(prm, std::max(stages, 1u));
  parse_parameter_text(prm, prm_text, path);
  if (stages == 0)
    throw CaseError(path, "program/stage 1",
                    "the loading program has no stage: expected 'subsection stage 1' in 'subsection program'");

  const sections::Reader reader{path};
  try {
    c.title = prm.get("title");
    c.engines = Utilities::split_string_list(prm.get("engines"));
    c.seed = static_cast<unsigned long long>(prm.get_integer("seed"));
    if (c.engines.empty())
      reader.fail("engines", "expected at least one of dem, continuum, material-point");
    c.specimen = sections::parse_specimen(prm, reader);
    c.contact = sections::parse_contact(prm, reader);
    sections::parse_contact_parts(prm, reader, c.contact);
    c.clumps = sections::parse_clumps(prm, reader);
    c.dem = sections::parse_dem(prm, reader);
    c.continuum = sections::parse_continuum(prm, reader);
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
void print_tree(const boost::property_tree::ptree &tree, std::ostream &out, int depth)
{
  const std::string indent(2 * depth, ' ');
  for (const auto &[key, node] : tree) {
    if (node.get_child_optional("default_value")) {
      out << indent << "# " << node.get<std::string>("documentation", "") << "\n"
          << indent << "# allowed: " << node.get<std::string>("pattern_description", "") << "\n"
          << indent << "set " << key << " = " << node.get<std::string>("default_value", "") << "\n\n";
    }
  }
  for (const auto &[key, node] : tree) {
    if (!node.get_child_optional("default_value") && !node.empty()) {
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
  boost::property_tree::ptree tree;
  std::istringstream in(json.str());
  boost::property_tree::read_json(in, tree);
  std::ostringstream out;
  out << "# geocomp case file parameters: every entry with its help, allowed values and default.\n"
      << "# SI units. Program stresses and rates are tension positive; 'pressure' entries are\n"
      << "# magnitudes, positive in compression. A program has 'subsection stage 1', 'stage 2', ...\n"
      << "# each with the entries shown for stage 1.\n\n";
  print_tree(tree, out, 0);
  return out.str();
}

} // namespace geocomp
