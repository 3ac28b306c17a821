#pragma once
// DEM localization from particle fields: per-particle best-fit affine strain, D2_min, a
// heterogeneity index, its onset along a series of snapshots, and the band orientation.
//
// Local strain (Falk & Langer 1998, PRE 57:7192; DEM-NOTES.md section 9). For particle i
// with reference neighbours j (|X_j - X_i| <= r_c) and separations d0_j = X_j - X_i,
// d_j = x_j - x_i, the affine map minimising sum_j |d_j - F d0_j|^2 is
//     F = (sum_j d_j (x) d0_j) (sum_j d0_j (x) d0_j)^-1,
// its Green-Lagrange strain E = (F^T F - I)/2, the von Mises shear strain
// eta = sqrt(dev E : dev E / 2) (as OVITO), and the non-affine residual
// D2_min = sum_j |d_j - F d0_j|^2 / N_j (mean per neighbour, m^2).
//
// Heterogeneity: the coefficient of variation of eta over the particles with a valid fit
// (or the share of the total eta carried by the top 10 %). Onset: the first snapshot
// whose incremental field (from the previous snapshot) has an index at or above the
// threshold, interpolated in the snapshot's label. Band: particles with eta above
// mean + k SD, split into neighbour-connected clusters; the largest is fitted by a plane
// (PCA: the normal is the eigenvector of the smallest eigenvalue of the position
// covariance). Neighbours come from a uniform cell grid of edge r_c (O(N)).
// The index, the threshold crossing and the band's cluster work on plain values too
// (heterogeneity of values, first_reaching, band_cluster): the FE engines' strain-field
// onset on their recorded mid-planes uses the same ones (SectionLocalization.h).
#include "common/Tensor.h"

#include <cstdint>
#include <string>
#include <vector>

