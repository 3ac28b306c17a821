#include "compare/Localization.h"
#include "compare/Metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace geocomp::compare {

namespace {
constexpr double rad2deg = 180.0 / 3.14159265358979323846;

/// Uniform cell grid over the bounding box, cell edge >= h, particles sorted by cell
/// (counting sort). A query visits the 27 cells around a point: every point within h.
class CellGrid {
public:
  CellGrid(const std::vector<Vector3> &points, double h) : points_(points)
  {
    lo_ = Vector3::Constant(0.0);
    Vector3 hi = lo_;
    if (!points.empty()) {
      lo_ = points.front();
      hi = lo_;
      for (const auto &p : points) {
        lo_ = lo_.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
    // Keep the number of cells O(N) even for a small h in a large box.
    const double n_max = 8.0 * static_cast<double>(points.size()) + 64.0;
    h_ = h;
    for (;;) {
      double total = 1.0;
      for (int k = 0; k < 3; ++k) {
        n_[k] = static_cast<long>(std::floor((hi[k] - lo_[k]) / h_)) + 1;
        total *= static_cast<double>(n_[k]);
      }
      if (total <= n_max)
        break;
      h_ *= std::cbrt(total / n_max) * 1.01;
    }
    start_.assign(static_cast<std::size_t>(n_[0] * n_[1] * n_[2]) + 1, 0);
    cell_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      cell_[i] = index(coords(points[i]));
      ++start_[cell_[i] + 1];
    }
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    order_.resize(points.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
      order_[fill[cell_[i]]++] = i;
  }

  /// Calls f(j) for every point j within `radius` (<= h) of point i, j != i.
  template <class F> void for_neighbours(std::size_t i, double radius, F &&f) const
  {
    const auto c = coords(points_[i]);
    const double r2 = radius * radius;
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const std::array<long, 3> d{c[0] + dx, c[1] + dy, c[2] + dz};
          if (d[0] < 0 || d[1] < 0 || d[2] < 0 || d[0] >= n_[0] || d[1] >= n_[1] || d[2] >= n_[2])
            continue;
          const std::size_t cell = index(d);
          for (std::size_t k = start_[cell]; k < start_[cell + 1]; ++k) {
            const std::size_t j = order_[k];
            if (j != i && (points_[j] - points_[i]).squaredNorm() <= r2)
              f(j);
          }
        }
  }

private:
  std::array<long, 3> coords(const Vector3 &p) const
  {
    std::array<long, 3> c{};
    for (int k = 0; k < 3; ++k)
      c[k] = std::clamp(static_cast<long>(std::floor((p[k] - lo_[k]) / h_)), 0L, n_[k] - 1);
    return c;
  }
  std::size_t index(const std::array<long, 3> &c) const
  {
    return static_cast<std::size_t>((c[2] * n_[1] + c[1]) * n_[0] + c[0]);
  }

  const std::vector<Vector3> &points_;
  Vector3 lo_;
  double h_ = 1.0;
  std::array<long, 3> n_{1, 1, 1};
  std::vector<std::size_t> start_, order_, cell_;
};

void check_snapshot(const ParticleSnapshot &s, const char *what)
{
  if (s.ids.size() != s.positions.size())
    throw std::invalid_argument(std::string(what) + " snapshot: " + std::to_string(s.ids.size()) +
                                " ids but " + std::to_string(s.positions.size()) + " positions");
}

/// Index in `current` of each reference particle (-1 when absent).
std::vector<long> match(const ParticleSnapshot &reference, const ParticleSnapshot &current)
{
  std::vector<long> m(reference.ids.size(), -1);
  if (reference.ids == current.ids) {
    std::iota(m.begin(), m.end(), 0L);
    return m;
  }
  std::unordered_map<std::int64_t, long> where;
  where.reserve(current.ids.size());
  for (std::size_t i = 0; i < current.ids.size(); ++i)
    where[current.ids[i]] = static_cast<long>(i);
  for (std::size_t i = 0; i < reference.ids.size(); ++i) {
    const auto it = where.find(reference.ids[i]);
    if (it != where.end())
      m[i] = it->second;
  }
  return m;
}

/// Global best-fit affine map of all valid particles about their centroids.
Tensor3 global_deformation(const LocalStrainField &f)
{
  Vector3 c0 = Vector3::Zero(), c = Vector3::Zero();
  std::size_t n = 0;
  for (std::size_t i = 0; i < f.ids.size(); ++i)
    if (f.valid[i]) {
      c0 += f.reference[i];
      c += f.current[i];
      ++n;
    }
  if (n < 4)
    return Tensor3::Identity();
  c0 /= double(n);
  c /= double(n);
  Tensor3 X = Tensor3::Zero(), Y = Tensor3::Zero();
  for (std::size_t i = 0; i < f.ids.size(); ++i)
    if (f.valid[i]) {
      const Vector3 d0 = f.reference[i] - c0, d = f.current[i] - c;
      X += d * d0.transpose();
      Y += d0 * d0.transpose();
    }
  return X * Y.inverse();
}

} // namespace

double angle_between_lines_deg(const Vector3 &a, const Vector3 &b)
{
  const double c = std::abs(a.normalized().dot(b.normalized()));
  return std::acos(std::min(1.0, c)) * rad2deg;
}

std::size_t LocalStrainField::valid_count() const
{
  return static_cast<std::size_t>(std::count(valid.begin(), valid.end(), char(1)));
}

std::vector<std::pair<std::size_t, std::size_t>> neighbour_pairs(const std::vector<Vector3> &points,
                                                                 double radius)
{
  if (!(radius > 0.0))
    throw std::invalid_argument("neighbour radius must be > 0");
  std::vector<std::pair<std::size_t, std::size_t>> out;
  const CellGrid grid(points, radius);
  for (std::size_t i = 0; i < points.size(); ++i)
    grid.for_neighbours(i, radius, [&](std::size_t j) {
      if (j > i)
        out.emplace_back(i, j);
    });
  return out;
}

LocalStrainField local_strain(const ParticleSnapshot &reference, const ParticleSnapshot &current,
                              const LocalStrainOptions &o)
{
  if (!(o.radius > 0.0))
    throw std::invalid_argument("local strain: neighbour radius must be > 0");
  check_snapshot(reference, "reference");
  check_snapshot(current, "current");
  const std::size_t n = reference.ids.size();
  const std::vector<long> m = match(reference, current);

  LocalStrainField f;
  f.ids = reference.ids;
  f.reference = reference.positions;
  f.current.resize(n, Vector3::Constant(nan));
  f.F.assign(n, Tensor3::Identity());
  f.eta.assign(n, 0.0);
  f.volumetric.assign(n, 0.0);
  f.d2min.assign(n, 0.0);
  f.neighbours.assign(n, 0);
  f.valid.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (m[i] >= 0)
      f.current[i] = current.positions[m[i]];

  const CellGrid grid(reference.positions, o.radius);
  std::vector<std::size_t> nb;
  for (std::size_t i = 0; i < n; ++i) {
    if (m[i] < 0)
      continue;
    nb.clear();
    grid.for_neighbours(i, o.radius, [&](std::size_t j) {
      if (m[j] >= 0)
        nb.push_back(j);
    });
    f.neighbours[i] = static_cast<int>(nb.size());
    if (static_cast<int>(nb.size()) < o.min_neighbours)
      continue;
    Tensor3 X = Tensor3::Zero(), Y = Tensor3::Zero();
    for (std::size_t j : nb) {
      const Vector3 d0 = reference.positions[j] - reference.positions[i];
      const Vector3 d = f.current[j] - f.current[i];
      X += d * d0.transpose();
      Y += d0 * d0.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Tensor3> eig(Y, Eigen::EigenvaluesOnly);
    const Vector3 l = eig.eigenvalues();
    if (!(l[0] > 0.0) || l[2] / l[0] > o.max_condition)
      continue;
    const Tensor3 F = X * Y.inverse();
    double r2 = 0.0;
    for (std::size_t j : nb) {
      const Vector3 d0 = reference.positions[j] - reference.positions[i];
      const Vector3 d = f.current[j] - f.current[i];
      r2 += (d - F * d0).squaredNorm();
    }
    const Tensor3 E = 0.5 * (F.transpose() * F - Tensor3::Identity());
    const Tensor3 dev = E - E.trace() / 3.0 * Tensor3::Identity();
    f.F[i] = F;
    f.eta[i] = std::sqrt(0.5 * (dev.array() * dev.array()).sum());
    f.volumetric[i] = E.trace();
    f.d2min[i] = r2 / static_cast<double>(nb.size());
    f.valid[i] = 1;
  }
  return f;
}

double heterogeneity(const LocalStrainField &f, HeterogeneityIndex index)
{
  std::vector<double> v;
  for (std::size_t i = 0; i < f.eta.size(); ++i)
    if (f.valid[i])
      v.push_back(f.eta[i]);
  return heterogeneity(std::move(v), index);
}

double heterogeneity(std::vector<double> v, HeterogeneityIndex index)
{
  if (v.size() < 2)
    return nan;
  const double sum = std::accumulate(v.begin(), v.end(), 0.0);
  if (!(sum > 0.0))
    return 0.0;
  if (index == HeterogeneityIndex::TopShare) {
    const std::size_t top = std::max<std::size_t>(1, (v.size() + 9) / 10);
    std::nth_element(v.begin(), v.begin() + (top - 1), v.end(), std::greater<double>());
    return std::accumulate(v.begin(), v.begin() + top, 0.0) / sum;
  }
  const double mean = sum / v.size();
  double var = 0.0;
  for (double x : v)
    var += (x - mean) * (x - mean);
  return std::sqrt(var / v.size()) / mean;
}

IndexOnset first_reaching(const std::vector<double> &labels, const std::vector<double> &index, double threshold)
{
  IndexOnset o;
  for (std::size_t j = 0; j < index.size() && j < labels.size(); ++j) {
    if (!(index[j] >= threshold))
      continue;
    o.found = true;
    o.increment = j;
    if (j == 0 || !std::isfinite(index[j - 1]))
      o.label = labels[j];
    else {
      const double t = (threshold - index[j - 1]) / (index[j] - index[j - 1]);
      o.label = labels[j - 1] + std::clamp(t, 0.0, 1.0) * (labels[j] - labels[j - 1]);
    }
    break;
  }
  return o;
}

BandCluster band_cluster(const std::vector<Vector3> &reference, const std::vector<double> &value,
                         const std::vector<char> &valid_flags, const LocalizationOptions &o)
{
  BandCluster b;
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < value.size(); ++i)
    if (valid_flags[i])
      valid.push_back(i);
  if (valid.size() < o.min_cluster)
    return b;
  double mean = 0.0, var = 0.0;
  for (std::size_t i : valid)
    mean += value[i];
  mean /= valid.size();
  for (std::size_t i : valid)
    var += (value[i] - mean) * (value[i] - mean);
  const double threshold = mean + o.band_sd_factor * std::sqrt(var / valid.size());
  std::vector<std::size_t> sel;
  for (std::size_t i : valid)
    if (value[i] > threshold)
      sel.push_back(i);
  if (sel.size() < o.min_cluster) { // fallback: the top fraction
    sel = valid;
    const std::size_t top =
      std::max(o.min_cluster, static_cast<std::size_t>(std::ceil(o.band_top_fraction * valid.size())));
    std::nth_element(sel.begin(), sel.begin() + (std::min(top, sel.size()) - 1), sel.end(),
                     [&](std::size_t a, std::size_t c) { return value[a] > value[c]; });
    sel.resize(std::min(top, sel.size()));
  }
  b.selected = sel.size();

  // Clusters: connected components of the selected points' reference neighbour graph.
  std::vector<Vector3> pts;
  for (std::size_t i : sel)
    pts.push_back(reference[i]);
  std::vector<std::size_t> parent(sel.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::size_t a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const auto &[a, c] : neighbour_pairs(pts, o.strain.radius))
    parent[root(a)] = root(c);
  std::unordered_map<std::size_t, std::vector<std::size_t>> clusters;
  for (std::size_t k = 0; k < sel.size(); ++k)
    clusters[root(k)].push_back(k);
  const std::vector<std::size_t> *largest = nullptr;
  for (const auto &[r, members] : clusters) {
    if (members.size() >= o.min_cluster)
      ++b.clusters;
    if (!largest || members.size() > largest->size())
      largest = &members;
  }
  if (!largest || largest->size() < o.min_cluster)
    return b;
  for (std::size_t k : *largest)
    b.members.push_back(sel[k]);
  return b;
}

BandFit fit_band(const LocalStrainField &f, const LocalizationOptions &o)
{
  BandFit b;
  const BandCluster cluster = band_cluster(f.reference, f.eta, f.valid, o);
  b.selected = cluster.selected;
  b.clusters = cluster.clusters;
  if (cluster.members.empty())
    return b;

  // PCA of the current positions of the largest cluster.
  Vector3 c = Vector3::Zero();
  for (std::size_t i : cluster.members)
    c += f.current[i];
  c /= double(cluster.members.size());
  Tensor3 cov = Tensor3::Zero();
  for (std::size_t i : cluster.members) {
    const Vector3 d = f.current[i] - c;
    cov += d * d.transpose();
  }
  cov /= double(cluster.members.size());
  Eigen::SelfAdjointEigenSolver<Tensor3> eig(cov);
  b.found = true;
  b.normal = eig.eigenvectors().col(0).normalized();
  b.centroid = c;
  b.band_particles = cluster.members.size();
  b.planarity = eig.eigenvalues()[1] > 0.0 ? 1.0 - eig.eigenvalues()[0] / eig.eigenvalues()[1] : 0.0;

  // Principal axes of the loading: given, or from the global affine map of the increment.
  const Tensor3 G = global_deformation(f);
  Eigen::SelfAdjointEigenSolver<Tensor3> axes(0.5 * (G + G.transpose()));
  b.compressive_axis = o.compressive_axis.squaredNorm() > 0.0 ? Vector3(o.compressive_axis.normalized())
                                                              : Vector3(axes.eigenvectors().col(0));
  b.intermediate_axis = o.intermediate_axis.squaredNorm() > 0.0 ? Vector3(o.intermediate_axis.normalized())
                                                                : Vector3(axes.eigenvectors().col(1));
  b.angle_to_compressive_deg = angle_between_lines_deg(b.normal, b.compressive_axis);
  b.angle_to_intermediate_deg = angle_between_lines_deg(b.normal, b.intermediate_axis);
  return b;
}

LocalizationResult detect_localization(const std::vector<ParticleSnapshot> &snapshots,
                                       const LocalizationOptions &o)
{
  if (snapshots.size() < 2)
    throw std::invalid_argument("localization needs at least 2 snapshots");
  LocalizationResult r;
  for (std::size_t k = 1; k < snapshots.size(); ++k) {
    r.labels.push_back(snapshots[k].label);
    r.index.push_back(heterogeneity(local_strain(snapshots[k - 1], snapshots[k], o.strain), o.index));
  }
  const IndexOnset onset = first_reaching(r.labels, r.index, o.threshold);
  r.onset_found = onset.found;
  r.onset_label = onset.label;
  // The band on the onset increment, or on the last one when there is no onset.
  const std::size_t k = onset.found ? onset.increment + 1 : snapshots.size() - 1;
  if (onset.found)
    r.onset_snapshot = k;
  r.band = fit_band(local_strain(snapshots[k - 1], snapshots[k], o.strain), o);
  return r;
}

} // namespace geocomp::compare
