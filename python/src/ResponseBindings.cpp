// geocomp.Response: a Response's quantities as numpy arrays, named as the results file
// names them (docs/results-format.md); see PyResponse in Bindings.h.
#include "Bindings.h"

#include "common/ResponseFile.h"
#include "common/Tensor.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace geocomp::python {

namespace py = pybind11;

namespace {
/// Appends a tensor's nine components row by row, t(i, j) at 3 i + j (the file's layout).
void append(std::vector<double> &out, const Tensor3 &t)
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      out.push_back(t(i, j));
}

/// A read-only numpy view of `data` with `shape`, owned by `owner` (no copy).
template <class T>
py::array view(const std::vector<T> &data, std::vector<py::ssize_t> shape, const py::object &owner)
{
  py::array a(py::dtype::of<T>(), std::move(shape), data.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::dict branch_dict(const BranchRecord &b)
{
  py::dict d;
  d["id"] = b.id;
  d["stage"] = b.stage;
  d["trigger"] = b.trigger;
  d["first_sample"] = b.first_sample;
  d["last_sample"] = b.last_sample;
  d["tau_start"] = b.tau_start;
  d["tau_target"] = b.tau_target;
  d["gamma_start"] = b.gamma_start;
  d["residual_gamma"] = b.residual_gamma;
  d["reached_target"] = b.reached_target;
  return d;
}

/// A tensor column (n x 3 x 3) or a scalar one (n) as a property.
template <class T> auto tensor_column(std::vector<T> PyResponse::*column)
{
  return [column](const py::object &self) {
    const PyResponse &r = self.cast<const PyResponse &>();
    return view(r.*column, {py::ssize_t(r.n), 3, 3}, self);
  };
}
template <class T> auto scalar_column(std::vector<T> PyResponse::*column)
{
  return [column](const py::object &self) {
    const PyResponse &r = self.cast<const PyResponse &>();
    return view(r.*column, {py::ssize_t(r.n)}, self);
  };
}
} // namespace

PyResponse::PyResponse(Response r, std::string run_status)
  : response(std::move(r)), status(std::move(run_status)), n(response.samples.size())
{
  extras.resize(response.extras.size());
  for (const ResponseSample &s : response.samples) {
    time.push_back(s.time);
    append(strain, s.strain);
    append(log_strain, logarithmic_strain(s.strain));
    append(stress, s.stress);
    append(stress_mean, s.stress_mean);
    volumetric_strain.push_back(geocomp::volumetric_strain(s.strain));
    gamma_max.push_back(geocomp::gamma_max(s.strain));
    tau_max.push_back(geocomp::tau_max(s.stress));
    mean_stress.push_back(geocomp::mean_stress(s.stress));
    stage.push_back(s.stage);
    branch.push_back(s.branch);
    for (std::size_t k = 0; k < extras.size(); ++k)
      extras[k].push_back(k < s.extras.size() ? s.extras[k] : std::numeric_limits<double>::quiet_NaN());
  }
}

void bind_response(py::module_ &m)
{
  const char *tension = " SI units, tension positive. Read-only view, no copy.";
  py::class_<PyResponse>(m, "Response", R"doc(What an engine emits for a loading program: one sample per sampling instant.

Arrays are named as in the results file (docs/results-format.md): time [s] (n), strain,
log_strain [1] and stress, stress_mean [Pa] (n x 3 x 3, engineering box strain from the
program start, Cauchy stress), volumetric_strain, gamma_max, tau_max, mean_stress (n),
stage and branch (n, 0 = main path), extras (dict of n-arrays). SI units, tension positive.

Copies: the engine records one C++ struct per sample; the samples are copied into one
column per quantity once, when the Response is made. Every array property is then a
read-only numpy view of that column (no copy), valid as long as any array or the Response
is alive. Use numpy.array(r.stress) for a writable copy.)doc")
    .def_static(
      "read",
      [](const std::string &path) {
        RunMeta meta;
        Response r = read_response(path, &meta);
        return PyResponse(std::move(r), meta.status);
      },
      py::arg("path"),
      "Reads a results file with the C++ reader (geocomp::read_response); geocomp.read_results is the h5py one.")
    .def_property_readonly("engine", [](const PyResponse &r) { return r.response.engine; })
    .def_property_readonly("status", [](const PyResponse &r) { return r.status; },
                           "'complete', or where and why the run stopped early (results' /meta/status).")
    .def_property_readonly("interval_means", [](const PyResponse &r) { return r.response.interval_means; },
                           "True when stress_mean is a mean over each sampling interval (DEM), else a copy of stress.")
    .def("__len__", [](const PyResponse &r) { return r.n; })
    .def_property_readonly("time", scalar_column(&PyResponse::time), (std::string("[s]") + tension).c_str())
    .def_property_readonly("strain", tensor_column(&PyResponse::strain),
                           (std::string("Engineering box strain L/L0 - 1 (n x 3 x 3).") + tension).c_str())
    .def_property_readonly("log_strain", tensor_column(&PyResponse::log_strain),
                           (std::string("Logarithmic strain ln(I + strain) (n x 3 x 3).") + tension).c_str())
    .def_property_readonly("stress", tensor_column(&PyResponse::stress),
                           (std::string("Cauchy stress at the sample instant [Pa] (n x 3 x 3).") + tension).c_str())
    .def_property_readonly("stress_mean", tensor_column(&PyResponse::stress_mean),
                           (std::string("Stress mean over the sampling interval [Pa] (n x 3 x 3).") + tension).c_str())
    .def_property_readonly("volumetric_strain", scalar_column(&PyResponse::volumetric_strain),
                           (std::string("det(I + strain) - 1.") + tension).c_str())
    .def_property_readonly("gamma_max", scalar_column(&PyResponse::gamma_max), "eps_max - eps_min (S0).")
    .def_property_readonly("tau_max", scalar_column(&PyResponse::tau_max), "(s_max - s_min)/2 [Pa] (S0).")
    .def_property_readonly("mean_stress", scalar_column(&PyResponse::mean_stress),
                           (std::string("tr(stress)/3 [Pa].") + tension).c_str())
    .def_property_readonly("stage", scalar_column(&PyResponse::stage), "0-based stage index of each sample.")
    .def_property_readonly("branch", scalar_column(&PyResponse::branch), "0 main path, k >= 1 unloading branch k.")
    .def_property_readonly(
      "extras",
      [](const py::object &self) {
        const PyResponse &r = self.cast<const PyResponse &>();
        py::dict d;
        for (std::size_t k = 0; k < r.extras.size(); ++k)
          d[py::str(r.response.extras[k].name)] = view(r.extras[k], {py::ssize_t(r.n)}, self);
        return d;
      },
      "Engine-specific columns by name (n each; units in extra_units). Views, no copy.")
    .def_property_readonly("extra_units",
                           [](const PyResponse &r) {
                             py::dict d;
                             for (const ExtraColumn &e : r.response.extras)
                               d[py::str(e.name)] = e.units;
                             return d;
                           })
    .def_property_readonly("stage_names", [](const PyResponse &r) { return r.response.stage_names; })
    .def_property_readonly("stage_end_reasons", [](const PyResponse &r) { return r.response.stage_end_reasons; })
    .def_property_readonly("branches",
                           [](const PyResponse &r) {
                             py::list l;
                             for (const BranchRecord &b : r.response.branches)
                               l.append(branch_dict(b));
                             return l;
                           },
                           "Unloading branches as dicts (the /branches columns of a results file).")
    .def("__repr__", [](const PyResponse &r) {
      return "<geocomp.Response " + r.response.engine + ", " + std::to_string(r.n) + " samples, " + r.status + ">";
    });
}

} // namespace geocomp::python
