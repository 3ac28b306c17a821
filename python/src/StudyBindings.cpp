// geocomp.read_study, geocomp.Study and the compiled half of geocomp.study: a study file
// (compare/case/StudyFile.h) read and checked by the command line's own reader, and run in
// this process by the command line's own run_study() (compare/cli/StudyRun.h) - the case
// files, `pair` on every case, <output>/report with study.json. The pure-Python half
// (geocomp/studies.py) lays the result out as numpy arrays.
#include "Bindings.h"

#include "common/ResponseFile.h"
#include "compare/cli/Engines.h"
#include "compare/cli/Pair.h"
#include "compare/cli/StudyRun.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>

namespace geocomp::python {

namespace py = pybind11;
namespace fs = std::filesystem;

namespace {
/// The engine named `label` in reports ("material point" -> "material-point").
std::string engine_named(const std::string &label)
{
  for (const auto &engine : cli::engine_names())
    if (cli::engine_label(engine) == label)
      return engine;
  return label;
}

/// One case's results as the study left them: the Responses of its results files, and the
/// summary study.json gives of each (compare::study_summary on the report's curve).
py::dict case_result(const StudyCase &c, const compare::StudyReportCase &rc, int code)
{
  py::dict responses, summaries;
  for (const auto &run : rc.runs) {
    const std::string engine = engine_named(run.engine);
    Response r = read_response(fs::path(c.folder) / cli::results_file(engine));
    const std::string status = completion_status(r, c.description.program);
    responses[py::str(engine)] = PyResponse(std::move(r), status);
    const compare::StudySummary s = compare::study_summary(run.response, rc.kind, rc.axial);
    py::dict summary;
    for (const auto &[key, value] : compare::study_summary_entries(s))
      summary[py::str(key)] = value;
    summary["metrics"] = metrics_dict(s.metrics);
    summary["error"] = s.error;
    summaries[py::str(engine)] = summary;
  }
  py::dict d;
  d["name"] = c.name;
  d["label"] = c.label;
  d["x"] = c.x;
  d["folder"] = c.folder;
  d["file"] = c.file;
  d["exit_code"] = code;
  d["status"] = rc.failure.empty() ? std::string("complete") : "failed: " + rc.failure;
  d["responses"] = responses;
  d["summaries"] = summaries;
  return d;
}

/// run_study() with the progress reported to Python; once the callback has raised, every
/// later case stops at its first sample and the exception is raised again at the end.
py::dict run(const Study &s, bool force, const std::optional<py::function> &progress)
{
  ensure_mpi();
  cli::RunSettings settings;
  settings.reuse = !force;
  settings.command_line = "python3: geocomp.study(" + s.file + ")";
  settings.signal_checkpoints = false;
  std::optional<py::error_already_set> raised;
  cli::CaseProgress report;
  if (progress)
    report = [&](std::size_t k, const std::string &engine, const RunProgress &p) {
      py::gil_scoped_acquire gil;
      if (raised)
        throw CallbackRaised();
      py::dict state = progress_dict(p);
      state["engine"] = engine;
      state["case"] = s.cases[k].name;
      state["case_index"] = k;
      state["case_count"] = s.cases.size();
      call_progress(*progress, state, raised);
    };
  cli::StudyOutcome out;
  {
    py::gil_scoped_release released;
    out = cli::run_study(s, settings, report);
  }
  if (raised)
    throw std::move(*raised);
  py::list cases;
  for (std::size_t k = 0; k < s.cases.size(); ++k)
    cases.append(case_result(s.cases[k], out.report.cases[k], out.codes[k]));
  py::dict d;
  d["cases"] = cases;
  d["report"] = (out.written.dir / "index.html").string();
  d["json"] = (out.written.dir / "study.json").string();
  d["plots_made"] = out.written.plots_made;
  d["complete"] = out.complete();
  return d;
}
} // namespace

void bind_study(py::module_ &m)
{
  py::class_<StudyCase>(m, "StudyCase", "One case of a study, as the study writes and runs it.")
    .def_property_readonly("name", [](const StudyCase &c) { return c.name; },
                           "Folder and file stem, unique in the study.")
    .def_property_readonly("label", [](const StudyCase &c) { return c.label; }, "The legend: '<entry> = <value>'.")
    .def_property_readonly("x", [](const StudyCase &c) { return c.x; }, "The value of the study's `against` entry.")
    .def_property_readonly("source", [](const StudyCase &c) { return c.source; }, "The case file it comes from.")
    .def_property_readonly("folder", [](const StudyCase &c) { return c.folder; },
                           "<output>/cases/<name>: its results.")
    .def_property_readonly("file", [](const StudyCase &c) { return c.file; }, "<folder>/<name>.prm, written by the run.")
    .def_property_readonly("case", [](const StudyCase &c) { return PyCase::of(c.description); },
                           "The case as a geocomp.Case (its text is the file the run writes).")
    .def("__repr__", [](const StudyCase &c) { return "<geocomp.StudyCase " + c.name + ": " + c.label + ">"; });

  py::class_<Study>(m, "Study", R"doc(A study file (docs/studies.md) read by `geocomp study`'s own reader.

Read with geocomp.read_study(path); run with geocomp.study(study). Every case it makes is
parsed and checked for its engines; nothing is written until it runs.)doc")
    .def_property_readonly("file", [](const Study &s) { return s.file; })
    .def_property_readonly("title", [](const Study &s) { return s.parameters.title; })
    .def_property_readonly("against", [](const Study &s) { return s.parameters.against; },
                           "The entry the summary is drawn against, e.g. 'contact/particle friction'.")
    .def_property_readonly("swept_entry", [](const Study &s) { return s.parameters.swept_entry; },
                           "The entry a sweep sets ('' for a list of cases).")
    .def_property_readonly("values", [](const Study &s) { return s.parameters.values; },
                           "The swept entry's values as written (empty for a list of cases).")
    .def_property_readonly("output", [](const Study &s) { return s.output; }, "The output directory (absolute).")
    .def_property_readonly("overrides", [](const Study &s) { return s.overrides; })
    .def_property_readonly("cases", [](const Study &s) { return s.cases; }, "The StudyCases, in the file's order.")
    .def_property_readonly(
      "x",
      [](const Study &s) {
        py::array_t<double> x(static_cast<py::ssize_t>(s.cases.size()));
        for (std::size_t k = 0; k < s.cases.size(); ++k)
          x.mutable_at(k) = s.cases[k].x;
        return x;
      },
      "The cases' values of `against` (numpy array).")
    .def("__len__", [](const Study &s) { return s.cases.size(); })
    .def("__repr__", [](const Study &s) {
      return "<geocomp.Study " + s.file + ": " + std::to_string(s.cases.size()) + " case(s) against " +
             s.parameters.against + ">";
    });

  m.def("read_study", &cli::read_valid_study, py::arg("path"),
        "Reads a study file and every case it makes as `geocomp study --check` does; raises CaseError naming "
        "the study file and its parameter (study/values, study/cases, ...).");
  m.def("_run_study", &run, py::arg("study"), py::arg("force") = false, py::arg("progress") = py::none(),
        "geocomp.study's compiled half: run_study() of the command line; a dict that geocomp.study lays out.");
}

} // namespace geocomp::python
