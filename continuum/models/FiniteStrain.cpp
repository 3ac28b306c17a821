#include "continuum/models/FiniteStrain.h"

#include "continuum/models/PointStateModel.h"
#include "continuum/models/SpectralDecomposition.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geocomp::continuum {

namespace {
/// sum_i f(x_i) v_i (x) v_i of a symmetric tensor's spectrum.
template <class Function>
Matrix3 spectral_map(const SortedSpectrum &s, Function f)
{
  Matrix3 out = Matrix3::Zero();
  for (int i = 0; i < 3; ++i)
    out += f(s.values(i)) * s.vectors.col(i) * s.vectors.col(i).transpose();
  return out;
}

/// L = d ln b / d b at b = sum x_i v_i (x) v_i, Mandel. Diagonal part 1/x_i; spin
/// coefficients (ln x_i - ln x_j)/(x_i - x_j) through log1p, exact in the limit x_i -> x_j.
Matrix6 log_tangent(const SortedSpectrum &b)
{
  const Vector3 &x = b.values;
  Matrix3 diagonal = Matrix3::Zero(), spin = Matrix3::Zero();
  for (int i = 0; i < 3; ++i)
    diagonal(i, i) = 1.0 / x(i);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double d = x(i) - x(j);
      spin(i, j) = d == 0.0 ? 1.0 / x(j) : std::log1p(d / x(j)) / d;
    }
  return isotropic_function_tangent(b.vectors, diagonal, spin);
}

/// J a = 1/2 (D : L) : B - tau_il delta_jk (file comment of FiniteStrain.h), column 3k+l
/// from the perturbation H = e_k (x) e_l: d b = H b + b H^T.
Matrix9 spatial_tangent(const Matrix6 &D_L, const Matrix3 &b_trial, const Matrix3 &tau)
{
  Matrix9 a;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      Matrix3 db = Matrix3::Zero();
      db.row(k) += b_trial.row(l);
      db.col(k) += b_trial.col(l);
      Matrix3 column = 0.5 * from_mandel(D_L * to_mandel(db)); // first term
      column.col(k) -= tau.col(l);                            // - tau_il delta_jk
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          a(pair_index(i, j), pair_index(k, l)) = column(i, j);
    }
  return a;
}
} // namespace

const char *to_string(Kinematics kinematics)
{
  return kinematics == Kinematics::finite_strain ? "finite strain" : "small strain";
}

Kinematics parse_kinematics(const std::string &text)
{
  if (text == "finite strain")
    return Kinematics::finite_strain;
  if (text == "small strain")
    return Kinematics::small_strain;
  throw std::invalid_argument("kinematics '" + text + "': expected 'finite strain' or 'small strain'");
}

Matrix3 symmetric_log(const Matrix3 &spd)
{
  return spectral_map(sorted_spectrum(spd), [](double x) { return std::log(x); });
}

Matrix3 symmetric_exp(const Matrix3 &symmetric)
{
  return spectral_map(sorted_spectrum(symmetric), [](double x) { return std::exp(x); });
}

Matrix3 FiniteStrainUpdate::elastic_log_strain() const
{
  return 0.5 * symmetric_log(history.elastic_left_cauchy_green);
}

FiniteStrainUpdate finite_strain_update(const ConstitutiveModel &model, const Matrix3 &F,
                                        const FiniteStrainHistory &old)
{
  const double J = F.determinant();
  if (!(J > 0.0) || !std::isfinite(J)) {
    std::ostringstream msg;
    msg << "finite strain: det F = " << J << " (an inverted or degenerate point)";
    throw ReturnMapFailure(msg.str());
  }
  if (const auto *point = dynamic_cast<const PointStateModel *>(&model))
    return point->advance_finite(F, old);
  // Elastic predictor (DSPO ch. 14): b^e_trial = F_inc b^e_n F_inc^T.
  const Matrix3 F_inc = F * old.deformation_gradient.inverse();
  const Matrix3 b_trial = F_inc * old.elastic_left_cauchy_green * F_inc.transpose();
  const SortedSpectrum spectrum = sorted_spectrum(b_trial);
  if (!(spectrum.values(2) > 0.0))
    throw ReturnMapFailure("finite strain: the trial b^e is not positive definite");
  const Vector3 eps_principal = 0.5 * spectrum.values.array().log().matrix();
  const Vector6 eps_trial = assemble_from_principal(eps_principal, spectrum.vectors);

  // The small-strain return "as if small strain" on the logarithmic trial strain.
  PlasticHistory small;
  small.kappa = old.kappa;
  const MaterialPointUpdate u = model.update(eps_trial, small);

  FiniteStrainUpdate out;
  out.kirchhoff_stress = from_mandel(u.stress);
  out.jacobian = J;
  out.logarithmic_tangent = u.tangent;
  out.region = u.region;
  out.trial_yield_value = u.trial_yield_value;
  out.local_iterations = u.local_iterations;
  out.history.deformation_gradient = F;
  out.history.kappa = u.history.kappa;
  if (u.region == ReturnRegion::elastic) {
    out.history.elastic_left_cauchy_green = 0.5 * (b_trial + b_trial.transpose());
  } else {
    // Exponential map: b^e_{n+1} = exp(2 eps^e_{n+1}) on the trial eigenvectors (the return
    // is coaxial with the trial), eps^e_{n+1} = eps^e_trial - Delta eps^p.
    const Matrix3 eps_e = from_mandel(eps_trial - u.history.plastic_strain);
    Vector3 e;
    for (int i = 0; i < 3; ++i)
      e(i) = spectrum.vectors.col(i).dot(eps_e * spectrum.vectors.col(i));
    SortedSpectrum elastic{e, spectrum.vectors};
    out.history.elastic_left_cauchy_green = spectral_map(elastic, [](double x) { return std::exp(2.0 * x); });
  }
  out.spatial_tangent = spatial_tangent(u.tangent * log_tangent(spectrum), b_trial, out.kirchhoff_stress);
  return out;
}

FiniteStrainHistory initial_finite_strain_history(const ConstitutiveModel &model, const Matrix3 &initial_stress)
{
  FiniteStrainHistory h;
  if (const auto *point = dynamic_cast<const PointStateModel *>(&model)) {
    h.state = point->initial_state(Vector6::Zero());
    return h;
  }
  const Matrix3 eps_e = from_mandel(model.elasticity().compliance() * to_mandel(initial_stress));
  h.elastic_left_cauchy_green = symmetric_exp(2.0 * eps_e);
  return h;
}

} // namespace geocomp::continuum
