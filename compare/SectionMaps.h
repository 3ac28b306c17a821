#pragma once
// Maps of the mid-section y = L0/2 at the named states (NamedStates.h), one panel per engine
// that recorded a section (DEM | FE cube | FEM x DEM) side by side at the same strain (S0
// Fig. 3-5), built the same way from every engine's section.
//
// A section series is what an engine recorded on its mid-section at every main-path sample of
// the analysed stage: points with reference in-plane coordinates X = (x, z) and, per sample,
// their displacements u since the first sample (DEM: the particles whose centres lie in the
// slab |y - L0/2| <= 2 mean radii; FE: points of the cells of the cube or box cut by the plane
// y = L_y/2, either FE engine's).
//
// One displacement reference for every engine: the displacement of the box centre X_c,
// estimated from the section's own field by the least-squares affine fit
//     u(X) ~ a + G (X - X_bar)   over the section's points,    u_c = a + G (X_c - X_bar),
// and subtracted from every point: exact for any affine field whatever the points' layout
// (a rigid translation maps to zero; a homogeneous deformation to the same field about the
// centre in every engine), and independent of which faces an engine holds (the DEM's
// platens move about the centre, the FE cube's rollers hold the x = 0 and z = 0 faces).
//
// Local strain, the same measure in every engine: at each point, the best-fit in-plane
// deformation gradient of its neighbours within r_c (Falk & Langer's fit, Localization.h, in
// two dimensions), F = (sum d d0^T)(sum d0 d0^T)^-1, its Green-Lagrange strain
// E = (F^T F - I)/2, and the in-plane maximum shear strain
//     gamma = e_1 - e_3 = sqrt((E_xx - E_zz)^2 + 4 E_xz^2),
// the box's gamma_max on a plane deformation. NaN where fewer than 3 neighbours or a
// degenerate neighbourhood.
//
// One colour scale per row: the panels of a quantity share one range, the union of their
// values, widened to at least `min_relative` of the row's scale (the largest |value|, and
// for displacements at least the largest displacement before the reference was subtracted,
// for strains the state's box strain), so a homogeneous field shows as one colour rather than
// a pattern of round-off.
#include "compare/NamedStates.h"
#include "common/Response.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace geocomp::compare {

struct SectionSeries {
  std::string engine;                       ///< "DEM", "FE cube", "FEM x DEM"
  std::vector<double> x, z;                 ///< reference in-plane coordinates [m]
  double centre_x = 0.0, centre_z = 0.0;    ///< the box centre in the reference state [m]
  double strain_radius = 0.0;               ///< r_c of the local strain fit [m]
  double marker = 0.0;                      ///< half-size of a point in the maps [m]: a particle's radius, half a tile's width
  double marker_z = 0.0;                    ///< half a tile's height [m] (tiles only)
  bool tiles = false;                       ///< points tile the plane (FE, rectangles) or are particles (DEM, discs)
  std::vector<double> times;                ///< program time of each recorded state [s]
  std::vector<std::vector<double>> ux, uz;  ///< per state: displacement since the first state [m]
};

/// The box-centre displacement of a section field (the affine fit above, in one component).
double centre_displacement(const std::vector<double> &x, const std::vector<double> &z, const std::vector<double> &u,
                           double centre_x, double centre_z);

/// In-plane maximum shear strain gamma at each point (NaN where the fit is impossible).
std::vector<double> in_plane_shear_strain(const std::vector<double> &x, const std::vector<double> &z,
                                          const std::vector<double> &ux, const std::vector<double> &uz,
                                          double radius);

struct ColourRange {
  double low = 0.0, high = 0.0; ///< in the values' units
};
/// One range over several fields (NaNs ignored), at least `min_relative` * max(largest |value|,
/// `scale`) wide about its middle; a field of zeros with a zero scale gets [-1, 1].
ColourRange shared_colour_range(const std::vector<const std::vector<double> *> &fields, double scale,
                                double min_relative = 0.01);

/// One engine's panel of a row: the field at the recorded state nearest the named state.
struct MapPanel {
  std::string engine;
  bool present = false;
  double strain = nan;          ///< of the recorded state shown
  std::vector<double> x, z, v;  ///< v in the row's display units
  double marker = 0.0, marker_z = 0.0; ///< as SectionSeries
  bool tiles = false;
  std::string missing;          ///< why there is no panel
  /// Half the extent of a point in z: a tile's half-height, a disc's radius.
  double half_height() const { return tiles ? marker_z : marker; }
};

/// A quantity at one state, one panel per engine (DEM | FE cube | FEM x DEM, those that ran),
/// on one colour scale.
struct MapRow {
  std::string quantity;         ///< "u_x", "u_z", "gamma (local)"
  std::string unit;             ///< "mm", "%"
  std::vector<MapPanel> panels; ///< in the order of the sections given to state_maps
  ColourRange range;
};

struct StateMaps {
  NamedState state;
  std::vector<MapRow> rows;     ///< empty when the state was not found
};

/// A series with the curve strain of each of its states (the nearest main-path sample in time
/// of the engine's Response, in the measure of onset_strain_measure: the curve's x) and the
/// in-plane most compressive principal direction (x, z) of the engine's stress there (the
/// eigenvector of the smaller eigenvalue of its x-z block; empty: not known), which the
/// strain-field onset measures its band against (SectionLocalization.h).
struct StrainedSection {
  std::string engine;                    ///< the panel's label
  const SectionSeries *series = nullptr; ///< none: the engine recorded no section
  std::vector<double> strains;
  std::vector<Eigen::Vector2d> compressive_axes;
};
StrainedSection strained_section(const SectionSeries &series, const Response &response, CurveKind kind, int stage,
                                 std::optional<AxialAxis> axial);

struct StateMapOptions {
  double max_strain_gap = 0.005; ///< a recorded state farther than this from the named one: no panel
  double min_relative_range = 0.01;
};

/// The rows u_x, u_z (from the box centre) and the local gamma of every named state, one panel
/// per section in the order given (DEM | FE cube | FEM x DEM); a section without a series gives
/// panels that say so.
std::vector<StateMaps> state_maps(const std::vector<NamedState> &states, const std::vector<StrainedSection> &sections,
                                  const StateMapOptions &options = {});

} // namespace geocomp::compare
