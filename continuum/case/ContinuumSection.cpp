// The `continuum` section: the continuum engines' material (Mohr-Coulomb tables,
// Drucker-Prager matching, S1's model in its subsection), mesh and solver.
#include "continuum/case/ContinuumSections.h"
#include "continuum/fe/GaussPoints.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geocomp::sections {

using dealii::Patterns::Anything;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::List;
using dealii::Patterns::Selection;


void declare_continuum(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("continuum");
  prm.declare_entry("model", "mohr-coulomb", Selection("mohr-coulomb|drucker-prager|nikolaevsky"),
                    "Constitutive model: Mohr-Coulomb with hardening/softening, Drucker-Prager matched to it, "
                    "nikolaevsky: S1's quasi-static model (Mises-Schleicher yield, Nikolaevsky non-associated flow, "
                    "linear hardening; docs/s1-kinetic-model.md), whose material is subsection nikolaevsky: the "
                    "entries E, nu, cohesion, friction and dilatancy angle below are then not used. (FEM x DEM, the "
                    "engine 'fem-dem', runs this section's cube with a DEM cell at every point: section 'dem rve'.)");
  prm.declare_entry("drucker prager matching", "outer", Selection("outer|inner|plane-strain"),
                    "How Drucker-Prager is matched to the Mohr-Coulomb c and phi.");
  prm.declare_entry("youngs modulus", "200e6", Double(1e3, 1e13),
                    "Young's modulus E [Pa] (mohr-coulomb, drucker-prager).");
  prm.declare_entry("poisson ratio", "0.25", Double(0, 0.4999), "Poisson ratio nu (mohr-coulomb, drucker-prager).");
  prm.declare_entry("cohesion", "0:1e5", Anything(),
                    "Cohesion c(kappa) [Pa], piecewise linear: 'kappa:value, kappa:value, ...', kappa from 0 "
                    "increasing; constant beyond the last point.");
  prm.declare_entry("friction angle", "0:30", Anything(), "Friction angle phi(kappa) [deg], same format.");
  prm.declare_entry("dilatancy angle", "0:5", Anything(),
                    "Dilatancy angle psi(kappa) [deg], same format; psi <= phi (non-associated flow).");
  prm.declare_entry("kinematics", "finite strain", Selection("finite strain|small strain"),
                    "finite strain: multiplicative plasticity with logarithmic elastic strain, F from the box edges "
                    "(material point) or total Lagrangian (FE cube), Cauchy stress as force over current area; "
                    "small strain: eps = sym grad u, force over initial area (for comparison). Both engines.");
  prm.declare_entry("cells per edge", "4", Integer(1, 512), "Hexahedra per cube edge.");
  prm.declare_entry("threads", "1", Integer(1, 1024),
                    "Threads over the quadrature points' material updates of the FE engines within a rank "
                    "(fem-dem: one DEM cell per point); the same bits for any count.");
  prm.declare_entry("box edges", "", List(Double(0), 0, 3),
                    "Edges L_x, L_y, L_z [m] of a box meshed instead of the specimen's cube (a biaxial specimen, "
                    "a plane-strain slab: y kinematic at zero strain); empty: the cube of edge L0. Walls, box strains "
                    "and wall stresses are the box's; the DEM engines keep their cube.");
  prm.declare_entry("box cells", "", List(Integer(1, 512), 0, 3),
                    "Hexahedra along x, y, z of the box ('box edges'); empty: 'cells per edge' on every axis.");
  prm.declare_entry("degree", "1", Integer(1, 3), "Polynomial degree of the FE_Q displacement.");
  prm.declare_entry("quadrature points", "", List(Integer(1, 6), 0, 3),
                    "Gauss points along x, y, z in every hexahedron; empty: degree + 1 on every axis (full "
                    "integration). For degree 2 or 3 one axis may take 'degree' points: the thickness of a plane-strain "
                    "slab one element thick, whose fields do not vary across it (its residual stays exact, the "
                    "element keeps no zero-energy mode; continuum/fe/GaussPoints.h). FEM x DEM: one DEM cell per "
                    "point.");
  prm.declare_entry("volumetric integration", "full", Selection("full|b-bar"),
                    "full: every quadrature point takes its own volumetric strain; b-bar: the cell average "
                    "(Hughes 1980), which removes the volumetric locking of Q1 under nearly isochoric plastic "
                    "flow (docs/continuum-fe.md). Meant for degree 1.");
  prm.declare_entry("imperfection radius", "0", Double(0, 1e3),
                    "Radius [m] of a weaker zone that triggers a band; 0 = none.");
  prm.declare_entry("imperfection factor", "0.9", Double(0.01, 1.0),
                    "Cohesion multiplier inside the weaker zone (drucker-prager: of Y(kappa); nikolaevsky: of every "
                    "strength, sigma_y and sigma_c, hence of Y(kappa)).");
  prm.declare_entry("imperfection centre", "0.5, 0.5, 0.5", List(Double(0, 1), 3, 3),
                    "Centre of the weaker zone, as fractions of the edges (L0, or the box's).");
  prm.declare_entry("linear solver", "gmres", Selection("gmres|cg|direct"),
                    "PETSc solver of the Newton systems (direct = MUMPS).");
  prm.declare_entry("preconditioner", "amg", Selection("amg|jacobi"),
                    "Preconditioner of the Krylov solvers: algebraic multigrid (Trilinos ML, or Hypre "
                    "BoomerAMG in a PETSc build) or Jacobi.");
  prm.declare_entry("near null space", "rigid-body", Selection("rigid-body|translations"),
                    "Near-null space of the algebraic multigrid (Trilinos ML): the six rigid-body modes "
                    "(Krylov iterations nearly independent of the mesh; a costlier set-up) or the three "
                    "translations (cheaper per solve on meshes up to ~64^3, iterations grow with the mesh). "
                    "docs/continuum-fe.md, Performance.");
  prm.declare_entry("newton tolerance", "1e-9", Double(1e-14, 1e-2),
                    "Newton converges when |R_free| <= tolerance * max(|F_int|, |F_ext|).");
  prm.declare_entry("load steps per sample", "2", Integer(1, 10000),
                    "Initial load steps per sampling interval (halved on non-convergence).");
  prm.declare_entry("point substeps per sample", "20", Integer(1, 100000),
                    "Load increments per sampling interval of the material-point engine.");
  prm.declare_entry("regularization", "none", Selection("crack-band|none"),
                    "Softening regularization: scale the softening by element size (crack band) or none "
                    "(nikolaevsky hardens linearly and never softens: nothing to scale). The cube's solution stays "
                    "diffuse on the meshes tested (docs/continuum-fe.md), where the unregularized curves already "
                    "agree across meshes.");
  prm.declare_entry("reference element size", "0", Double(0, 1e3),
                    "Crack-band reference width [m]: the softening table holds as written for elements of this size "
                    "and is stretched by width/h_e elsewhere; 0 = the cube edge L0 (the table describes the whole "
                    "specimen, as a material-point calibration from DEM does).");
  declare_nikolaevsky(prm);
  prm.leave_subsection();
}

