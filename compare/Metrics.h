#pragma once
// Engine-agnostic metrics of one Response: the numbers a geomechanic reads off a
// stress-strain curve (S0 Fig. 2 and Fig. 5), computed by one piece of code whichever
// engine produced the curve.
//
// Conventions. Inside the code stress and strain are tension positive (Tensor.h). Measures:
// the **logarithmic strain** of the box, e = ln(L / L_start) = ln(1 + eps) - ln(1 + eps_start)
// (the box axes never rotate, so these add), and the **Cauchy stress** (force over current
// area), for every engine alike. The curve a metric is read from is oriented "loading
// positive": on the isochoric shear curve (S0 program 1) x = gamma_max = e_max - e_min and
// y = tau_max = (s_max - s_min)/2, both sign-free; on the axial curve (S0 program 2) of axis a
// x = s e_aa and y = s sigma_aa with s = -1 when the axis is shortened (**compression
// positive**, as geomechanics plots it) and s = +1 when it is extended. The axis and its
// sense come from the program (axial_axis_for) or, without one, from the response. Strains
// are measured from the start of the analysed stage, stresses are absolute (y0 is the value
// at the stage start); the volumetric strain is ln(V / V_start) = tr e, dilation positive.
// Every definition, window and tolerance is listed in docs/metrics.md.
#include "common/LoadingProgram.h"
#include "common/Response.h"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace geocomp::compare {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// Which curve the metrics are read from.
enum class CurveKind {
  Auto,          ///< isochoric if the volume stays constant, otherwise lateral pressure
  ShearIsochoric, ///< tau_max - gamma_max (S0 program 1)
  AxialLateral    ///< -sigma_zz - (-eps_zz), compression positive (S0 program 2)
};
std::string to_string(CurveKind kind);
/// "shear", "axial" or "auto"; throws std::invalid_argument otherwise.
CurveKind parse_curve_kind(const std::string &text);
/// Kind implied by a program: any isochoric stage means shear, otherwise axial.
CurveKind curve_kind_for(const LoadingProgram &program);
/// Kind guessed from a Response: shear when |eps_v| stays below 1e-6 while gamma_max grows.
CurveKind guess_curve_kind(const Response &response);

/// The axis of an axial curve and its sense: x = sense e_aa, y = sense sigma_aa.
struct AxialAxis {
  int axis = 2;        ///< 0, 1, 2 = x, y, z
  double sense = -1.0; ///< -1 shortened (compression positive), +1 extended
  /// "z, compression positive" etc.
  std::string describe() const;
  /// Table names: "eps_z (compr. +)", "sigma_z (compr. +)".
  std::string strain_label() const;
  std::string stress_label() const;
};
/// From a program's stage (-1: the last): its kinematic axis with the largest non-zero rate,
/// shortened or extended as the rate says; without one, the stress axis whose target
/// differs most from the others'. std::nullopt for an isochoric stage.
std::optional<AxialAxis> axial_axis_for(const LoadingProgram &program, int stage = -1);
/// From a response's stage (-1: the last): the axis whose logarithmic strain changes most
/// over the main path, in the sense it changes.
AxialAxis guess_axial_axis(const Response &response, int stage = -1);

/// Logarithmic strain of the box relative to a reference state of it (engineering box
/// strains in, both diagonal in the same axes): ln(1 + eps) - ln(1 + eps_reference).
Tensor3 relative_log_strain(const Tensor3 &strain, const Tensor3 &reference);

/// One stress-strain curve of one stage, in loading-positive measures (see the file
/// comment), with its unloading branches and the per-sample state the metrics need.
/// Extracting it once keeps every metric (and every plot) reading the same numbers.
struct Curve {
  struct Branch {
    int id = 0;
    double x_start = 0.0, y_start = 0.0; ///< where it left the main path
    std::vector<double> x, y;             ///< its samples, starting at the main-path point
    double residual = 0.0;                ///< x at its last sample (strain not recovered)
    bool reached_target = false;
    bool bisection = false;               ///< placed by the runner to locate the elastic limit
  };
  CurveKind kind = CurveKind::ShearIsochoric;
  AxialAxis axial;            ///< the axis of an axial curve
  int stage = 0;
  std::string x_name, y_name; ///< e.g. "gamma_max", "tau_max"
  std::vector<double> x, y;   ///< main path, x from the stage start
  std::vector<double> gamma;  ///< gamma_max of the log strain since the stage start
  std::vector<double> tau;    ///< tau_max [Pa]
  std::vector<double> eps_v;  ///< ln(V / V_start) = tr e, dilation positive
  std::vector<double> p;      ///< mean stress tr(sigma)/3 [Pa], tension positive
  std::vector<double> q;      ///< von Mises equivalent stress [Pa]
  std::vector<double> sin_phi; ///< mobilized (sigma_1 - sigma_3)/(sigma_1 + sigma_3), compression positive
  std::vector<double> broken_bonds; ///< S3 bonds broken for good (the DEM's `broken_bonds` extra); empty without it
  std::vector<Branch> branches;
  double y0() const { return y.empty() ? 0.0 : y.front(); }
};

