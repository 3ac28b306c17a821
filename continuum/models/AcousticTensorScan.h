#pragma once
// @sect3{Localization indicator: minimum of the normalized acoustic-tensor determinant}
//
// Why: a shear band can form when the incremental equilibrium equations lose
// ellipticity, i.e. when the acoustic tensor A(n)_ik = n_j C_ijkl n_l of the tangent C
// becomes singular for some unit normal n (Hill 1962; Rice 1976; Rudnicki & Rice 1975).
// We monitor, per quadrature point,
//
//   q(n) = det(n.C_ep.n) / det(n.C_e.n),      q_min = min_{|n|=1} q(n),
//
// which is 1 for elasticity and reaches 0 at the onset of localization; the minimizer is
// the band normal. The normalization by the elastic determinant makes q dimensionless.
//
// Algorithm: q(n) = q(-n), so a coarse scan over a Fibonacci lattice on the upper
// hemisphere finds the basins; from the best few lattice points we refine with a
// Levenberg-regularized Newton method in a tangent chart n(u,v) = normalize(n0 + u t1 + v t2)
// (central-difference gradient and Hessian), which gives the minimizer to ~1e-9 rad.
// Cost: coarse_points + ~40 * candidates determinant evaluations, each ~100 flops.
#include "continuum/models/Mandel.h"

namespace geocomp::continuum {

struct LocalizationResult {
  double min_ratio = 1.0;                   ///< q_min = min_n det(A_ep)/det(A_e)
  Vector3 normal = Vector3::UnitZ();        ///< a minimizing unit normal (sign arbitrary)
  bool localized() const { return min_ratio <= 0.0; }
};

class AcousticTensorScan {
public:
  struct Options {
    int coarse_points = 600;         ///< Fibonacci points on the hemisphere
    int refine_candidates = 4;       ///< number of distinct coarse minima refined
    int max_refine_iterations = 60;
    double fd_step = 1e-4;           ///< chart step for the derivatives [rad]
    double step_tolerance = 1e-11;   ///< stop when the Newton step is below this [rad]
  };

  AcousticTensorScan();
  explicit AcousticTensorScan(Options options);

  /// @param[in] tangent C_ep, Mandel (need not be symmetric).
  /// @param[in] elastic C_e, Mandel.
  LocalizationResult scan(const Matrix6 &tangent, const Matrix6 &elastic) const;

  /// A(n)_ik = n_j C_ijkl n_l.
  static Matrix3 acoustic_tensor(const Matrix6 &C, const Vector3 &n);

  /// q(n) for one normal.
  static double determinant_ratio(const Matrix6 &tangent, const Matrix6 &elastic,
                                  const Vector3 &n);

private:
  Options options_;
};

} // namespace geocomp::continuum
