// geocomp.run and geocomp.material_point: an engine of a case played through the case's
// loading program in this process, the way `geocomp <engine>` plays it (make_engine() of
// compare/cli/Engines.h, then ProgramRunner), with the progress reported to Python.
#include "Bindings.h"

#include "common/ProgramRunner.h"
#include "compare/cli/Engines.h"

#include <deal.II/base/mpi.h>

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>

namespace geocomp::python {

namespace py = pybind11;

namespace {
/// MPI (and PETSc) for the FE cube, started once per process as the command line starts it
/// (deal.II's MPI_InitFinalize, one thread per rank) and finished when Python exits.
std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;

void ensure_mpi()
{
  if (mpi)
    return;
  static int argc = 1;
  static char name[] = "python3";
  static char *argv_storage[] = {name, nullptr};
  static char **argv = argv_storage;
  mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
  py::module_::import("atexit").attr("register")(py::cpp_function([] { mpi.reset(); }));
}

/// Thrown from the progress callback to stop the run when Python raised; the Python
/// exception itself is kept and raised again once the run has unwound.
struct CallbackRaised : std::runtime_error {
  CallbackRaised() : std::runtime_error("the Python progress callback raised") {}
};

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
      try {
        (*progress)(progress_dict(p));
        if (PyErr_CheckSignals() != 0)
          throw py::error_already_set();
      } catch (py::error_already_set &python_error) {
        raised.emplace(std::move(python_error));
        throw CallbackRaised();
      }
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
