#pragma once
// @sect3{SecantPairs: limited-memory BFGS updates of the Newton step (Matthies & Strang 1979)}
//
// Why it exists: a material whose tangent is only an approximation of the derivative of its
// stress (a DEM cell's contact stiffness at an FE point, continuum/models/PointStateModel.h)
// makes Newton converge linearly, at the rate 1 - K_true/K_tangent of its worst mode; each
// iteration costs a material update of every point. The secant pairs of the iterations of one
// load step carry what the tangent misses:
// $$ s_i = u_{i+1} - u_i,\qquad y_i = R(u_{i+1}) - R(u_i) \approx J s_i , $$
// and the BFGS update of the inverse, taken from the tangent K of the step
// ($H_0 = K^{-1}$, one linear solve),
// $$ H_{i+1} = (I - \rho_i s_i y_i^T) H_i (I - \rho_i y_i s_i^T) + \rho_i s_i s_i^T,\qquad \rho_i = 1/(y_i^T s_i), $$
// makes $H y_i = s_i$ for the latest pairs: along the directions the iterations explored the
// step uses the measured stiffness, elsewhere the tangent's. This is the quasi-Newton method
// Matthies and Strang introduced for nonlinear finite elements (Int. J. Numer. Meth. Eng. 14,
// 1979); the step $H\,(-R)$ is applied by the two-loop recursion of limited-memory BFGS
// (Nocedal 1980) over at most m pairs. A pair with $y^T s \le 10^{-12}|y||s|$ (no positive
// curvature measured along s) is not kept, so H stays positive definite for a positive K.
//
// VectorType: a deal.II distributed vector (operator* is the global dot product, add, sadd).
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

namespace geocomp::continuum {

template <class VectorType>
class SecantPairs {
public:
  explicit SecantPairs(unsigned max_pairs = 0) : max_pairs_(max_pairs) {}

  unsigned capacity() const { return max_pairs_; }
  std::size_t size() const { return pairs_.size(); }
  void clear() { pairs_.clear(); }

  /// Keeps the pair (s, y) when it has positive curvature; the oldest goes beyond capacity.
  /// Returns whether it was kept.
  bool add(const VectorType &s, const VectorType &y)
  {
    if (max_pairs_ == 0)
      return false;
    const double ys = y * s, ns = s.l2_norm(), ny = y.l2_norm();
    if (!(ys > 1e-12 * ns * ny))
      return false;
    if (pairs_.size() == max_pairs_)
      pairs_.pop_front();
    pairs_.push_back({s, y, 1.0 / ys});
    return true;
  }

  /// The step H v for v = -R: `direction` holds v on entry and H v on return;
  /// solve(w) must replace w by K^{-1} w (the linear solve of the tangent).
  template <class Solve>
  void apply(VectorType &direction, Solve solve) const
  {
    std::vector<double> alpha(pairs_.size());
    for (std::size_t k = pairs_.size(); k-- > 0;) {
      const Pair &p = pairs_[k];
      alpha[k] = p.rho * (p.s * direction);
      direction.add(-alpha[k], p.y);
    }
    solve(direction);
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      const Pair &p = pairs_[k];
      const double beta = p.rho * (p.y * direction);
      direction.add(alpha[k] - beta, p.s);
    }
  }

private:
  struct Pair {
    VectorType s, y;
    double rho;
  };
  unsigned max_pairs_;
  std::deque<Pair> pairs_;
};

} // namespace geocomp::continuum
