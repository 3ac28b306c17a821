// See ParseParameters.h: parameter files read, deal.II's parse errors turned into CaseErrors.
#include "common/case/ParseParameters.h"

#include "common/case/InputFile.h"
#include "common/case/InputLimits.h"
#include "common/case/TextEncoding.h"

#include <cctype>
#include <sstream>

namespace geocomp {

namespace {

std::string trimmed(const std::string &s)
{
  const auto b = s.find_first_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

/// The number in deal.II's "Line <N> of file <...>", or 0.
unsigned int line_in(const std::string &what)
{
  const auto at = what.find("Line <");
  if (at == std::string::npos)
    return 0;
  unsigned long n = 0;
  for (std::size_t k = at + 6; k < what.size() && k < at + 16 && std::isdigit(static_cast<unsigned char>(what[k])); ++k)
    n = 10 * n + static_cast<unsigned long>(what[k] - '0');
  return static_cast<unsigned int>(n);
}

/// deal.II's exception text carries file/line of the library and a stack trace; keep the
/// part for users, on one line, with the line of the file the user wrote.
std::string user_message(const std::string &what, const ParameterText &text, const std::string &path)
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
  // "Line <N> of file <path>: " -> "line N: " (or "line M of 'included': "): the file is
  // named once, by CaseError.
  const unsigned int line = line_in(out);
  if (line > 0) {
    const std::string from = "Line <" + std::to_string(line) + ">";
    const auto at = out.find(from);
    auto end = out.find(": ", at);
    for (const std::string &file : {" of file <" + path + ">: ", " of file <" + path + ": "})
      if (out.compare(at + from.size(), file.size(), file) == 0)
        end = at + from.size() + file.size() - 2;
    if (end != std::string::npos)
      out.replace(at, end - at, text.where(line));
  }
  return out;
}

/// The text between `open` and the next '>' after it, or "" (no regular expression: the
/// message quotes the user's value, up to input_limits::max_line_bytes of it).
std::string quoted_after(const std::string &message, const std::string &open)
{
  const auto at = message.find(open);
  if (at == std::string::npos)
    return "";
  const auto close = message.find('>', at + open.size());
  return close == std::string::npos ? "" : message.substr(at + open.size(), close - at - open.size());
}

/// The parameter a ParameterHandler message is about, with its section path: read from
/// the statement at the line the message gives (a `set` names its entry, a `subsection`
/// its name), else from the entry the message quotes; "(file)" when it names none.
std::string parameter_in(const std::string &what, const ParameterText &text)
{
  const unsigned int line = line_in(what);
  if (line > 0) {
    const std::string s = text.statement_at(line);
    const auto eq = s.find('=');
    if ((s.rfind("set ", 0) == 0 || s.rfind("SET ", 0) == 0) && eq != std::string::npos)
      return text.section_at(line) + trimmed(s.substr(4, eq - 4));
    if (s.rfind("subsection ", 0) == 0 || s.rfind("SUBSECTION ", 0) == 0)
      return text.section_at(line) + trimmed(s.substr(11));
    return "(file)";
  }
  for (const char *open : {"entry <", "parameter <", "No entry with name <", "subsection <"}) {
    const std::string name = quoted_after(what, open);
    if (!name.empty())
      return name;
  }
  return "(file)";
}

} // namespace

CaseError parameter_error(const dealii::ExceptionBase &e, const ParameterText &text, const std::string &path)
{
  return CaseError(path, parameter_in(e.what(), text), user_message(e.what(), text, path));
}

std::string read_parameter_file(const std::string &path, const std::string &kind)
{
  std::string text = read_input_file(path, kind, input_limits::max_file_bytes);
  check_utf8_text(text, path);
  return text;
}

void parse_parameter_text(dealii::ParameterHandler &prm, const std::string &text, const std::string &path)
{
  parse_parameter_text(prm, expand_parameter_text(text, path), path);
}

void parse_parameter_text(dealii::ParameterHandler &prm, const ParameterText &text, const std::string &path)
{
  try {
    std::istringstream s(text.text);
    prm.parse_input(s, path, "", false);
  } catch (const dealii::ExceptionBase &e) {
    throw parameter_error(e, text, path);
  } catch (const std::exception &e) {
    throw CaseError(path, "(file)", user_message(e.what(), text, path));
  }
}

} // namespace geocomp
