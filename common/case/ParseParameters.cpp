// See ParseParameters.h: parameter files read, deal.II's parse errors turned into CaseErrors.
#include "common/case/ParseParameters.h"

#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace geocomp {

namespace {

/// deal.II's exception text carries file/line of the library; keep the part for users.
std::string user_message(const std::string &what, const std::string &path)
{
  std::string s = what;
  const auto info = s.find("Additional information:");
  if (info != std::string::npos)
    s = s.substr(info + 23);
  const auto trace = s.find("Stacktrace:");
  if (trace != std::string::npos)
    s = s.substr(0, trace);
  std::string out;
  bool space = false;
  for (char c : s) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      space = !out.empty();
      continue;
    }
    if (space)
      out += ' ';
    space = false;
    out += c;
  }
  while (!out.empty() && (out.back() == '-' || out.back() == ' '))
    out.pop_back();
  // The file is named once, by CaseError; keep only the line number.
  for (const std::string &file : {" of file <" + path + ">: ", " of file <" + path + ": "}) {
    const auto at = out.find(file);
    if (at != std::string::npos)
      out.replace(at, file.size(), ": ");
  }
  static const std::regex where(R"(Line <([0-9]+)>: )");
  return std::regex_replace(out, where, "line $1: ");
}

/// "section/subsection/" enclosing a 1-based line of a .prm text.
std::string section_path_at(const std::string &text, int line)
{
  std::vector<std::string> stack;
  std::istringstream in(text);
  std::string l;
  static const std::regex sub(R"(^\s*subsection\s+(.*?)\s*$)"), end(R"(^\s*end\s*$)");
  for (int n = 1; n < line && std::getline(in, l); ++n) {
    const auto hash = l.find('#');
    if (hash != std::string::npos)
      l = l.substr(0, hash);
    std::smatch m;
    if (std::regex_match(l, m, sub))
      stack.push_back(m[1]);
    else if (std::regex_match(l, end) && !stack.empty())
      stack.pop_back();
  }
  std::string out;
  for (const auto &s : stack)
    out += s + "/";
  return out;
}

/// The parameter a ParameterHandler message is about, with its section path when the
/// message gives a line; "(file)" when it names none.
std::string parameter_in(const std::string &message, const std::string &text)
{
  static const std::regex line(R"([Ll]ine <?([0-9]+)>?:)");
  static const std::regex named(R"(entry named (.+?) does not match)");
  static const std::regex declared(R"(entry <([^>]*)>|parameter <([^>]*)>)");
  static const std::regex subsection(R"(subsection <([^>]*)>|No entry with name <([^>]*)>|no such subsection to be entered: ([^ .]+))");
  std::smatch m, l;
  const int at = std::regex_search(message, l, line) ? std::stoi(l[1]) : -1;
  const std::string prefix = at > 0 ? section_path_at(text, at) : "";
  if (std::regex_search(message, m, named))
    return prefix + m[1].str();
  if (std::regex_search(message, m, declared))
    return prefix + (m[1].matched ? m[1].str() : m[2].str());
  if (std::regex_search(message, m, subsection))
    return prefix + (m[1].matched ? m[1].str() : m[2].matched ? m[2].str() : m[3].str());
  return "(file)";
}

} // namespace

CaseError parameter_error(const dealii::ExceptionBase &e, const std::string &text, const std::string &path)
{
  const std::string msg = user_message(e.what(), path);
  return CaseError(path, parameter_in(msg, text), msg);
}

std::string read_parameter_file(const std::string &path, const std::string &kind)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw CaseError(path, "(file)", "cannot be read: expected a readable " + kind);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void parse_parameter_text(dealii::ParameterHandler &prm, const std::string &text, const std::string &path)
{
  try {
    std::istringstream s(text);
    prm.parse_input(s, path, "", false);
  } catch (const dealii::ExceptionBase &e) {
    throw parameter_error(e, text, path);
  } catch (const std::exception &e) {
    throw CaseError(path, "(file)", user_message(e.what(), path));
  }
}

} // namespace geocomp
