#pragma once
// The pieces of the `geocomp` Python module (docs/python.md), one file each: cases
// (CaseBindings.cpp), runs (RunBindings.cpp), responses as numpy arrays
// (ResponseBindings.cpp), metrics and the Rudnicki-Rice functions (MetricsBindings.cpp),
// studies (StudyBindings.cpp).
// Module.cpp calls each bind_*() once, in this order: later ones use the types and
// exceptions the earlier ones register.
#include "common/ProgramRunner.h"
#include "common/Response.h"
#include "compare/Metrics.h"
#include "compare/case/CaseDescription.h"

#include <optional>
#include <pybind11/pybind11.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace geocomp::python {

/// A case file as the command line reads it, plus the entries set from Python.
///
/// Why it exists: `geocomp check` and every run command read a case with read_case() and
/// validate it with validate_engines() (compare/cli/CaseValidation.h). A Python user wants
/// the same case, changed one entry at a time. PyCase keeps the case text and its file
/// name (which picks .prm or .json and names the file in every message) and re-reads the
/// whole text after each change, so a changed case is checked by exactly the readers a
/// case file is.
class PyCase {
public:
  /// read_case(path): the file's text, parsed and checked entry by entry (CaseError).
  static PyCase read(const std::string &path);
  /// read_valid_case(path): read_case(), then every named engine's checks, as `geocomp check`.
  static PyCase checked(const std::string &path);
  /// parse_case(text, name): `name` picks the syntax (.prm/.json) and names the case in messages.
  static PyCase parse(const std::string &text, const std::string &name);
  /// A case already read and checked (a study's case).
  static PyCase of(CaseDescription d) { return PyCase(std::move(d)); }

  const CaseDescription &description() const { return description_; }
  const std::string &file() const { return description_.file; }
  const std::string &text() const { return description_.text; }

  /// The entry `path` ("continuum/friction angle", "program/stage 1/mode") as parsed, in
  /// the canonical text results files store under /meta/parameters. Throws py::key_error.
  std::string get(const std::string &path) const;
  /// Sets entry `path` to `value` (case-file syntax, e.g. "0:12, 0.04:29") and re-reads the
  /// case; on a refusal (CaseError) the case is left as it was.
  void set(const std::string &path, const std::string &value);
  /// The case's entries as canonical `section/entry = value` lines (parameters_text()).
  std::string parameters() const;

private:
  explicit PyCase(CaseDescription d) : description_(std::move(d)) {}
  CaseDescription description_;
};

/// A Response with its columns laid out once for numpy.
///
/// Why it exists: the engines record one ResponseSample per instant (an array of
/// structs), numpy wants one contiguous array per quantity. PyResponse copies the samples
/// into columns once, when it is made; every array property is then a read-only view of
/// those columns (no further copy), kept alive by the PyResponse. The derived columns
/// (log_strain, gamma_max, ...) come from the same functions write_response() uses, so they
/// equal a results file's bit for bit.
struct PyResponse {
  explicit PyResponse(Response r, std::string status = "complete");

  Response response;
  std::string status; ///< "complete", or why the run stopped early (completion_status, ProgramFailed)
  std::size_t n = 0;
  std::vector<double> time, volumetric_strain, gamma_max, tau_max, mean_stress;
  std::vector<double> strain, log_strain, stress, stress_mean; ///< n x 3 x 3, row-major
  std::vector<int> stage, branch;
  std::vector<std::vector<double>> extras; ///< aligned with response.extras
};

/// A Python value as case-file text: a str as it is, True/False as true/false, a number as
/// Python writes it (the shortest text that reads back to the same double).
std::string entry_text(const pybind11::handle &value);

/// The compare layer's metrics as geocomp.metrics() returns them (a dict; NaN where missing).
pybind11::dict metrics_dict(const compare::MetricSet &s);

/// MPI (and PETSc) started once per process as the command line starts it, finished when
/// Python exits (RunBindings.cpp).
void ensure_mpi();

/// A run's progress as the Python callbacks get it: stage, stage_count, branch, time [s],
/// stage_fraction (RunBindings.cpp).
pybind11::dict progress_dict(const RunProgress &p);

/// Thrown from a progress callback to stop a run when Python raised; the Python exception
/// itself is kept and raised again once the run has unwound (RunBindings.cpp).
struct CallbackRaised : std::runtime_error {
  CallbackRaised() : std::runtime_error("the Python progress callback raised") {}
};

/// Calls a progress callback with `state` (the caller holds the GIL); when it raises, or a
/// signal is pending, keeps the Python exception in `raised` and throws CallbackRaised.
void call_progress(const pybind11::object &callback, const pybind11::dict &state,
                   std::optional<pybind11::error_already_set> &raised);

void bind_case(pybind11::module_ &m);
void bind_response(pybind11::module_ &m);
void bind_run(pybind11::module_ &m);
void bind_metrics(pybind11::module_ &m);
void bind_study(pybind11::module_ &m);

} // namespace geocomp::python
