#include "compare/Metrics.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace geocomp::compare {

namespace {
constexpr double rad2deg = 180.0 / 3.14159265358979323846;

/// Linear interpolation of the crossing of `level` between (a, fa) and (b, fb).
double cross(double a, double fa, double b, double fb, double level)
{
  if (fb == fa)
    return b;
  return a + (level - fa) * (b - a) / (fb - fa);
}

/// y at x on a polyline, scanning from the start for the first segment that reaches x.
double interpolate_at(const std::vector<double> &x, const std::vector<double> &y, double xv,
                      std::size_t last)
{
  last = std::min(last, x.size() - 1);
  for (std::size_t i = 1; i <= last; ++i)
    if (x[i] >= xv)
      return x[i] == x[i - 1] ? y[i] : y[i - 1] + (xv - x[i - 1]) * (y[i] - y[i - 1]) / (x[i] - x[i - 1]);
  return y[last];
}

double relative_volumetric(const Tensor3 &eps, const Tensor3 &eps0)
{
  return (Tensor3::Identity() + eps).determinant() / (Tensor3::Identity() + eps0).determinant() - 1.0;
}

const char *axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

/// Index of the main-path sample the stage starts from and the stage's main-path samples.
std::vector<std::size_t> stage_samples(const Response &response, int &stage)
{
  const auto &samples = response.samples;
  std::vector<std::size_t> main;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples[i].branch == 0)
      main.push_back(i);
  if (main.empty())
    throw std::invalid_argument("response has no main-path samples");
  if (stage < 0)
    stage = samples[main.back()].stage;
  // The stage starts from the last main-path sample of the stages before it.
  std::vector<std::size_t> idx;
  for (std::size_t i : main)
    if (samples[i].stage < stage)
      idx.assign(1, i);
  for (std::size_t i : main)
    if (samples[i].stage == stage)
      idx.push_back(i);
  return idx;
}

double mobilized_sin_phi(const Tensor3 &stress)
{
  const Vector3 s = principal_values(stress);
  const double s1 = -s[0], s3 = -s[2]; // compression positive, s1 >= s3
  return s1 + s3 > 0.0 ? (s1 - s3) / (s1 + s3) : nan;
}
} // namespace

std::string to_string(CurveKind kind)
{
  switch (kind) {
  case CurveKind::Auto: return "auto";
  case CurveKind::ShearIsochoric: return "shear";
  case CurveKind::AxialLateral: return "axial";
  }
  return "auto";
}

CurveKind parse_curve_kind(const std::string &text)
{
  if (text == "auto")
    return CurveKind::Auto;
  if (text == "shear")
    return CurveKind::ShearIsochoric;
  if (text == "axial")
    return CurveKind::AxialLateral;
  throw std::invalid_argument("curve kind '" + text + "': expected shear, axial or auto");
}

std::string AxialAxis::describe() const
{
  return std::string(axis_name(axis)) + (sense < 0 ? ", compression positive" : ", extension positive");
}

std::string AxialAxis::strain_label() const
{
  return std::string("eps_") + axis_name(axis) + (sense < 0 ? " (compr. +)" : " (ext. +)");
}

std::string AxialAxis::stress_label() const
{
  return std::string("sigma_") + axis_name(axis) + (sense < 0 ? " (compr. +)" : " (tension +)");
}

std::optional<AxialAxis> axial_axis_for(const LoadingProgram &program, int stage)
{
  if (program.stages.empty())
    return std::nullopt;
  const Stage &s = program.stages[stage < 0 ? program.stages.size() - 1 : static_cast<std::size_t>(stage)];
  if (s.isochoric)
    return std::nullopt;
  AxialAxis a;
  double fastest = 0.0;
  for (int k = 0; k < 3; ++k)
    if (!s.axes[k].is_stress() && std::abs(s.axes[k].value) > fastest) {
      fastest = std::abs(s.axes[k].value);
      a.axis = k;
      a.sense = s.axes[k].value < 0.0 ? -1.0 : 1.0;
    }
  if (fastest > 0.0)
    return a;
  // All stress-driven: the target farthest from the mean of the other two.
  double farthest = -1.0;
  for (int k = 0; k < 3; ++k) {
    if (!s.axes[k].is_stress())
      continue;
    double others = 0.0;
    int n = 0;
    for (int m = 0; m < 3; ++m)
      if (m != k && s.axes[m].is_stress()) {
        others += s.axes[m].value;
        ++n;
      }
    const double d = s.axes[k].value - (n ? others / n : 0.0);
    if (std::abs(d) > farthest) {
      farthest = std::abs(d);
      a.axis = k;
      a.sense = d < 0.0 ? -1.0 : 1.0;
    }
  }
  return a;
}

