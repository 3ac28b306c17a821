// geocomp.metrics, geocomp.rudnicki_rice and friends: the compare layer's numbers of a
// Response (compare/Metrics.h, compare/LocalizationOnsets.h) and Rudnicki & Rice's closed
// form (continuum/models/RudnickiRice.h), for exploring from Python.
#include "Bindings.h"

#include "compare/LocalizationOnsets.h"
#include "compare/Metrics.h"
#include "compare/cli/Engines.h"
#include "continuum/models/RudnickiRice.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace geocomp::python {

namespace py = pybind11;

py::dict metrics_dict(const compare::MetricSet &s)
{
  py::dict d;
  d["kind"] = compare::to_string(s.kind);
  d["axial_axis"] = s.kind == compare::CurveKind::AxialLateral ? py::cast(s.axial.describe()) : py::none();
  d["stage"] = s.stage;
  d["engine"] = s.engine;
  d["y0"] = s.y0;
  d["initial_modulus"] = s.initial_modulus;
  d["secant_modulus"] = s.secant_modulus;
  d["elastic_limit_strain"] = s.elastic_limit_strain;
  d["elastic_limit_stress"] = s.elastic_limit_stress;
  d["elastic_limit_method"] = s.elastic_limit_method;
  d["elastic_limit_lower"] = s.elastic_limit_lower;
  d["elastic_limit_upper"] = s.elastic_limit_upper;
  d["peak_strain"] = s.peak_strain;
  d["peak_stress"] = s.peak_stress;
  d["softening_modulus"] = s.softening_modulus;
  d["residual_stress"] = s.residual_stress;
  d["dilatancy_angle_deg"] = s.dilatancy_angle_deg;
  d["friction_peak_deg"] = s.friction_peak_deg;
  d["friction_residual_deg"] = s.friction_residual_deg;
  d["shear_modulus"] = s.shear_modulus;
  d["bulk_modulus"] = s.bulk_modulus;
  py::list branches;
  for (const compare::BranchResidual &b : s.branches)
    branches.append(py::dict(py::arg("id") = b.id, py::arg("x_start") = b.x_start, py::arg("y_start") = b.y_start,
                             py::arg("residual") = b.residual, py::arg("bisection") = b.bisection));
  d["branches"] = branches;
  d["notes"] = s.notes;
  return d;
}

namespace {
py::dict onset_dict(const compare::OnsetEstimate &o)
{
  return py::dict(py::arg("source") = o.source, py::arg("found") = o.found, py::arg("strain") = o.strain,
                  py::arg("angle_deg") = o.has_angle ? py::cast(o.angle_deg) : py::none(), py::arg("note") = o.note);
}

/// The curve kind and axis of a case's program, or of `kind` ("auto", "shear", "axial").
compare::MetricOptions curve_options(const PyCase *c, const std::string &kind, int stage)
{
  compare::MetricOptions o;
  o.stage = stage;
  if (c) {
    o.kind = compare::curve_kind_for(c->description().program);
    o.axial = compare::axial_axis_for(c->description().program, stage);
  }
  if (!kind.empty()) {
    try {
      o.kind = compare::parse_curve_kind(kind);
    } catch (const std::invalid_argument &e) {
      throw py::value_error("kind '" + kind + "': " + e.what());
    }
  }
  return o;
}

continuum::Matrix3 matrix3(const py::array_t<double, py::array::c_style | py::array::forcecast> &a)
{
  if (a.ndim() != 2 || a.shape(0) != 3 || a.shape(1) != 3)
    throw py::value_error("expected a 3 x 3 stress tensor");
  continuum::Matrix3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m(i, j) = a.at(i, j);
  return m;
}
} // namespace

/// The closed form and the onsets along a response (continuum/models/RudnickiRice.h,
/// compare/LocalizationOnsets.h); bind_metrics() calls it.
void bind_rudnicki_rice(py::module_ &m);

void bind_metrics(py::module_ &m)
{
  m.def(
    "metrics",
    [](const PyResponse &r, const PyCase *c, const std::string &kind, int stage, bool interval_means) {
      const compare::MetricOptions o = curve_options(c, kind, stage);
      return metrics_dict(compare::compute_metrics(interval_means ? with_interval_means(r.response) : r.response, o));
    },
    py::arg("response"), py::arg("case") = py::none(), py::arg("kind") = "", py::arg("stage") = -1,
    py::arg("interval_means") = true,
    R"doc(The compare layer's metrics of a Response (docs/metrics.md), as `geocomp compare` computes them.

The curve: the case's program picks it (isochoric: tau_max - gamma_max; otherwise the axial
curve on the program's axis, compression positive), or kind = 'shear' | 'axial' | 'auto'.
Strains are logarithmic from the stage start (fractions), stresses Pa, angles degrees;
NaN where a metric does not exist (notes say why). interval_means: read the DEM's
interval-mean stresses, as the report does. Keys: elastic_limit_strain/_stress/_method,
peak_strain, peak_stress, softening_modulus, residual_stress, initial_modulus,
secant_modulus, dilatancy_angle_deg, friction_peak_deg, friction_residual_deg,
shear_modulus, bulk_modulus, branches, notes, ...)doc");

  bind_rudnicki_rice(m);
}

