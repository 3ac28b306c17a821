#include "continuum/models/AcousticTensorScan.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace geocomp::continuum {

namespace {

// Full fourth-order components C[i][j][k][l] from a Mandel matrix, unpacked once per scan.
struct Tensor4 {
  std::array<double, 81> c{};
  explicit Tensor4(const Matrix6 &C) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            c[27 * i + 9 * j + 3 * k + l] = tensor4_component(C, i, j, k, l);
  }
  Matrix3 acoustic(const Vector3 &n) const {
    Matrix3 A = Matrix3::Zero();
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        double a = 0.0;
        for (int j = 0; j < 3; ++j)
          for (int l = 0; l < 3; ++l)
            a += n(j) * c[27 * i + 9 * j + 3 * k + l] * n(l);
        A(i, k) = a;
      }
    return A;
  }
};

struct Ratio {
  const Tensor4 &ep, &e;
  double operator()(const Vector3 &n) const {
    return ep.acoustic(n).determinant() / e.acoustic(n).determinant();
  }
};

// Orthonormal t1, t2 with n.
void tangent_basis(const Vector3 &n, Vector3 &t1, Vector3 &t2) {
  const Vector3 a = std::abs(n(0)) < 0.9 ? Vector3::UnitX() : Vector3::UnitY();
  t1 = (a - a.dot(n) * n).normalized();
  t2 = n.cross(t1);
}

// Local minimization of q on the sphere from n0 (see the header).
Vector3 refine(const Ratio &q, Vector3 n, double &qn, const AcousticTensorScan::Options &o) {
  const double h = o.fd_step;
  qn = q(n);
  for (int it = 0; it < o.max_refine_iterations; ++it) {
    Vector3 t1, t2;
    tangent_basis(n, t1, t2);
    auto f = [&](double u, double v) { return q((n + u * t1 + v * t2).normalized()); };
    const double fpp = f(h, h), fpm = f(h, -h), fmp = f(-h, h), fmm = f(-h, -h);
    const double fp0 = f(h, 0), fm0 = f(-h, 0), f0p = f(0, h), f0m = f(0, -h);
    const Eigen::Vector2d g((fp0 - fm0) / (2 * h), (f0p - f0m) / (2 * h));
    Eigen::Matrix2d H;
    H(0, 0) = (fp0 - 2 * qn + fm0) / (h * h);
    H(1, 1) = (f0p - 2 * qn + f0m) / (h * h);
    H(0, 1) = H(1, 0) = (fpp - fpm - fmp + fmm) / (4 * h * h);
    // Levenberg shift keeps the step a descent direction where H is indefinite.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(H);
    const double lmin = es.eigenvalues()(0), lmax = std::abs(es.eigenvalues()(1));
    const double shift = lmin > 1e-8 * std::max(lmax, 1e-300) ? 0.0 : -lmin + 1e-6 * std::max(lmax, 1.0);
    Eigen::Vector2d d = -(H + shift * Eigen::Matrix2d::Identity()).ldlt().solve(g);
    if (!d.allFinite())
      break;
    const double max_step = 0.2;
    if (d.norm() > max_step)
      d *= max_step / d.norm();
    // Backtracking: accept the first step that does not increase q.
    bool accepted = false;
    for (int k = 0; k < 30; ++k) {
      const Vector3 trial = (n + d(0) * t1 + d(1) * t2).normalized();
      const double qt = q(trial);
      if (qt <= qn) {
        n = trial;
        qn = qt;
        accepted = true;
        break;
      }
      d *= 0.5;
    }
    if (!accepted || d.norm() < o.step_tolerance)
      break;
  }
  return n;
}

} // namespace

AcousticTensorScan::AcousticTensorScan() : options_() {}
AcousticTensorScan::AcousticTensorScan(Options options) : options_(options) {}

Matrix3 AcousticTensorScan::acoustic_tensor(const Matrix6 &C, const Vector3 &n) {
  return Tensor4(C).acoustic(n);
}

double AcousticTensorScan::determinant_ratio(const Matrix6 &tangent, const Matrix6 &elastic,
                                             const Vector3 &n) {
  const Tensor4 ep(tangent), e(elastic);
  return Ratio{ep, e}(n.normalized());
}

LocalizationResult AcousticTensorScan::scan(const Matrix6 &tangent, const Matrix6 &elastic) const {
  const Tensor4 ep(tangent), e(elastic);
  const Ratio q{ep, e};

  // Coarse: Fibonacci lattice on the hemisphere z >= 0.
  const int N = std::max(options_.coarse_points, 8);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<std::pair<double, Vector3>> samples;
  samples.reserve(N);
  for (int i = 0; i < N; ++i) {
    const double z = (i + 0.5) / N; // uniform in z on [0,1] = uniform area on the hemisphere
    const double r = std::sqrt(1.0 - z * z);
    const Vector3 n(r * std::cos(golden * i), r * std::sin(golden * i), z);
    samples.emplace_back(q(n), n);
  }
  std::sort(samples.begin(), samples.end(),
            [](const auto &a, const auto &b) { return a.first < b.first; });

  // Refine from the best candidates that are not close to an already chosen one.
  const double spacing = std::sqrt(2.0 * M_PI / N); // typical lattice spacing [rad]
  std::vector<Vector3> starts;
  for (const auto &s : samples) {
    if (static_cast<int>(starts.size()) >= options_.refine_candidates)
      break;
    bool distinct = true;
    for (const Vector3 &t : starts)
      if (std::abs(s.second.dot(t)) > std::cos(3.0 * spacing))
        distinct = false;
    if (distinct)
      starts.push_back(s.second);
  }

  LocalizationResult best;
  best.min_ratio = samples.front().first;
  best.normal = samples.front().second;
  for (const Vector3 &n0 : starts) {
    double qn;
    const Vector3 n = refine(q, n0, qn, options_);
    if (qn < best.min_ratio) {
      best.min_ratio = qn;
      best.normal = n;
    }
  }
  return best;
}

} // namespace geocomp::continuum
