#include "compare/SectionMaps.h"
#include "compare/Localization.h"
#include "compare/LocalizationOnsets.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geocomp::compare {

namespace {
double largest_magnitude(const std::vector<double> &v)
{
  double m = 0.0;
  for (double x : v)
    if (std::isfinite(x))
      m = std::max(m, std::abs(x));
  return m;
}

/// The recorded state nearest `strain`, or a panel saying why there is none.
MapPanel locate(const StrainedSection &s, double strain, double max_gap, std::size_t &index)
{
  MapPanel p;
  const std::string &engine = s.engine;
  p.engine = engine;
  if (!s.series || s.strains.empty()) {
    p.missing = engine + ": no mid-section recorded";
    return p;
  }
  index = 0;
  for (std::size_t k = 1; k < s.strains.size(); ++k)
    if (std::abs(s.strains[k] - strain) < std::abs(s.strains[index] - strain))
      index = k;
  p.strain = s.strains[index];
  if (!(std::abs(p.strain - strain) <= max_gap)) {
    p.missing = engine + ": no recorded mid-section within " + percent_label(max_gap) + " strain of " + percent_label(strain) +
                " (nearest " + percent_label(p.strain) + ")";
    return p;
  }
  p.present = true;
  p.x = s.series->x;
  p.z = s.series->z;
  p.marker = s.series->marker;
  p.marker_z = s.series->marker_z;
  p.tiles = s.series->tiles;
  return p;
}

/// The panels' values of one quantity; `raw_scale` grows with the field before referencing.
void fill(MapPanel &p, const SectionSeries &s, std::size_t k, int quantity, double &raw_scale)
{
  if (quantity == 2) {
    p.v = in_plane_shear_strain(s.x, s.z, s.ux[k], s.uz[k], s.strain_radius);
    for (double &g : p.v)
      g *= 100.0;
    return;
  }
  const std::vector<double> &u = quantity == 0 ? s.ux[k] : s.uz[k];
  const double c = centre_displacement(s.x, s.z, u, s.centre_x, s.centre_z);
  p.v.resize(u.size());
  for (std::size_t i = 0; i < u.size(); ++i)
    p.v[i] = (u[i] - c) * 1e3;
  raw_scale = std::max(raw_scale, largest_magnitude(u) * 1e3);
}
} // namespace

double centre_displacement(const std::vector<double> &x, const std::vector<double> &z, const std::vector<double> &u,
                           double centre_x, double centre_z)
{
  const std::size_t n = u.size();
  if (n == 0)
    return 0.0;
  // Points without a value (a particle the engine no longer has) take no part.
  double xb = 0.0, zb = 0.0, ub = 0.0, count = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(u[i]))
      xb += x[i], zb += z[i], ub += u[i], count += 1.0;
  if (count == 0.0)
    return 0.0;
  xb /= count, zb /= count, ub /= count;
  Eigen::Matrix2d C = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(u[i]))
      continue;
    const Eigen::Vector2d d(x[i] - xb, z[i] - zb);
    C += d * d.transpose();
    b += d * (u[i] - ub);
  }
  // A section too thin to fit a gradient (all points on a line or one point): its mean.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(C, Eigen::EigenvaluesOnly);
  if (!(eig.eigenvalues()[0] > 1e-12 * eig.eigenvalues()[1]))
    return ub;
  const Eigen::Vector2d g = C.inverse() * b;
  return ub + g[0] * (centre_x - xb) + g[1] * (centre_z - zb);
}

