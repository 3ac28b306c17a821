#pragma once
// Spectral decomposition and the tangent of an isotropic tensor function.
//
// Both plastic models here return in principal stress space: with isotropic elasticity
// and an isotropic yield function the returned stress shares the trial eigenvectors e_i,
// so the return is a map of three principal values, sigma_i = f_i(eps^tr_1..3). Its
// derivative with respect to the tensor eps^tr has two parts (de Souza Neto, Peric & Owen
// 2008, App. A; CONTINUUM-THEORY.md Sec. 1):
//
//   C = sum_ij Dp_ij E_i (x) E_j + sum_{i<j} r_ij N_ij (x) N_ij,
//   E_i = e_i (x) e_i,  N_ij = (e_i (x) e_j + e_j (x) e_i)/sqrt2  (unit in Mandel norm),
//   Dp_ij = d sigma_i / d eps^tr_j,  r_ij = (sigma_i - sigma_j)/(eps^tr_i - eps^tr_j).
//
// The second sum is the eigenvector-rotation (spin) term. When two trial eigenvalues
// coincide r_ij is 0/0; we use its limit r_ij -> Dp_ii - Dp_ij, which holds for any
// symmetric isotropic function (the limiting formula, no perturbation). "Coincide" means
// |eps^tr_i - eps^tr_j| <= coincidence_tolerance * max|eps^tr|.
#include "continuum/models/Mandel.h"

namespace geocomp::continuum {

/// Eigen-decomposition of a symmetric tensor sorted descending: values(0) >= values(1)
/// >= values(2) (tension positive: values(0) is the most tensile), vectors.col(i) the unit
/// eigenvector of values(i).
struct SortedSpectrum {
  Vector3 values;
  Matrix3 vectors;
};

SortedSpectrum sorted_spectrum(const Matrix3 &symmetric);

/// Symmetric tensor sum_i values(i) e_i (x) e_i in Mandel form.
Vector6 assemble_from_principal(const Vector3 &values, const Matrix3 &vectors);

/// The tangent C above in Mandel form.
/// @param[in] vectors trial eigenvectors (columns).
/// @param[in] trial_strain principal trial strains eps^tr_i (any order matching vectors).
/// @param[in] stress principal returned stresses sigma_i (same order).
/// @param[in] principal_tangent Dp_ij = d sigma_i / d eps^tr_j.
Matrix6 isotropic_function_tangent(const Matrix3 &vectors, const Vector3 &trial_strain,
                                   const Vector3 &stress, const Matrix3 &principal_tangent,
                                   double coincidence_tolerance = 1e-9);

/// The same tangent with the spin coefficients given: `spin(i, j)` (i < j) is r_ij. For a
/// function whose ratio (f_i - f_j)/(x_i - x_j) has a closed form that stays accurate as
/// x_i -> x_j (the logarithm of LogarithmicStrain.h), the caller computes it itself.
Matrix6 isotropic_function_tangent(const Matrix3 &vectors, const Matrix3 &principal_tangent,
                                   const Matrix3 &spin);

} // namespace geocomp::continuum
