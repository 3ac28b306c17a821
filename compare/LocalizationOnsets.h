#pragma once
// Localization onsets along a Response, for the Rudnicki-Rice verdict table.
//
// Theory (Rudnicki & Rice 1975): a pressure-sensitive dilatant solid with friction mu,
// dilatancy beta and Poisson ratio nu, in a deviatoric state N = s_II / tau, localizes when
// its hardening modulus h = d tau_bar / d gamma^p (at fixed mean stress) falls to
//     h_cr / G = (1 + nu)/9 (beta - mu)^2 / (1 - nu) - (1 + nu)/2 (N + (beta + mu)/3)^2,
// in a band whose normal makes theta_0 with the most compressive axis (continuum/models/
// RudnickiRice.h has the closed form). Along the material-point path of a Mohr-Coulomb
// model we use the Drucker-Prager cone matched to the current c, phi, psi (the same
// matching the Drucker-Prager model uses): tau_bar = Y(kappa) - 3 omega(kappa) p, so
//     h = (dY/dkappa - 3 p d omega/dkappa) / f(psi),
// with f(psi) = gamma^p / kappa the ratio of RR's equivalent plastic shear strain
// sqrt(2 e^p:e^p) to the Mohr-Coulomb kappa = eps1^p - eps3^p on the main plane
// (f = 1 for psi = 0). A Drucker-Prager model's kappa IS gamma^p (DruckerPragerModel.h):
// there f = 1 (KappaMeasure). The predicted onset is the first sample where h - h_cr <= 0.
//
// Onset strains are read in the metrics' measure (Metrics.h): the logarithmic strain of
// the box from the stage start, gamma_max on shear programs, s e_aa on the axial axis.
//
// Engines report their own onsets as the acoustic-tensor indicator
// q = min_n det(n.C_ep.n)/det(n.C_e.n) (extra "localization_q") and the band normal at
// onset ("localization_nx/ny/nz"): the onset is where q first reaches 0.
#include "common/LoadingProgram.h"
#include "common/Response.h"
#include "compare/Metrics.h"
#include "compare/Verdict.h"
#include "continuum/models/DruckerPragerModel.h"
#include "continuum/models/MohrCoulombReturnMap.h"

namespace geocomp::compare {

/// The strain an onset is reported in, for a box strain relative to a reference state:
/// gamma_max of the relative log strain (shear) or sense e_aa on the axial axis.
double onset_strain(const Tensor3 &strain, const Tensor3 &reference, CurveKind kind, const AxialAxis &axial);

/// onset_strain along the main path of `stage` (-1: last), from the stage start, on
/// `axial` (guessed from the response when empty). Also returns the sample indices.
std::vector<double> onset_strain_measure(const Response &r, CurveKind kind, int stage,
                                         std::vector<std::size_t> &samples,
                                         std::optional<AxialAxis> axial = std::nullopt);

/// What a continuum model's hardening variable kappa measures.
enum class KappaMeasure {
  mohr_coulomb, ///< kappa = eps1^p - eps3^p on the main plane: gamma^p = f(psi) kappa
  shear_strain  ///< kappa = gamma^p = sqrt(2 e^p:e^p) (Drucker-Prager): f = 1
};

/// Rudnicki-Rice prediction along a continuum (material-point) Response whose model has
/// hardening variable `measure`.
OnsetEstimate rudnicki_rice_onset(const Response &r, const continuum::MohrCoulombParameters &mc,
                                  continuum::DruckerPragerMatching matching, KappaMeasure measure, CurveKind kind,
                                  int stage = -1, std::optional<AxialAxis> axial = std::nullopt);

/// An engine's own onset from its acoustic-tensor extras (not found if it has none).
OnsetEstimate acoustic_tensor_onset(const Response &r, const std::string &source, CurveKind kind, int stage = -1,
                                    std::optional<AxialAxis> axial = std::nullopt);

} // namespace geocomp::compare
