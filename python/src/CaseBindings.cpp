// geocomp.Case, geocomp.read_case, geocomp.check and geocomp.CaseError: a case file read,
// changed and validated by the command line's own readers (see PyCase in Bindings.h).
#include "Bindings.h"

#include "compare/cli/CaseValidation.h"
#include "compare/cli/Engines.h"
#include "common/case/CaseError.h"

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include <algorithm>
#include <sstream>

namespace geocomp::python {

namespace py = pybind11;

namespace {
/// "a/b/c" as its parts; refuses empty parts (a path names one entry).
std::vector<std::string> split_path(const std::string &path)
{
  std::vector<std::string> parts;
  std::stringstream in(path);
  for (std::string part; std::getline(in, part, '/');)
    parts.push_back(part);
  if (parts.empty() || path.back() == '/' ||
      std::any_of(parts.begin(), parts.end(), [](const std::string &p) { return p.empty(); }))
    throw py::value_error("entry path '" + path + "': expected 'section/entry' (e.g. 'continuum/friction angle')");
  return parts;
}

bool is_json(const std::string &file) { return file.size() >= 5 && file.substr(file.size() - 5) == ".json"; }

/// A .prm's text with `path = value` set: a block appended at the end, read after (and so
/// over) the entry's earlier value, the way a later `set` of deal.II's parameter files wins.
std::string prm_with(const std::string &text, const std::vector<std::string> &parts, const std::string &value)
{
  std::string out = text;
  if (!out.empty() && out.back() != '\n')
    out += '\n';
  out += "# set from Python (geocomp.Case.set)\n";
  std::string indent;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k, indent += "  ")
    out += indent + "subsection " + parts[k] + "\n";
  out += indent + "set " + parts.back() + " = " + value + "\n";
  for (std::size_t k = parts.size() - 1; k-- > 0;)
    out += std::string(2 * k, ' ') + "end\n";
  return out;
}

/// A JSON case's text with `path = value` set as a string member of nested objects.
std::string json_with(const std::string &text, const std::string &file, const std::vector<std::string> &parts,
                      const std::string &value)
{
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception &e) {
    throw CaseError(file, "(file)", std::string("not valid JSON: ") + e.what());
  }
  nlohmann::ordered_json *node = &doc;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    node = &(*node)[parts[k]];
    if (!node->is_object() && !node->is_null())
      throw CaseError(file, parts[k], "is a value, not a section: cannot set an entry inside it");
  }
  (*node)[parts.back()] = value;
  return doc.dump(2) + "\n";
}
} // namespace

PyCase PyCase::read(const std::string &path) { return PyCase(read_case(path)); }

PyCase PyCase::checked(const std::string &path) { return PyCase(cli::read_valid_case(path)); }

PyCase PyCase::parse(const std::string &text, const std::string &name) { return PyCase(parse_case(text, name)); }

std::string PyCase::parameters() const { return parameters_text(description_); }

std::string PyCase::get(const std::string &path) const
{
  split_path(path);
  std::istringstream lines(parameters());
  const std::string key = path + " = ";
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(key, 0) == 0)
      return line.substr(key.size());
  throw py::key_error("no entry '" + path + "' in " + file() +
                      " (entries are 'section/entry' as in Case.parameters(), e.g. 'continuum/friction angle')");
}

void PyCase::set(const std::string &path, const std::string &value)
{
  const std::vector<std::string> parts = split_path(path);
  if (value.find_first_of("\n\r") != std::string::npos)
    throw py::value_error("value for '" + path + "': expected one line");
  const std::string text =
    is_json(file()) ? json_with(this->text(), file(), parts, value) : prm_with(this->text(), parts, value);
  description_ = parse_case(text, file()); // CaseError: *this unchanged
}

std::string entry_text(const py::handle &value)
{
  if (py::isinstance<py::bool_>(value))
    return value.cast<bool>() ? "true" : "false";
  return py::isinstance<py::str>(value) ? value.cast<std::string>() : std::string(py::str(value));
}

void bind_case(py::module_ &m)
{
  static py::exception<CaseError> case_error(m, "CaseError", PyExc_ValueError);
  case_error.doc() = "Bad input in a case file: the message names the file, the parameter and what was expected, "
                     "word for word as `geocomp check` prints it after 'error: '. Attributes: file, parameter.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const CaseError &e) {
      py::object error = py::handle(case_error.ptr())(e.what());
      error.attr("file") = e.file;
      error.attr("parameter") = e.parameter;
      PyErr_SetObject(case_error.ptr(), error.ptr());
    }
  });

  const auto set_entry = [](PyCase &c, const std::string &path, const py::object &value) {
    c.set(path, entry_text(value));
  };
  py::class_<PyCase>(m, "Case", R"doc(A case file (.prm or .json) as the command line reads it.

Read with geocomp.read_case(path) (entry by entry, as every command does) or
geocomp.check(path) (also each engine's own checks, as `geocomp check` does). Entries are
named by their path, 'section/entry' ('continuum/friction angle', 'program/stage 1/mode').
Values are case-file text in SI units; program stresses and rates are tension positive,
entries named 'pressure' are magnitudes, positive in compression.)doc")
    .def_static("read", &PyCase::read, py::arg("path"), "Reads a case file; raises CaseError.")
    .def_static("parse", &PyCase::parse, py::arg("text"), py::arg("name"),
                "Reads a case from its text; `name` ends in .prm or .json (the syntax) and names it in messages.")
    .def_property_readonly("file", &PyCase::file, "The case file's path as given (messages name it).")
    .def_property_readonly("text", &PyCase::text, "The case text, with the entries set from Python.")
    .def_property_readonly("title", [](const PyCase &c) { return c.description().title; })
    .def_property_readonly("engines", [](const PyCase &c) { return c.description().engines; },
                           "The engines the case names, e.g. ['dem', 'continuum', 'material-point'].")
    .def_property_readonly("output_directory", [](const PyCase &c) { return c.description().output.directory; })
    .def("get", &PyCase::get, py::arg("path"),
         "The entry's value as parsed (canonical text: numbers to 17 digits, angles as written). KeyError if none.")
    .def("set", set_entry, py::arg("path"), py::arg("value"),
         "Sets an entry (case-file syntax; numbers may be given as Python numbers) and re-reads the case. "
         "Raises CaseError, leaving the case unchanged, when the value is refused.")
    .def("__getitem__", &PyCase::get)
    .def("__setitem__", set_entry)
    .def("parameters", &PyCase::parameters, "Every entry as 'section/entry = value' lines (results' /meta/parameters).")
    .def(
      "validate",
      [](const PyCase &c, const std::vector<std::string> &also) { cli::validate_engines(c.description(), also); },
      py::arg("also") = std::vector<std::string>{},
      "Each engine's checks for every engine the case names and each of `also` (compare/cli/CaseValidation.h): "
      "raises CaseError with the message `geocomp check` prints.")
    .def("copy", [](const PyCase &c) { return PyCase(c); })
    .def("__repr__", [](const PyCase &c) { return "<geocomp.Case " + c.file() + ">"; });

  m.def("read_case", &PyCase::read, py::arg("path"),
        "Reads a case file (.prm or .json) as the command line does; raises CaseError naming the file, "
        "the parameter and what was expected.");
  m.def(
    "check",
    &PyCase::checked, py::arg("path"),
    "`geocomp check` in-process: reads the case and runs every named engine's checks; returns the Case or "
    "raises CaseError with the same message.");
}

} // namespace geocomp::python