void bind_rudnicki_rice(py::module_ &m)
{
  m.def(
    "rudnicki_rice",
    [](double mu, double beta, double nu, double N) {
      const continuum::RudnickiRicePrediction p = continuum::rudnicki_rice_prediction({mu, beta, nu}, N);
      return py::dict(py::arg("critical_hardening_over_G") = p.critical_hardening_over_G, py::arg("alpha") = p.alpha,
                      py::arg("band_normal_angle") = p.band_normal_angle,
                      py::arg("band_plane_angle") = p.band_plane_angle,
                      py::arg("closed_form_valid") = p.closed_form_valid);
    },
    py::arg("mu"), py::arg("beta"), py::arg("nu"), py::arg("N"),
    R"doc(Rudnicki & Rice (1975) closed form: critical hardening modulus h_cr/G and band angle.

mu: internal friction coefficient, beta: dilatancy factor, nu: Poisson ratio, N = s_II/tau
the deviatoric state (+1/sqrt(3) axisymmetric compression, -1/sqrt(3) extension; tension
positive). Angles in radians: band_normal_angle theta_0 from the most compressive axis,
band_plane_angle = pi/2 - theta_0. closed_form_valid is False when |alpha| > 1 (clamped).)doc");
  m.def(
    "rudnicki_rice_from_drucker_prager",
    [](double omega, double Lambda, double nu) {
      const continuum::RudnickiRiceMaterial r = continuum::rudnicki_rice_from_drucker_prager(omega, Lambda, nu);
      return py::dict(py::arg("mu") = r.mu, py::arg("beta") = r.beta, py::arg("nu") = r.nu);
    },
    py::arg("omega"), py::arg("Lambda"), py::arg("nu"), "mu = 3 omega, beta = Lambda: Rudnicki-Rice's material of a "
                                                        "Drucker-Prager cone omega tr(sigma) + tau = Y.");
  m.def(
    "deviatoric_state", [](const py::array_t<double, py::array::c_style | py::array::forcecast> &stress) {
      return continuum::deviatoric_state(matrix3(stress));
    },
    py::arg("stress"), "N = s_II / tau of a 3 x 3 stress tensor [Pa], tension positive (0 when hydrostatic).");
  m.def(
    "rudnicki_rice_onset",
    [](const PyResponse &r, const PyCase &c, int stage) {
      const CaseDescription &d = c.description();
      if (d.continuum.model == "nikolaevsky")
        throw py::value_error("no Rudnicki-Rice prediction for " + d.file +
                              ": it is computed from the Mohr-Coulomb parameters, and the case's model is nikolaevsky");
      const continuum::MaterialParameters mat = cli::continuum_material(d);
      const compare::KappaMeasure measure = d.continuum.model == "drucker-prager"
                                              ? compare::KappaMeasure::shear_strain
                                              : compare::KappaMeasure::mohr_coulomb;
      const compare::MetricOptions o = curve_options(&c, "", stage);
      return onset_dict(compare::rudnicki_rice_onset(r.response, mat.mohr_coulomb, mat.drucker_prager_matching,
                                                     measure, o.kind, stage, o.axial));
    },
    py::arg("response"), py::arg("case"), py::arg("stage") = -1,
    R"doc(Rudnicki-Rice's predicted localization onset along a material-point Response of `case`, as the report gives it.

Returns a dict: source, found, strain (the metrics' measure: gamma_max, or the axial
log strain, from the stage start), angle_deg (band normal from the most compressive axis),
note.)doc");
  m.def(
    "acoustic_tensor_onset",
    [](const PyResponse &r, const PyCase *c, const std::string &kind, int stage) {
      const compare::MetricOptions o = curve_options(c, kind, stage);
      return onset_dict(compare::acoustic_tensor_onset(r.response, r.response.engine + " (acoustic tensor)", o.kind,
                                                       stage, o.axial));
    },
    py::arg("response"), py::arg("case") = py::none(), py::arg("kind") = "", py::arg("stage") = -1,
    "An engine's own onset from its acoustic-tensor extra (localization_q): the dict of rudnicki_rice_onset.");
}

} // namespace geocomp::python
