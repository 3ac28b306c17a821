#pragma once
// The continuum's section of a case file (`continuum`, with its subsection `nikolaevsky`),
// as plain data.
//
// Why here: each engine owns its parameters (one home per parameter). The structs, their
// declaration and parser (continuum/case/*Section.cpp) and their `visit` lists live in the
// continuum's folder; `visit(struct, v)` calls v("entry", field) for every declared entry
// in declaration order (CanonicalText writes `/meta/parameters` with it; a test checks it
// names exactly the declared entries). SI; angles in degrees as the case file gives them.
#include <string>
#include <utility>
#include <vector>

namespace geocomp::continuum {

/// A piecewise-linear function of the equivalent plastic strain kappa.
struct HardeningTable {
  std::vector<std::pair<double, double>> points; ///< (kappa, value), kappa increasing from 0

  double operator()(double kappa) const
  {
    if (points.empty())
      return 0.0;
    if (kappa <= points.front().first)
      return points.front().second;
    for (std::size_t i = 1; i < points.size(); ++i)
      if (kappa <= points[i].first) {
        const auto &[k0, v0] = points[i - 1];
        const auto &[k1, v1] = points[i];
        return v0 + (v1 - v0) * (kappa - k0) / (k1 - k0);
      }
    return points.back().second;
  }
};

/// S1's quasi-static Nikolaevsky model (continuum/model = nikolaevsky), subsection
/// continuum/nikolaevsky (NikolaevskySection.cpp): a row of S1's material table, or
/// custom values. SI; stresses are magnitudes of uniaxial compression.
struct NikolaevskyParameters {
  std::string material = "sandstone";   ///< sandstone | concrete (S1's table) | custom
  // material = custom only, where every one is required (0: not given):
  double youngs_modulus = 0.0;          ///< E [Pa]
  double poisson_ratio = 0.0;           ///< nu
  double yield_stress = 0.0;            ///< sigma_y [Pa]
  double compressive_strength = 0.0;    ///< sigma_c [Pa], > sigma_y
  double internal_friction = 0.0;       ///< alpha = 3 omega (S1 eq. (1))
  double dilatancy = 0.0;               ///< Lambda (S1 eq. (2))
  double plastic_strain_at_strength = 0.0; ///< axial plastic strain at sigma_c (sets the hardening)

  template <class Self, class V>
  static void visit(Self &p, V &&v)
  {
    v("material", p.material);
    v("youngs modulus", p.youngs_modulus);
    v("poisson ratio", p.poisson_ratio);
    v("yield stress", p.yield_stress);
    v("compressive strength", p.compressive_strength);
    v("internal friction", p.internal_friction);
    v("dilatancy", p.dilatancy);
    v("plastic strain at strength", p.plastic_strain_at_strength);
  }
};

struct ContinuumParameters {
  std::string model = "mohr-coulomb";   ///< mohr-coulomb | drucker-prager | nikolaevsky
  std::string dp_matching = "outer";    ///< outer | inner | plane-strain
  double youngs_modulus = 200.0e6;      ///< [Pa]
  double poisson_ratio = 0.25;
  HardeningTable cohesion;              ///< [Pa]
  HardeningTable friction_angle;        ///< [deg]
  HardeningTable dilatancy_angle;       ///< [deg]
  std::string kinematics = "finite strain";    ///< finite strain | small strain
  unsigned int cells_per_edge = 4;
  unsigned int threads = 1;             ///< threads over the points' updates (FE engines)
  std::vector<double> box_edges;        ///< [m] L_x, L_y, L_z of a box; empty = the specimen's cube
  std::vector<double> box_cells;        ///< n_x, n_y, n_z (integers) of the box; empty = cells per edge
  unsigned int degree = 1;
  std::vector<double> quadrature_points; ///< Gauss points along x, y, z (integers); empty = degree + 1 each
  std::string volumetric_integration = "full"; ///< full | b-bar
  double imperfection_radius = 0.0;     ///< [m]; 0 = none
  double imperfection_factor = 0.9;     ///< cohesion multiplier inside it
  std::vector<double> imperfection_centre{0.5, 0.5, 0.5}; ///< relative to L0
  std::string linear_solver = "gmres";  ///< gmres | cg | direct
  std::string preconditioner = "amg";  ///< amg | jacobi
  std::string near_null_space = "rigid-body"; ///< ML's near-null space: rigid-body | translations
  double newton_tolerance = 1e-9;
  unsigned int load_steps_per_sample = 2;
  unsigned int point_substeps = 20;     ///< material-point increments per sample
  std::string regularization = "none"; ///< crack-band | none
  double reference_element_size = 0.0;  ///< [m] crack-band reference width; 0 = the cube edge L0
  NikolaevskyParameters nikolaevsky;    ///< for model = nikolaevsky

  /// The entries of `continuum` itself (the subsection: NikolaevskyParameters::visit).
  template <class Self, class V>
  static void visit(Self &p, V &&v)
  {
    v("model", p.model);
    v("drucker prager matching", p.dp_matching);
    v("youngs modulus", p.youngs_modulus);
    v("poisson ratio", p.poisson_ratio);
    v("cohesion", p.cohesion.points);
    v("friction angle", p.friction_angle.points);
    v("dilatancy angle", p.dilatancy_angle.points);
    v("kinematics", p.kinematics);
    v("cells per edge", p.cells_per_edge);
    v("threads", p.threads);
    v("box edges", p.box_edges);
    v("box cells", p.box_cells);
    v("degree", p.degree);
    v("quadrature points", p.quadrature_points);
    v("volumetric integration", p.volumetric_integration);
    v("imperfection radius", p.imperfection_radius);
    v("imperfection factor", p.imperfection_factor);
    v("imperfection centre", p.imperfection_centre);
    v("linear solver", p.linear_solver);
    v("preconditioner", p.preconditioner);
    v("near null space", p.near_null_space);
    v("newton tolerance", p.newton_tolerance);
    v("load steps per sample", p.load_steps_per_sample);
    v("point substeps per sample", p.point_substeps);
    v("regularization", p.regularization);
    v("reference element size", p.reference_element_size);
  }
};

} // namespace geocomp::continuum

namespace geocomp {
// The continuum's structs by their old names, for code that spoke of them before they had a home.
using continuum::ContinuumParameters;
using continuum::HardeningTable;
using continuum::NikolaevskyParameters;
} // namespace geocomp