namespace geocomp::compare {

/// Particle centres at one state, with the ids that pair them across states.
struct ParticleSnapshot {
  std::vector<std::int64_t> ids;
  std::vector<Vector3> positions;
  double label = 0.0; ///< what onsets are reported in (e.g. the box gamma_max), any monotone measure
};

struct LocalStrainOptions {
  double radius = 0.0;            ///< neighbour cut-off r_c [m] in the reference state (> 0)
  int min_neighbours = 4;         ///< fewer: no fit (flagged invalid)
  double max_condition = 1e6;     ///< cond(sum d0 d0^T) above this: no fit
};

/// Per-particle fields, aligned with the reference snapshot's order.
struct LocalStrainField {
  std::vector<std::int64_t> ids;
  std::vector<Vector3> reference, current;
  std::vector<Tensor3> F;          ///< best-fit deformation gradient
  std::vector<double> eta;         ///< von Mises shear strain
  std::vector<double> volumetric;  ///< tr E
  std::vector<double> d2min;       ///< non-affine residual per neighbour [m^2]
  std::vector<int> neighbours;
  std::vector<char> valid;
  std::size_t valid_count() const;
};

/// Local strain from `reference` to `current`. Particles missing in `current` are invalid.
/// Throws std::invalid_argument for a non-positive radius or mismatched id/position sizes.
LocalStrainField local_strain(const ParticleSnapshot &reference, const ParticleSnapshot &current,
                              const LocalStrainOptions &options);

/// All pairs of particles closer than `radius` (i < j), found through a cell grid.
std::vector<std::pair<std::size_t, std::size_t>> neighbour_pairs(const std::vector<Vector3> &points,
                                                                 double radius);

enum class HeterogeneityIndex {
  CoefficientOfVariation, ///< SD(eta)/mean(eta)
  TopShare                ///< share of sum(eta) carried by the top 10 % of particles
};

/// Band geometry from one (incremental) field.
struct BandFit {
  bool found = false;
  Vector3 normal = Vector3::Zero();   ///< unit normal of the fitted plane
  Vector3 centroid = Vector3::Zero();
  std::size_t band_particles = 0;     ///< in the fitted cluster
  std::size_t selected = 0;           ///< above the selection threshold
  std::size_t clusters = 0;           ///< clusters with at least min_cluster particles
  double planarity = 0.0;             ///< 1 - lambda_min / lambda_mid (1: a perfect plane)
  Vector3 compressive_axis = Vector3::Zero();   ///< most compressive principal direction used
  Vector3 intermediate_axis = Vector3::Zero();
  double angle_to_compressive_deg = 0.0;  ///< normal vs compressive axis, in [0, 90] (RR theta_0)
  double angle_to_intermediate_deg = 0.0; ///< normal vs intermediate axis, in [0, 90]
};

struct LocalizationOptions {
  LocalStrainOptions strain;
  HeterogeneityIndex index = HeterogeneityIndex::CoefficientOfVariation;
  double threshold = 1.0;        ///< onset when the index reaches this
  double band_sd_factor = 1.5;   ///< band particles: eta > mean + k SD
  double band_top_fraction = 0.1; ///< fallback selection when fewer than min_cluster pass
  std::size_t min_cluster = 10;
  /// Most compressive principal axis of the loading; zero: taken from the global best-fit
  /// affine map of the increment (the eigenvector of its most negative principal strain).
  Vector3 compressive_axis = Vector3::Zero();
  Vector3 intermediate_axis = Vector3::Zero(); ///< zero: the middle principal direction
};

double heterogeneity(const LocalStrainField &field, HeterogeneityIndex index);
/// The index of a field given as its valid values only (the particles', or the points' of a
/// section: SectionLocalization.h); NaN with fewer than 2 values, 0 for an all-zero field.
double heterogeneity(std::vector<double> values, HeterogeneityIndex index);

/// Where an index series first reaches the threshold: `increment` is the first j with
/// index[j] >= threshold, `label` the crossing interpolated linearly between label[j - 1]
/// and label[j] (label[j] itself when j = 0 or index[j - 1] is NaN). Each index belongs to
/// the label at the end of its increment.
struct IndexOnset {
  bool found = false;
  double label = 0.0;
  std::size_t increment = 0;
};
IndexOnset first_reaching(const std::vector<double> &labels, const std::vector<double> &index, double threshold);

/// The band's members in a field: the points with a value above mean + k SD (or the top
/// fraction, at least min_cluster, when fewer pass), split into clusters connected through
/// neighbours within options.strain.radius of their `reference` positions; the largest
/// cluster (empty when it has fewer than min_cluster members).
struct BandCluster {
  std::vector<std::size_t> members; ///< indices into the field
  std::size_t selected = 0;         ///< above the selection threshold
  std::size_t clusters = 0;         ///< clusters with at least min_cluster members
};
BandCluster band_cluster(const std::vector<Vector3> &reference, const std::vector<double> &value,
                         const std::vector<char> &valid, const LocalizationOptions &options);

/// The angle between two lines of directions a and b, in [0, 90] degrees.
double angle_between_lines_deg(const Vector3 &a, const Vector3 &b);

/// Plane through the high-strain particles of a field (band_cluster, then PCA).
BandFit fit_band(const LocalStrainField &field, const LocalizationOptions &options);

struct LocalizationResult {
  std::vector<double> labels;  ///< label of each snapshot after the first
  std::vector<double> index;   ///< heterogeneity of the increment ending there
  bool onset_found = false;
  double onset_label = 0.0;    ///< interpolated crossing of the threshold
  std::size_t onset_snapshot = 0; ///< first snapshot at or above it
  BandFit band;                ///< fitted on the onset increment (or the last one if none)
};

/// Incremental analysis along snapshots (at least 2), each increment from the previous one.
LocalizationResult detect_localization(const std::vector<ParticleSnapshot> &snapshots,
                                       const LocalizationOptions &options);

} // namespace geocomp::compare