HardeningTable parse_table(const std::string &text, const std::string &parameter, const Reader &r)
{
  return HardeningTable{parse_points(text, parameter, r)};
}

ContinuumParameters parse_continuum(dealii::ParameterHandler &prm, const Reader &r)
{
  ContinuumParameters p;
  prm.enter_subsection("continuum");
  ContinuumParameters::visit(p, ReadEntries{prm, r, "continuum"});
  p.nikolaevsky = parse_nikolaevsky(prm, r);
  prm.leave_subsection();
  if (!p.box_edges.empty() && p.box_edges.size() != 3)
    r.fail("continuum/box edges", "three edges L_x, L_y, L_z > 0 [m], or none (the cube)");
  if (!p.box_edges.empty() && !(*std::min_element(p.box_edges.begin(), p.box_edges.end()) > 0.0))
    r.fail("continuum/box edges", "edges > 0 [m]");
  if (!p.box_cells.empty() && p.box_cells.size() != 3)
    r.fail("continuum/box cells", "three counts n_x, n_y, n_z >= 1, or none (cells per edge on every axis)");
  if (!p.quadrature_points.empty() && p.quadrature_points.size() != 3)
    r.fail("continuum/quadrature points", "three counts along x, y, z, or none (degree + 1 on every axis)");
  if (p.quadrature_points.size() == 3) {
    const std::array<unsigned, 3> n{{static_cast<unsigned>(p.quadrature_points[0]),
                                     static_cast<unsigned>(p.quadrature_points[1]),
                                     static_cast<unsigned>(p.quadrature_points[2])}};
    if (const std::string problem = continuum::gauss_points_problem(p.degree, n); !problem.empty())
      r.fail("continuum/quadrature points", problem);
  }
  if (p.volumetric_integration == "b-bar" && p.kinematics == "finite strain")
    r.fail("continuum/volumetric integration", "b-bar is a small-strain method: set kinematics = small strain");
  for (const auto &[k, c] : p.cohesion.points)
    if (c < 0)
      r.fail("continuum/cohesion", "cohesion must be >= 0 Pa");
  for (const auto &[k, phi] : p.friction_angle.points)
    if (phi < 0 || phi >= 90)
      r.fail("continuum/friction angle", "expected angles in [0, 90) degrees");
  for (const auto &[k, psi] : p.dilatancy_angle.points)
    if (psi < 0 || psi >= 90)
      r.fail("continuum/dilatancy angle", "expected angles in [0, 90) degrees");
  // Both tables are piecewise linear: psi <= phi everywhere when it holds at every knot of either.
  std::vector<double> knots;
  for (const HardeningTable *t : {&p.dilatancy_angle, &p.friction_angle})
    for (const auto &point : t->points)
      knots.push_back(point.first);
  for (double k : knots)
    if (p.dilatancy_angle(k) > p.friction_angle(k) + 1e-12)
      r.fail("continuum/dilatancy angle", "psi must not exceed phi at the same kappa (got psi > phi at kappa = " +
                                            std::to_string(k) + ")");
  return p;
}

} // namespace geocomp::sections