AxialAxis guess_axial_axis(const Response &response, int stage)
{
  const std::vector<std::size_t> idx = stage_samples(response, stage);
  const Tensor3 e0 = response.samples[idx.front()].strain;
  Vector3 change = Vector3::Zero();
  for (std::size_t i : idx) {
    const Tensor3 e = relative_log_strain(response.samples[i].strain, e0);
    for (int k = 0; k < 3; ++k)
      if (std::abs(e(k, k)) > std::abs(change[k]))
        change[k] = e(k, k);
  }
  AxialAxis a;
  change.cwiseAbs().maxCoeff(&a.axis);
  a.sense = change[a.axis] > 0.0 ? 1.0 : -1.0;
  return a;
}

Tensor3 relative_log_strain(const Tensor3 &strain, const Tensor3 &reference)
{
  return logarithmic_strain(strain) - logarithmic_strain(reference);
}

CurveKind curve_kind_for(const LoadingProgram &program)
{
  for (const auto &s : program.stages)
    if (s.isochoric)
      return CurveKind::ShearIsochoric;
  return CurveKind::AxialLateral;
}

CurveKind guess_curve_kind(const Response &response)
{
  const auto main = response.path(0);
  if (main.empty())
    return CurveKind::ShearIsochoric;
  const int stage = main.back()->stage;
  const ResponseSample *start = main.front();
  for (const auto *s : main)
    if (s->stage < stage)
      start = s;
  double max_ev = 0.0, max_g = 0.0;
  for (const auto *s : main)
    if (s->stage == stage) {
      max_ev = std::max(max_ev, std::abs(relative_volumetric(s->strain, start->strain)));
      max_g = std::max(max_g, gamma_max(s->strain - start->strain));
    }
  return max_ev < 1e-6 && max_g > 1e-5 ? CurveKind::ShearIsochoric : CurveKind::AxialLateral;
}

Curve extract_curve(const Response &response, CurveKind kind, int stage, std::optional<AxialAxis> axial)
{
  if (kind == CurveKind::Auto)
    kind = guess_curve_kind(response);
  const auto &samples = response.samples;
  const std::vector<std::size_t> idx = stage_samples(response, stage);
  if (idx.size() < 3)
    throw std::invalid_argument("stage " + std::to_string(stage) + " has " + std::to_string(idx.size()) +
                                " main-path samples; metrics need at least 3");

  Curve c;
  c.kind = kind;
  c.stage = stage;
  const bool shear = kind == CurveKind::ShearIsochoric;
  if (!shear)
    c.axial = axial ? *axial : guess_axial_axis(response, stage);
  const int a = c.axial.axis;
  const double sense = c.axial.sense;
  c.x_name = shear ? "gamma_max" : std::string(sense < 0 ? "-" : "") + "eps_" + axis_name(a) + axis_name(a);
  c.y_name = shear ? "tau_max" : std::string(sense < 0 ? "-" : "") + "sigma_" + axis_name(a) + axis_name(a);
  const Tensor3 eps0 = samples[idx.front()].strain;
  auto xy = [&](const ResponseSample &s) {
    const Tensor3 e = relative_log_strain(s.strain, eps0);
    if (shear)
      return std::pair<double, double>(gamma_max(e), tau_max(s.stress));
    return std::pair<double, double>(sense * e(a, a), sense * s.stress(a, a));
  };
  std::map<std::size_t, std::size_t> position; // sample index -> main-path position
  const int broken = response.extra_index("broken_bonds");
  for (std::size_t i : idx) {
    const ResponseSample &s = samples[i];
    const auto [x, y] = xy(s);
    position[i] = c.x.size();
    c.x.push_back(x);
    c.y.push_back(y);
    const Tensor3 e = relative_log_strain(s.strain, eps0);
    c.gamma.push_back(gamma_max(e));
    c.tau.push_back(tau_max(s.stress));
    c.eps_v.push_back(e.trace());
    c.p.push_back(mean_stress(s.stress));
    c.q.push_back(von_mises(s.stress));
    c.sin_phi.push_back(mobilized_sin_phi(s.stress));
    if (broken >= 0 && std::size_t(broken) < s.extras.size())
      c.broken_bonds.push_back(s.extras[std::size_t(broken)]);
  }

  // Branches: from the records when present, otherwise from the branch ids in the samples.
  std::map<int, std::vector<std::size_t>> branch_samples;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples[i].branch > 0 && samples[i].stage == stage)
      branch_samples[samples[i].branch].push_back(i);
  for (const auto &[id, members] : branch_samples) {
    std::size_t origin = idx.front();
    bool reached = true;
    bool recorded = false;
    bool bisection = false;
    for (const auto &b : response.branches)
      if (b.id == id) {
        origin = b.first_sample;
        reached = b.reached_target;
        bisection = b.bisection();
        recorded = true;
      }
    if (!recorded) // the main-path sample just before the branch
      for (std::size_t i : idx)
        if (samples[i].time <= samples[members.front()].time)
          origin = i;
    if (origin >= samples.size())
      continue;
    Curve::Branch b;
    b.id = id;
    b.reached_target = reached;
    b.bisection = bisection;
    std::tie(b.x_start, b.y_start) = xy(samples[origin]);
    b.x.push_back(b.x_start);
    b.y.push_back(b.y_start);
    for (std::size_t i : members) {
      if (i == origin) // a bisection branch that starts between main-path samples records its origin
        continue;
      const auto [x, y] = xy(samples[i]);
      b.x.push_back(x);
      b.y.push_back(y);
    }
    b.residual = b.x.back();
    c.branches.push_back(std::move(b));
  }
  return c;
}

