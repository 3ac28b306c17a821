// geocomp.run and geocomp.material_point: an engine of a case played through the case's
// loading program in this process, the way `geocomp <engine>` plays it (make_engine() of
// compare/cli/Engines.h, then ProgramRunner), with the progress reported to Python;
// geocomp.pair: the command line's own `pair` (compare/cli/Pair.h) - results files, report.
#include "Bindings.h"

#include "common/ProgramRunner.h"
#include "compare/Report.h"
#include "compare/cli/CaseValidation.h"
#include "compare/cli/Engines.h"
#include "compare/cli/Mpi.h"
#include "compare/cli/OutputFolderLock.h"
#include "compare/cli/Pair.h"

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>

namespace geocomp::python {

namespace py = pybind11;

void ensure_mpi()
{
  static bool started = false;
  if (started)
    return;
  cli::ensure_mpi();
  py::module_::import("atexit").attr("register")(py::cpp_function([] { cli::finalize_mpi(); }));
  started = true;
}

void call_progress(const py::object &callback, const py::dict &state, std::optional<py::error_already_set> &raised)
{
  try {
    callback(state);
    if (PyErr_CheckSignals() != 0)
      throw py::error_already_set();
  } catch (py::error_already_set &python_error) {
    raised.emplace(std::move(python_error));
    throw CallbackRaised();
  }
}

/// run()'s progress dict (its docstring lists the keys).
py::dict progress_dict(const RunProgress &p)
{
  py::dict d;
  d["stage"] = p.stage;
  d["stage_count"] = p.stage_count;
  d["branch"] = p.branch;
  d["time"] = p.time;
  d["stage_fraction"] = p.stage_fraction;
  return d;
}

namespace {
/// Raises geocomp.RunError(message) with the samples recorded so far as its `response`.
[[noreturn]] void raise_run_error(const py::object &type, const std::string &message, PyResponse partial)
{
  py::object error = type(message);
  error.attr("response") = py::cast(std::move(partial));
  PyErr_SetObject(type.ptr(), error.ptr());
  throw py::error_already_set();
}

PyResponse run(const PyCase &c, const std::string &engine, const std::optional<std::string> &output,
               const std::optional<py::function> &progress, const py::object &run_error)
{
  const CaseDescription &d = c.description();
  const std::string dir = output.value_or(d.output.directory);
  if (engine == "continuum")
    ensure_mpi();
  std::unique_ptr<LoadingEngine> e;
  {
    py::gil_scoped_release released; // the DEM prepares its specimen here (seconds)
    e = cli::make_engine(engine, d, dir); // validates first (CaseError)
  }
  ProgramRunner runner(d.program, *e);
  std::optional<py::error_already_set> raised;
  if (progress)
    runner.on_progress([&](const RunProgress &p) {
      py::gil_scoped_acquire gil;
      call_progress(*progress, progress_dict(p), raised);
    });
  Response r;
  try {
    py::gil_scoped_release released;
    r = runner.run();
  } catch (const CallbackRaised &) {
    throw std::move(*raised);
  } catch (ProgramFailed &failure) {
    if (raised)
      throw std::move(*raised);
    raise_run_error(run_error, engine + " " + failure.status, PyResponse(std::move(failure.partial), failure.status));
  }
  const std::string status = completion_status(r, d.program);
  return PyResponse(std::move(r), status);
}
/// geocomp.pair: the command line's `pair` on `c` into `output` (the case's output folder by
/// default, locked for the run as the command line locks it), the progress of every engine
/// reported to Python (`engine` added to the dict).
py::dict pair(const PyCase &c, const std::optional<std::string> &output, bool force,
              const std::optional<py::function> &progress, const py::object &run_error)
{
  const CaseDescription &d = c.description();
  cli::validate_engines(d); // every engine's refusals before anything runs (CaseError)
  ensure_mpi();
  const std::string dir = output.value_or(d.output.directory);
  cli::RunSettings settings;
  settings.reuse = !force;
  settings.command_line = "python3: geocomp.pair(" + d.file + ")";
  settings.signal_checkpoints = false;
  std::optional<py::error_already_set> raised;
  if (progress)
    settings.progress = [&](const std::string &engine, const RunProgress &p) {
      py::gil_scoped_acquire gil;
      py::dict state = progress_dict(p);
      state["engine"] = engine;
      call_progress(*progress, state, raised);
    };
  cli::PairOutcome outcome;
  try {
    py::gil_scoped_release released;
    const auto lock = cli::lock_for_run(dir, d.file, output ? "output" : "output/directory", MPI_COMM_WORLD);
    outcome = cli::pair_case(d, dir, settings);
  } catch (const CaseError &) {
    throw;
  } catch (const std::exception &failure) {
    if (raised)
      throw std::move(*raised);
    py::object error = run_error(failure.what());
    error.attr("response") = py::none(); // the samples so far are in the engine's file
    PyErr_SetObject(run_error.ptr(), error.ptr());
    throw py::error_already_set();
  }
  py::dict responses;
  for (auto &[engine, response] : outcome.runs) {
    const std::string status = completion_status(response, d.program);
    responses[py::str(engine)] = PyResponse(std::move(response), status);
  }
  py::dict result;
  result["responses"] = responses;
  result["metrics"] = py::module_::import("json").attr("loads")(compare::metrics_json(outcome.comparison));
  result["report"] = outcome.report.string();
  result["complete"] = outcome.complete;
  return result;
}
} // namespace

void bind_run(py::module_ &m)
{
  static py::exception<ProgramFailed> run_error(m, "RunError", PyExc_RuntimeError);
  run_error.doc() = "A run that failed mid-way (an engine's exception, a DEM guard): the message says in which "
                    "stage and after which time; `response` holds the samples recorded so far.";
  const py::object error_type = run_error;
  m.attr("engines") = cli::engine_names();
  m.def(
    "run",
    [error_type](const PyCase &c, const std::string &engine, std::optional<std::string> output,
                 std::optional<py::function> progress) { return run(c, engine, output, progress, error_type); },
    py::arg("case"), py::arg("engine"), py::arg("output") = py::none(), py::arg("progress") = py::none(),
    R"doc(Runs one engine of a case through its loading program and returns the Response.

engine: 'material-point', 'dem' or 'continuum' (geocomp.engines), built by the command
line's make_engine() after the engine's checks (CaseError on a refusal). output: the folder
for the engine's own files (the DEM's prepared specimen dem-specimen.bin, reused as the
command line reuses it; the FE fields); default the case's output/directory. No results
file is written (the command line writes them). progress(p) is called at every sample with
a dict: stage, stage_count, branch, time [s], stage_fraction; an exception it raises (or
Ctrl-C) stops the run and is raised again. The GIL is released while the engine runs.
A run that fails mid-way raises RunError (its .response holds the samples so far); a stage
ended by its max duration returns a Response whose status says so. 'continuum' starts MPI
in this process once (one rank; docs/python.md).)doc");
  m.def(
    "pair",
    [error_type](const PyCase &c, std::optional<std::string> output, bool force, std::optional<py::function> progress) {
      return pair(c, output, force, progress, error_type);
    },
    py::arg("case"), py::arg("output") = py::none(), py::arg("force") = false, py::arg("progress") = py::none(),
    R"doc(Runs every engine the case names, compares them and writes the report: `geocomp pair`.

The command line's own code: each engine's results file <output>/<engine>.h5 (reused when
made from the same case text and parameters by the same build, unless force=True), the DEM's
particle snapshots and program checkpoints, the FE cube's mid-plane, <output>/report/
(index.html, metrics.json, plots). output: default the case's output/directory; the folder
is locked for the run as the command line locks it (CaseError when another run holds it).
progress(p) is called at every sample with run()'s dict plus 'engine'; an exception it
raises (or Ctrl-C) stops the run and is raised again (the stopped engine's file holds the
samples so far, with its status). Returns a dict: 'responses' {engine: Response},
'metrics' (metrics.json's content: each engine's metrics, differences, the Rudnicki-Rice
verdict), 'report' (the path of index.html) and 'complete' (every engine finished its
program). Starts MPI in this process once (one rank); the GIL is released while it runs.
CaseError for a refused case; RunError for a run that failed mid-way.)doc");
  m.def(
    "material_point",
    [error_type](const PyCase &c, const std::map<std::string, py::object> &entries,
                 std::optional<py::function> progress) {
      PyCase changed = c;
      for (const auto &[path, value] : entries)
        changed.set(path, entry_text(value));
      return run(changed, "material-point", std::nullopt, progress, error_type);
    },
    py::arg("case"), py::arg("entries") = std::map<std::string, py::object>{}, py::arg("progress") = py::none(),
    R"doc(The case's material point with some entries changed, for quick exploration.

entries: {'continuum/friction angle': '0:30', ...} set on a copy of the case (the case
itself is not changed), then run('material-point'). Milliseconds for a typical program.)doc");
}

} // namespace geocomp::python
