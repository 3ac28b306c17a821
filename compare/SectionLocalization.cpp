#include "compare/SectionLocalization.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace geocomp::compare {

namespace {
/// The points' positions at state k (X + u_k; the reference position where u_k is unknown).
std::vector<Vector3> positions_at(const SectionSeries &s, std::size_t k)
{
  std::vector<Vector3> p(s.x.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool known = std::isfinite(s.ux[k][i]) && std::isfinite(s.uz[k][i]);
    p[i] = Vector3(s.x[i] + (known ? s.ux[k][i] : 0.0), 0.0, s.z[i] + (known ? s.uz[k][i] : 0.0));
  }
  return p;
}

/// The band of increment k (states k - 1 to k): band_cluster on the positions of state k - 1,
/// a line through the cluster's positions at state k, its normal against the state's axis.
SectionBand fit_section_band(const StrainedSection &s, std::size_t k, const std::vector<double> &gamma,
                             const LocalizationOptions &o)
{
  SectionBand b;
  std::vector<char> valid(gamma.size());
  for (std::size_t i = 0; i < gamma.size(); ++i)
    valid[i] = std::isfinite(gamma[i]);
  const BandCluster cluster = band_cluster(positions_at(*s.series, k - 1), gamma, valid, o);
  b.selected = cluster.selected;
  b.clusters = cluster.clusters;
  if (cluster.members.empty())
    return b;
  const std::vector<Vector3> now = positions_at(*s.series, k);
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (std::size_t i : cluster.members)
    c += Eigen::Vector2d(now[i].x(), now[i].z());
  c /= double(cluster.members.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (std::size_t i : cluster.members) {
    const Eigen::Vector2d d = Eigen::Vector2d(now[i].x(), now[i].z()) - c;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  b.found = true;
  b.normal = eig.eigenvectors().col(0).normalized();
  b.centroid = c;
  b.points = cluster.members.size();
  b.linearity = eig.eigenvalues()[1] > 0.0 ? 1.0 - eig.eigenvalues()[0] / eig.eigenvalues()[1] : 0.0;
  if (k < s.compressive_axes.size() && s.compressive_axes[k].squaredNorm() > 0.0) {
    const Eigen::Vector2d &a = s.compressive_axes[k];
    b.has_angle = true;
    b.angle_to_compressive_deg =
      angle_between_lines_deg(Vector3(b.normal.x(), 0.0, b.normal.y()), Vector3(a.x(), 0.0, a.y()));
  }
  return b;
}
} // namespace

std::vector<double> incremental_shear_strain(const SectionSeries &s, std::size_t k)
{
  const std::vector<Vector3> from = positions_at(s, k - 1);
  const std::size_t n = s.x.size();
  std::vector<double> x(n), z(n), dux(n), duz(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = from[i].x();
    z[i] = from[i].z();
    dux[i] = s.ux[k][i] - s.ux[k - 1][i]; // NaN where either state lacks the point
    duz[i] = s.uz[k][i] - s.uz[k - 1][i];
  }
  return in_plane_shear_strain(x, z, dux, duz, s.strain_radius);
}

SectionLocalization detect_section_localization(const StrainedSection &s, const LocalizationOptions &o)
{
  if (!s.series || s.series->times.size() < 2)
    throw std::invalid_argument("a strain-field onset needs a section of at least 2 recorded states");
  const SectionSeries &series = *s.series;
  if (s.strains.size() != series.times.size() || series.ux.size() != series.times.size() ||
      series.uz.size() != series.times.size())
    throw std::invalid_argument("section " + series.engine + ": strains, displacements and states do not match");
  SectionLocalization r;
  std::vector<std::vector<double>> gamma(series.times.size()); // of each increment (kB for a mesh)
  for (std::size_t k = 1; k < series.times.size(); ++k) {
    gamma[k] = incremental_shear_strain(series, k);
    std::vector<double> fitted;
    std::copy_if(gamma[k].begin(), gamma[k].end(), std::back_inserter(fitted), [](double g) { return std::isfinite(g); });
    r.labels.push_back(s.strains[k]);
    r.index.push_back(heterogeneity(std::move(fitted), o.index));
  }
  r.onset = first_reaching(r.labels, r.index, o.threshold);
  const std::size_t k = r.onset.found ? r.onset.increment + 1 : series.times.size() - 1;
  r.band = fit_section_band(s, k, gamma[k], o);
  return r;
}

OnsetEstimate strain_field_onset(const StrainedSection &s, const std::string &source)
{
  OnsetEstimate e;
  e.source = source;
  e.has_angle = false;
  if (!s.series || s.series->times.size() < 2 || s.strains.size() != s.series->times.size()) {
    e.note = !s.series                      ? "no mid-plane recorded"
             : s.series->times.size() < 2 ? "fewer than two recorded mid-plane states"
                                            : "no strains for the recorded mid-plane states (no main-path samples)";
    return e;
  }
  LocalizationOptions o;
  o.strain.radius = s.series->strain_radius;
  const SectionLocalization r = detect_section_localization(s, o);
  e.found = r.onset.found;
  e.strain = r.onset.label;
  e.has_angle = r.band.found && r.band.has_angle;
  e.angle_deg = r.band.angle_to_compressive_deg;
  double largest = 0.0, largest_at = 0.0;
  for (std::size_t i = 0; i < r.index.size(); ++i)
    if (std::isfinite(r.index[i]) && r.index[i] > largest) {
      largest = r.index[i];
      largest_at = r.labels[i];
    }
  std::ostringstream note;
  note << s.series->times.size() << " mid-plane states of " << s.series->x.size()
       << " points; heterogeneity index (CV of the incremental in-plane local shear strain) up to " << largest
       << " (at " << 100.0 * largest_at << " %), threshold " << o.threshold;
  if (r.band.found)
    note << "; band of " << r.band.points << " points" << (r.onset.found ? "" : " (last increment)")
         << ", linearity " << r.band.linearity;
  e.note = note.str();
  return e;
}

} // namespace geocomp::compare