LineFit fit_line(const std::vector<double> &x, const std::vector<double> &y, std::size_t begin,
                 std::size_t end)
{
  LineFit f;
  end = std::min(end, std::min(x.size(), y.size()));
  if (end <= begin)
    return f;
  const std::size_t n = end - begin;
  double mx = 0, my = 0;
  for (std::size_t i = begin; i < end; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = begin; i < end; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  f.count = n;
  if (n < 2 || !(sxx > 0.0))
    return f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  return f;
}

std::vector<double> moving_average(const std::vector<double> &y, int half_window)
{
  if (half_window <= 0)
    return y;
  const long n = static_cast<long>(y.size());
  std::vector<double> out(y.size());
  for (long i = 0; i < n; ++i) {
    const long k = std::min<long>({half_window, i, n - 1 - i});
    double s = 0.0;
    for (long j = i - k; j <= i + k; ++j)
      s += y[j];
    out[i] = s / (2 * k + 1);
  }
  return out;
}

MetricSet compute_metrics(const Response &response, const MetricOptions &options)
{
  MetricSet m = compute_metrics(extract_curve(response, options.kind, options.stage, options.axial), options);
  m.engine = response.engine;
  return m;
}

MetricSet compute_metrics(const Curve &c, const MetricOptions &o)
{
  MetricSet m;
  m.kind = c.kind;
  m.axial = c.axial;
  m.stage = c.stage;
  const std::size_t n = c.x.size();
  if (n < 3) {
    m.notes.push_back("fewer than 3 samples");
    return m;
  }
  const std::vector<double> ys = moving_average(c.y, o.smoothing_half_window);
  const double y0 = c.y.front();
  m.y0 = y0;

  // Peak: maximum of the smoothed curve.
  const std::size_t ipk = static_cast<std::size_t>(std::max_element(ys.begin(), ys.end()) - ys.begin());
  m.peak_strain = c.x[ipk];
  m.peak_stress = ys[ipk];
  const double rise = ys[ipk] - y0;
  if (!(rise > 0.0)) {
    m.notes.push_back("the stress never rises above its value at the stage start");
    return m;
  }
  if (ipk == n - 1)
    m.notes.push_back("the maximum is the last sample: the peak may not have been reached");

  // Initial modulus: least squares over y - y0 <= initial_fraction * rise (at least 3 samples).
  std::size_t init_end = 0;
  while (init_end <= ipk && ys[init_end] - y0 <= o.initial_fraction * rise)
    ++init_end;
  init_end = std::min(n, std::max<std::size_t>(init_end, 3));
  const LineFit initial = fit_line(c.x, c.y, 0, init_end);
  m.initial_modulus = initial.slope;

  // Secant modulus at secant_fraction of the rise, interpolated on the rising branch.
  {
    const double target = o.secant_fraction * rise;
    for (std::size_t i = 1; i <= ipk; ++i)
      if (ys[i] - y0 >= target) {
        const double xt = cross(c.x[i - 1], ys[i - 1] - y0, c.x[i], ys[i] - y0, target);
        const double dx = xt - c.x.front();
        if (dx > 0.0)
          m.secant_modulus = target / dx;
        break;
      }
  }

  // Elastic limit, S0's method: residual strain after unloading, interpolated where it
  // reaches the threshold; the origin counts as a branch with zero residual.
  std::vector<BranchResidual> res;
  for (const auto &b : c.branches)
    if (b.reached_target)
      res.push_back({b.id, b.x_start, b.y_start, b.residual, b.bisection});
    else
      m.notes.push_back("branch " + std::to_string(b.id) + " did not reach its unloading target; ignored");
  std::sort(res.begin(), res.end(), [](const auto &a, const auto &b) { return a.x_start < b.x_start; });
  m.branches = res;
  if (!res.empty()) {
    m.elastic_limit_method = "unloading residual";
    double xa = c.x.front(), ra = 0.0;
    bool found = false;
    for (std::size_t k = 0; k < res.size(); ++k) {
      const BranchResidual &b = res[k];
      if (b.residual >= o.residual_threshold) {
        m.elastic_limit_strain = cross(xa, ra, b.x_start, b.residual, o.residual_threshold);
        found = true;
        if (k > 0) { // the first crossing is bracketed by two branches
          m.elastic_limit_lower = res[k - 1].x_start;
          m.elastic_limit_upper = b.x_start;
          if (res[k - 1].bisection || b.bisection) { // ProgramRunner bisected this bracket
            m.elastic_limit_method = "located by bisection";
            m.elastic_limit_strain = 0.5 * (m.elastic_limit_lower + m.elastic_limit_upper);
          }
        }
        break;
      }
      xa = b.x_start;
      ra = b.residual;
    }
    if (found)
      m.elastic_limit_stress = interpolate_at(c.x, ys, m.elastic_limit_strain, n - 1);
    else {
      std::ostringstream s;
      s << "every unloading residual is below " << o.residual_threshold
        << ": the elastic limit lies beyond the last branch (x = " << res.back().x_start << ")";
      m.notes.push_back(s.str());
    }
  } else if (std::isfinite(initial.slope)) {
    // Deviation from linearity: |line - y| / rise above the tolerance on
    // `linearity_persistence` consecutive samples; interpolated where it reaches it.
    m.elastic_limit_method = "deviation from linearity";
    auto dev = [&](std::size_t i) {
      return std::abs(initial.intercept + initial.slope * c.x[i] - ys[i]) / rise;
    };
    const int persist = std::max(1, o.linearity_persistence);
    for (std::size_t i = 1; i <= ipk; ++i) {
      if (dev(i) <= o.linearity_tolerance)
        continue;
      bool holds = true;
      for (std::size_t j = i; j < std::min(n, i + persist); ++j)
        holds = holds && dev(j) > o.linearity_tolerance;
      if (!holds)
        continue;
      const double t = cross(0.0, dev(i - 1), 1.0, dev(i), o.linearity_tolerance);
      const double tc = std::clamp(t, 0.0, 1.0);
      m.elastic_limit_strain = c.x[i - 1] + tc * (c.x[i] - c.x[i - 1]);
      m.elastic_limit_stress = ys[i - 1] + tc * (ys[i] - ys[i - 1]);
      break;
    }
    if (!std::isfinite(m.elastic_limit_strain))
      m.notes.push_back("the curve stays within the linearity tolerance up to the peak");
  }

  // Residual strength and softening modulus (need samples after the peak).
  std::vector<std::size_t> tail;
  if (ipk + 1 < n) {
    const double x_tail = c.x[ipk] + (1.0 - o.residual_tail_fraction) * (c.x.back() - c.x[ipk]);
    double sum = 0.0, sum_sin = 0.0;
    for (std::size_t i = ipk + 1; i < n; ++i)
      if (c.x[i] >= x_tail) {
        tail.push_back(i);
        sum += c.y[i];
        sum_sin += c.sin_phi[i];
      }
    if (!tail.empty()) {
      m.residual_stress = sum / tail.size();
      const double s = sum_sin / tail.size();
      if (std::abs(s) <= 1.0)
        m.friction_residual_deg = std::asin(s) * rad2deg;
    }
    const double drop = ys[ipk] - m.residual_stress;
    if (std::isfinite(drop) && drop > o.min_drop * rise) {
      const double hi = ys[ipk] - o.softening_window_begin * drop;
      const double lo = ys[ipk] - o.softening_window_end * drop;
      std::vector<double> wx, wy;
      for (std::size_t i = ipk + 1; i < n && ys[i] >= lo; ++i)
        if (ys[i] <= hi) {
          wx.push_back(c.x[i]);
          wy.push_back(c.y[i]);
        }
      const LineFit f = fit_line(wx, wy, 0, wx.size());
      m.softening_modulus = f.slope;
      if (!std::isfinite(f.slope))
        m.notes.push_back("fewer than 2 samples in the softening window");
    } else {
      m.notes.push_back("no softening: the post-peak drop is below min_drop");
    }
  } else {
    m.notes.push_back("no samples after the peak: no softening modulus or residual strength");
  }

  // Mobilized friction angle at the peak (cohesionless: sin phi = (s1 - s3)/(s1 + s3)).
  if (std::abs(c.sin_phi[ipk]) <= 1.0)
    m.friction_peak_deg = std::asin(c.sin_phi[ipk]) * rad2deg;

  // Dilatancy: plastic parts gamma^p = gamma - (tau - tau0)/G, eps_v^p = eps_v - (p - p0)/K,
  // sin psi = slope of eps_v^p against gamma^p over the samples around the peak.
  m.shear_modulus = fit_line(c.gamma, c.tau, 0, init_end).slope;
  if (o.bulk_modulus > 0.0)
    m.bulk_modulus = o.bulk_modulus;
  else {
    const auto [lo, hi] = std::minmax_element(c.eps_v.begin(), c.eps_v.begin() + init_end);
    const double k = fit_line(c.eps_v, c.p, 0, init_end).slope;
    if (*hi - *lo > 1e-12 && k > 0.0)
      m.bulk_modulus = k;
  }
  if (!std::isfinite(m.bulk_modulus) || !(m.shear_modulus > 0.0)) {
    m.notes.push_back("dilatancy angle not measured: the volume does not change in the initial window "
                      "(an isochoric program), so the bulk modulus that splits off the elastic volumetric "
                      "strain cannot be fitted");
  } else {
    std::size_t a = ipk, b = ipk;
    const double floor = y0 + (1.0 - o.dilatancy_window) * rise;
    while (a > 0 && ys[a - 1] >= floor)
      --a;
    while (b + 1 < n && ys[b + 1] >= floor)
      ++b;
    std::vector<double> gp, evp;
    for (std::size_t i = a; i <= b; ++i) {
      gp.push_back(c.gamma[i] - (c.tau[i] - c.tau.front()) / m.shear_modulus);
      evp.push_back(c.eps_v[i] - (c.p[i] - c.p.front()) / m.bulk_modulus);
    }
    const LineFit f = fit_line(gp, evp, 0, gp.size());
    if (!std::isfinite(f.slope))
      m.notes.push_back("dilatancy: no plastic shear increment around the peak");
    else if (std::abs(f.slope) > 1.0)
      m.notes.push_back("dilatancy: |d eps_v^p / d gamma^p| > 1, no angle");
    else
      m.dilatancy_angle_deg = std::asin(f.slope) * rad2deg;
  }
  return m;
}

std::vector<MetricValue> metric_table(const MetricSet &m)
{
  const bool shear = m.kind == CurveKind::ShearIsochoric;
  const std::string s = shear ? "tau_max" : m.axial.stress_label();
  const std::string e = shear ? "gamma_max" : m.axial.strain_label();
  const double MPa = 1e-6, pct = 100.0;
  return {
    {"initial_modulus_MPa", "initial modulus d" + s + "/d" + e, "MPa", m.initial_modulus * MPa},
    {"secant_modulus_MPa", "secant modulus at 50 % of peak", "MPa", m.secant_modulus * MPa},
    {"elastic_limit_strain_pct", "elastic limit " + e, "%",
     m.elastic_limit_strain * pct},
    {"elastic_limit_stress_MPa", "elastic limit " + s, "MPa", m.elastic_limit_stress * MPa},
    {"peak_strain_pct", "peak " + e, "%", m.peak_strain * pct},
    {"peak_stress_MPa", "peak " + s, "MPa", m.peak_stress * MPa},
    {"softening_modulus_MPa", "softening modulus (post-peak slope)", "MPa", m.softening_modulus * MPa},
    {"residual_stress_MPa", "residual " + s, "MPa", m.residual_stress * MPa},
    {"dilatancy_angle_deg", "dilatancy angle psi (at peak)", "deg", m.dilatancy_angle_deg},
    {"friction_peak_deg", "mobilized friction angle at peak", "deg", m.friction_peak_deg},
    {"friction_residual_deg", "mobilized friction angle, residual", "deg", m.friction_residual_deg},
  };
}

} // namespace geocomp::compare
