#pragma once
// The localization onset of an FE engine read off its recorded mid-plane, by the DEM's own
// detection (Localization.h) applied to the section's points instead of particles, so that the
// verdict table has one field-based onset per engine beside the acoustic-tensor scan.
//
// Increments. Between consecutive recorded states k-1 and k the incremental in-plane local
// shear strain of each point,
//     gamma_k(i) = e_1 - e_3 of the best-fit 2-D deformation of i's neighbours
//                  (in_plane_shear_strain, SectionMaps.h) for the displacement u_k - u_{k-1}
//                  from the positions X + u_{k-1} of state k-1,
// as the DEM's increments go from snapshot k-1 to snapshot k. Its heterogeneity index (the
// coefficient of variation by default) over the points with a fit is attached to the strain
// of state k (the curve's measure, StrainedSection); the onset is where the index first
// reaches the DEM's threshold, interpolated linearly between states (first_reaching).
//
// Band, on the onset increment (on the last one when there is none): the points whose gamma_k
// exceeds mean + k SD, their largest cluster of neighbours (band_cluster), fitted by a line in
// the x-z plane - its normal n is the eigenvector of the smaller eigenvalue of the 2 x 2
// covariance of the cluster's positions at state k, its linearity 1 - lambda_min / lambda_max -
// and the angle of n to the most compressive in-plane principal axis of the engine's stress at
// state k, in [0, 90] deg (the convention of Rudnicki-Rice's theta_0).
//
// What the FE point layout does to the index: the points lie 9 to a cut cell on a regular grid
// (spacing h_x / 3, h_z / 3), each standing for the same area, so the index over points is the
// area-weighted one. The Q1 interpolation reproduces an affine field exactly and so does every
// neighbour fit, so a homogeneous increment has an index of round-off (tested), far below the
// threshold. A band holding a fraction f of the points, straining r times faster than the rest,
// has CV = sqrt(f (1 - f)) (r - 1) / (f r + 1 - f), at most sqrt((1 - f) / f) when nothing else
// strains: a band one element wide at 45 deg across the biaxial case's 4 x 8 mesh holds
// f = 0.18 of the points and reaches the threshold 1 at r = 5.9; on a 2 x 4 mesh (f = 0.35) at
// r = 8.9; a band of half the section or more (f >= 0.5) never does.
#include "compare/Localization.h"
#include "compare/SectionMaps.h"
#include "compare/Verdict.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace geocomp::compare {

/// The line through the band's points in the x-z plane.
struct SectionBand {
  bool found = false;
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();   ///< unit normal (x, z)
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero(); ///< at state k [m]
  std::size_t points = 0;    ///< in the fitted cluster
  std::size_t selected = 0;  ///< above the selection threshold
  std::size_t clusters = 0;  ///< with at least min_cluster points
  double linearity = 0.0;    ///< 1 - lambda_min / lambda_max (1: a perfect line)
  bool has_angle = false;    ///< the engine's stress axes were known
  double angle_to_compressive_deg = 0.0;
};

struct SectionLocalization {
  std::vector<double> labels; ///< the strain of each state after the first
  std::vector<double> index;  ///< heterogeneity of the increment ending there
  IndexOnset onset;           ///< onset.increment: index of the onset in `index`
  SectionBand band;
};

/// gamma_k of every point of `series` for the increment from state k - 1 to k (k >= 1); NaN
/// where the fit is impossible.
std::vector<double> incremental_shear_strain(const SectionSeries &series, std::size_t k);

/// The analysis above along a strained section of at least 2 states; `options.strain.radius`
/// is the neighbour radius of the band's clusters (that of the gamma fit is the series').
/// Throws std::invalid_argument for fewer than 2 states or strains that do not match them.
SectionLocalization detect_section_localization(const StrainedSection &section, const LocalizationOptions &options);

/// The verdict table's row: the detection with the DEM's options (LocalizationOptions' defaults:
/// the same index and threshold) and the series' strain radius; not found, with the reason,
/// without a series, with fewer than 2 states or without their strains.
OnsetEstimate strain_field_onset(const StrainedSection &section, const std::string &source);

} // namespace geocomp::compare