/// Extracts the curve of `stage` (-1: the last stage on the main path); an axial curve on
/// `axial`, or on guess_axial_axis() without it. Throws std::invalid_argument when the
/// stage has fewer than 3 main-path samples.
Curve extract_curve(const Response &response, CurveKind kind, int stage = -1,
                    std::optional<AxialAxis> axial = std::nullopt);

/// Every window and tolerance of the metric definitions (defaults in docs/metrics.md).
struct MetricOptions {
  CurveKind kind = CurveKind::Auto;
  std::optional<AxialAxis> axial;      ///< axis of an axial curve (axial_axis_for); empty: guessed
  int stage = -1;                      ///< -1: the last stage
  int smoothing_half_window = 2;       ///< centred moving average of y over 2k+1 samples (0: none)
  double initial_fraction = 0.25;      ///< initial-modulus window: y - y0 <= f (peak - y0)
  double residual_threshold = s0_residual_threshold; ///< S0 elastic limit: residual strain after unloading
  double linearity_tolerance = 0.02;   ///< no branches: |deviation from the initial line| / (peak - y0)
  int linearity_persistence = 3;       ///< ... exceeded on this many consecutive samples
  double secant_fraction = 0.5;        ///< secant modulus at this fraction of (peak - y0)
  double softening_window_begin = 0.2; ///< softening fit from this fraction of the drop peak -> residual
  double softening_window_end = 0.8;   ///< ... to this one
  double residual_tail_fraction = 0.1; ///< residual: mean over the last fraction of the post-peak strain
  double min_drop = 0.02;              ///< softening exists when (peak - residual) > this (peak - y0)
  double dilatancy_window = 0.1;       ///< dilatancy: samples around the peak with y - y0 >= (1 - w)(peak - y0)
  double bulk_modulus = 0.0;           ///< K [Pa] for the elastic volumetric strain; 0: fit it
};

/// One residual measurement: an unloading branch that left the main path at x_start.
struct BranchResidual {
  int id = 0;
  double x_start = 0.0, y_start = 0.0, residual = 0.0;
  bool bisection = false; ///< placed by the runner to locate the elastic limit (else planned)
};

/// Metrics of one curve. Strains are fractions, stresses and moduli Pa, angles degrees;
/// the axial curve is compression positive. NaN where a metric does not exist (reasons in notes).
struct MetricSet {
  CurveKind kind = CurveKind::ShearIsochoric;
  AxialAxis axial;                     ///< the axis of an axial curve
  int stage = 0;
  std::string engine;
  double y0 = 0.0;                     ///< stress at the stage start
  double initial_modulus = nan;        ///< dy/dx, least squares over the initial window
  double secant_modulus = nan;         ///< (y - y0)/x at secant_fraction of the peak increment
  double elastic_limit_strain = nan, elastic_limit_stress = nan;
  std::string elastic_limit_method;    ///< "located by bisection", "unloading residual" or "deviation from linearity"
  /// Start strains of the neighbouring branches whose residuals straddle the threshold (the
  /// first crossing); NaN without such a pair. With bisection branches the elastic limit
  /// strain is their midpoint.
  double elastic_limit_lower = nan, elastic_limit_upper = nan;
  double peak_strain = nan, peak_stress = nan;
  double softening_modulus = nan;      ///< dy/dx after the peak (negative when softening)
  double residual_stress = nan;
  double dilatancy_angle_deg = nan;    ///< sin psi = d eps_v^p / d gamma^p, dilation positive
  double friction_peak_deg = nan;      ///< mobilized friction angle at the peak (c = 0)
  double friction_residual_deg = nan;  ///< ... mean over the residual tail
  double shear_modulus = nan;          ///< d tau / d gamma over the initial window (plastic split)
  double bulk_modulus = nan;           ///< K used for the plastic split
  std::vector<BranchResidual> branches;
  std::vector<std::string> notes;
};

MetricSet compute_metrics(const Response &response, const MetricOptions &options = {});
/// Same, on an already extracted curve.
MetricSet compute_metrics(const Curve &curve, const MetricOptions &options = {});

/// A metric as reports show it: display units (MPa, %, deg), one key per value. The HTML
/// table and metrics.json are both written from this list, so they cannot disagree.
struct MetricValue {
  std::string key;   ///< JSON key, e.g. "peak_stress_MPa"
  std::string label; ///< table label
  std::string units;
  double value = nan;
};
std::vector<MetricValue> metric_table(const MetricSet &metrics);

// Small numerical helpers, public because localization and the tests use them too.
/// Least-squares slope and intercept of y(x); NaN slope when fewer than 2 distinct x.
struct LineFit {
  double slope = nan, intercept = nan;
  std::size_t count = 0;
};
LineFit fit_line(const std::vector<double> &x, const std::vector<double> &y, std::size_t begin,
                 std::size_t end);
/// Centred moving average over 2k+1 samples, shrinking at the ends.
std::vector<double> moving_average(const std::vector<double> &y, int half_window);

} // namespace geocomp::compare