std::vector<double> in_plane_shear_strain(const std::vector<double> &x, const std::vector<double> &z,
                                          const std::vector<double> &ux, const std::vector<double> &uz,
                                          double radius)
{
  const std::size_t n = x.size();
  std::vector<Vector3> points(n);
  for (std::size_t i = 0; i < n; ++i)
    points[i] = Vector3(x[i], 0.0, z[i]);
  std::vector<Eigen::Matrix2d> X(n, Eigen::Matrix2d::Zero()), Y(n, Eigen::Matrix2d::Zero());
  std::vector<int> count(n, 0);
  for (const auto &[i, j] : neighbour_pairs(points, radius)) {
    // The pair adds the same d d0^T and d0 d0^T to both ends (d and d0 change sign together).
    const Eigen::Vector2d d0(x[j] - x[i], z[j] - z[i]);
    const Eigen::Vector2d d = d0 + Eigen::Vector2d(ux[j] - ux[i], uz[j] - uz[i]);
    if (!d.allFinite())
      continue;
    for (std::size_t k : {i, j}) {
      X[k] += d * d0.transpose();
      Y[k] += d0 * d0.transpose();
      ++count[k];
    }
  }
  std::vector<double> gamma(n, nan);
  for (std::size_t i = 0; i < n; ++i) {
    if (count[i] < 3)
      continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(Y[i], Eigen::EigenvaluesOnly);
    if (!(eig.eigenvalues()[0] > 0.0) || eig.eigenvalues()[1] / eig.eigenvalues()[0] > 1e6)
      continue;
    const Eigen::Matrix2d F = X[i] * Y[i].inverse();
    const Eigen::Matrix2d E = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
    gamma[i] = std::sqrt((E(0, 0) - E(1, 1)) * (E(0, 0) - E(1, 1)) + 4.0 * E(0, 1) * E(0, 1));
  }
  return gamma;
}

ColourRange shared_colour_range(const std::vector<const std::vector<double> *> &fields, double scale,
                                double min_relative)
{
  double lo = INFINITY, hi = -INFINITY;
  for (const auto *f : fields)
    for (double v : *f)
      if (std::isfinite(v))
        lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi))
    return {-1.0, 1.0};
  const double size = std::max({std::abs(lo), std::abs(hi), std::abs(scale)});
  const double span = std::max(hi - lo, min_relative * size);
  if (!(span > 0.0) || !std::isfinite(span))
    return {-1.0, 1.0};
  const double mid = 0.5 * (lo + hi);
  return {std::min(lo, mid - 0.5 * span), std::max(hi, mid + 0.5 * span)}; // min/max: no round-off cut
}

StrainedSection strained_section(const SectionSeries &series, const Response &response, CurveKind kind, int stage,
                                 std::optional<AxialAxis> axial)
{
  std::vector<std::size_t> samples;
  const std::vector<double> strain = onset_strain_measure(response, kind, stage, samples, axial);
  StrainedSection s{series.engine, &series, {}, {}};
  if (samples.empty())
    return s;
  for (double t : series.times) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < samples.size(); ++k)
      if (std::abs(response.samples[samples[k]].time - t) < std::abs(response.samples[samples[best]].time - t))
        best = k;
    s.strains.push_back(strain[best]);
    const Tensor3 &stress = response.samples[samples[best]].stress;
    Eigen::Matrix2d plane;
    plane << stress(0, 0), stress(0, 2), stress(2, 0), stress(2, 2);
    s.compressive_axes.push_back(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(plane).eigenvectors().col(0));
  }
  return s;
}

std::vector<StateMaps> state_maps(const std::vector<NamedState> &states, const std::vector<StrainedSection> &sections,
                                  const StateMapOptions &o)
{
  static const char *const quantity[3] = {"u_x", "u_z", "gamma (local)"};
  std::vector<StateMaps> out;
  for (const NamedState &state : states) {
    StateMaps m{state, {}};
    if (!state.found) {
      out.push_back(m);
      continue;
    }
    std::vector<MapPanel> located;
    std::vector<std::size_t> recorded(sections.size(), 0);
    for (std::size_t e = 0; e < sections.size(); ++e)
      located.push_back(locate(sections[e], state.strain, o.max_strain_gap, recorded[e]));
    for (int q = 0; q < 3; ++q) {
      MapRow row{quantity[q], q == 2 ? "%" : "mm", located, {}};
      double scale = q == 2 ? std::abs(state.strain) * 100.0 : 0.0;
      std::vector<const std::vector<double> *> fields;
      for (std::size_t e = 0; e < sections.size(); ++e) {
        if (row.panels[e].present)
          fill(row.panels[e], *sections[e].series, recorded[e], q, scale);
        fields.push_back(&row.panels[e].v);
      }
      row.range = shared_colour_range(fields, scale, o.min_relative_range);
      m.rows.push_back(std::move(row));
    }
    out.push_back(std::move(m));
  }
  return out;
}

} // namespace geocomp::compare
