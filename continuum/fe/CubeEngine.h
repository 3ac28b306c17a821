#pragma once
// CubeEngine: the loading program played on a finite element cube (deal.II).
//
// The specimen is the cube [0, L]^3 (or a box [0, L_x] x [0, L_y] x [0, L_z]: a biaxial
// specimen, a plane-strain slab) between six rigid, frictionless walls, exactly the
// DEM box: the walls x = 0, y = 0, z = 0 stay where they are (zero normal displacement,
// tangential sliding free) and the walls x = L, y = L, z = L follow the StageControl:
//   - kinematic axis a:  u_a = eps_a(t) L_a on the face x_a = L_a  (a frictionless platen;
//                        S0 eq. (3) included, it is just a prescribed eps_a(t)),
//   - stress axis a:     traction t = sigma*_a(t) e_a on the face x_a = L (a flexible
//                        membrane, as a servo wall in the limit of fast servo).
// The three fixed walls remove the rigid modes, so an all-stress stage is well posed.
//
// Equilibrium, rate-independent elastoplasticity, finite strain by default (`kinematics`):
// total Lagrangian on the reference cube with F = I + Grad u, the exponential-map update of
// continuum/models/FiniteStrain.h at every quadrature point and its spatial tangent,
//     R(u) = int_Omega0 grad_x N : tau dV0 - F_ext(u) = 0,   K = int grad_x N : (J a) : grad_x N dV0 + K_load,
// (deal.II step-44 is the model of the assembly); with `kinematics = small strain`
//     R(u) = int_Omega B^T sigma(eps(u); history) dV - int_Gamma_t N^T t dA = 0,  K = int B^T C_alg B dV.
// Each load step is solved by Newton-Raphson with the consistent tangent, K du = -R,
// u <- u + alpha du, where the first iteration of a step carries the increment of the prescribed wall
// displacements as inhomogeneous constraints (a tangent predictor, exact for elasticity),
// and alpha comes from a backtracking line search on |R|. A step that does not converge in
// `max_newton_iterations` (or whose last three iterations did not halve the residual) is
// cut back (halved) from the last converged state; steps grow again after a step of at
// most four iterations or two in a row within half that limit.
// History lives per quadrature point (CellDataStorage): the converged state and the trial
// state of the current iteration, committed only after convergence, so cut-backs and the
// engine's save()/restore() are exact. A material that owns its point state
// (continuum/models/PointStateModel.h, e.g. a DEM cell per point) rides in the same history
// and gets the same commit/cut-back/save semantics, at small or finite strain.
//
// Response. Wall stress sigma_aa = (sum of the internal nodal forces in direction a on the
// face x_a = L) / (area of that face): at finite strain its CURRENT area projected on the
// wall, int cof(F)_aa dA0, so sigma_aa is the Cauchy stress a DEM wall measures (force over
// current wall area) and stress-axis tractions are applied per current area as well; at
// small strain the initial area L^2, the work conjugate of the engineering strain. A
// homogeneous cube reproduces the material point exactly either way. Box strain eps_aa =
// mean normal displacement of the face x_a = L over L (exact on kinematic faces, the
// average of a possibly warped face on stress faces); the engineering strain of the box,
// whose log ln(1 + eps) the metrics read. Off-diagonal stress = the volume average of the
// Cauchy stress over the current configuration (zero up to round-off between frictionless
// walls); off-diagonal box strain = 0.
//
// Softening and localization: an imperfection (a sphere of quadrature points with reduced
// cohesion) triggers the band, and the softening branch is regularized by the crack-band
// method (the kappa-extent of softening scaled by l_ref / h_e, h_e the element size;
// docs/continuum-fe.md). Each plastic quadrature point carries Rice's indicator
// q = min_n det(n.C_alg.n)/det(n.C_e.n); the first q <= 0 (time, place, band normal) is
// recorded in the Response extras.
#include "common/LoadingEngine.h"
#include "continuum/driver/Materials.h"
#include "continuum/models/FiniteStrain.h"

#include <mpi.h>

#include <array>
#include <memory>
#include <string>

namespace geocomp::continuum {

/// Parameters of the FE cube (the lead declares them in the case file).
struct CubeParameters {
  // Geometry and discretization: the cube [0, L]^3 in n^3 hexahedra, or a box.
  double side = 1.0;              ///< L [m] > 0
  unsigned cells_per_side = 8;    ///< n >= 1: n^3 hexahedra
  /// A box [0, L_x] x [0, L_y] x [0, L_z] instead of the cube (a plane-strain slab, a
  /// biaxial specimen): edges [m], all > 0; zero = the cube of `side`.
  Vector3 box_edges = Vector3::Zero();
  /// Hexahedra along x, y, z (each >= 1); zero = `cells_per_side` on every axis.
  std::array<unsigned, 3> box_cells{{0, 0, 0}};

  /// The edges and subdivisions in use (the box when given, else the cube).
  Vector3 edges() const { return box_edges.isZero() ? Vector3::Constant(side) : box_edges; }
  std::array<unsigned, 3> cells() const
  {
    return box_cells[0] == 0 ? std::array<unsigned, 3>{{cells_per_side, cells_per_side, cells_per_side}} : box_cells;
  }
  unsigned degree = 1;            ///< FE_Q degree, 1..3
  /// Gauss points along x, y, z in every hexahedron; all zero = degree + 1 on every axis (full
  /// integration). For degree 2 or 3 one axis may take `degree` points: the thickness of a
  /// plane-strain slab (GaussPoints.h: why it keeps no zero-energy mode; Q1 would).
  std::array<unsigned, 3> quadrature_points{{0, 0, 0}};
  /// full | b-bar. b-bar (Hughes 1980) replaces the volumetric strain at every quadrature
  /// point by its cell average, which removes the volumetric locking of Q1 under nearly
  /// isochoric plastic flow; meant for degree 1.
  std::string volumetric_integration = "full";
  /// finite strain (total Lagrangian, logarithmic elastic strain; the default) or small strain.
  Kinematics kinematics = Kinematics::finite_strain;
  // Linear solver (Trilinos or PETSc, chosen when configuring; docs/continuum-fe.md).
  std::string linear_solver = "gmres";  ///< gmres | cg (symmetric tangents only) | direct
  /// amg | jacobi. amg = the AMG of the configured linear algebra (ML with Trilinos,
  /// BoomerAMG with PETSc); "boomeramg" and "ml" are accepted as aliases of amg.
  std::string preconditioner = "amg";
  /// Near-null space given to ML (Trilinos AMG only): rigid-body = the three translations
  /// and the three rotations (default), translations = the translations only.
  std::string near_null_space = "rigid-body";
  double linear_tolerance = 1e-10;  ///< relative residual of the Krylov solve
  /// ML's hierarchy is kept across Newton iterations and load steps while a solve needs at
  /// most this times (plus 5) the Krylov iterations per decade of reduction of the first
  /// solve after the last build; rebuilt otherwise (CubeSolver.cpp). 0 = rebuild for every solve.
  double amg_rebuild_growth = 1.5;
  unsigned max_linear_iterations = 5000;
  // Newton and load stepping.
  double newton_tolerance = 1e-9;   ///< |R_free| <= tol * max(|F_int|, |F_ext|)
  /// A step whose |R_free| / F is below this times newton_tolerance and no longer halves per
  /// iteration (Newton creeping where points cross a kink of a piecewise-linear table) is
  /// accepted and counted (extra `relaxed_steps`); 0 = never.
  double newton_stagnation_factor = 1e3;
  unsigned max_newton_iterations = 15;
  /// A step is cut back when its last this many iterations have not halved the residual
  /// (>= 1): Newton stalling at a floor. Secant pairs may plateau for a few iterations while
  /// they learn the stiffness, then drop.
  unsigned stall_iterations = 3;
  /// 0: Newton with the tangent of every iterate (the consistent tangent of the plasticity
  /// models). m > 0: the tangent of the step's first corrector iteration only, updated by the
  /// BFGS pairs of the step's iterations, at most m of them (SecantPairs.h: for a material
  /// whose tangent is approximate, a DEM cell per point).
  unsigned secant_pairs = 0;
  unsigned line_search_steps = 6;   ///< halvings of the Newton step (0 = full steps)
  unsigned steps_per_advance = 2;   ///< load steps per sample interval (initial size)
  unsigned max_cutbacks = 10;       ///< halvings of a load step before giving up
  double initial_stress = 0.0;      ///< isotropic initial stress [Pa], tension positive
  /// Threads over the quadrature points' material updates in each assembly pass (within a
  /// rank; FEM x DEM: one RVE per point). Each update is independent and the assembly sums
  /// in cell order, so the results are the same bits for any count; 1 = serial.
  unsigned threads = 1;
  // Imperfection: quadrature points inside the sphere get a reduced cohesion.
  Vector3 imperfection_centre = Vector3(0.5, 0.5, 0.5); ///< [m]
  double imperfection_radius = 0.0; ///< [m] >= 0; 0 = no imperfection
  double imperfection_cohesion_factor = 0.9; ///< (0, 1]
  // Regularization of softening.
  std::string regularization = "crack-band"; ///< crack-band | none
  /// Width over which the softening law was measured/calibrated [m] (crack band l_ref):
  /// softening kappa-extents are scaled by l_ref / h_e, h_e = cube root of the cell volume.
  /// 0 = the side L (the law describes the whole specimen, as a material-point calibration).
  double band_reference_width = 0.0;
  // Localization indicator.
  unsigned localization_directions = 200; ///< coarse scan points on the hemisphere, >= 10
  /// Fraction of the elastic stiffness added to the tangent (matrix only, not the stress)
  /// at apex returns, whose perfect-plastic tangent is singular.
  double apex_tangent_fraction = 1e-3;
  // Output: VTU/PVTU per sample + a PVD index; empty directory = no output.
  std::string output_directory;
  std::string output_basename = "cube";
  unsigned output_every = 1;  ///< write every k-th measured sample
  bool verbose = false;       ///< Newton log on rank 0
};

/// Counters of the last advance_to (and totals), for benchmarks and tests.
struct CubeStatistics {
  unsigned steps = 0;             ///< converged load steps, total
  unsigned newton_iterations = 0; ///< Newton iterations in converged steps, total
  unsigned cutbacks = 0;          ///< total
  unsigned relaxed_steps = 0;     ///< steps accepted at the stagnation tolerance, total
  unsigned linear_iterations = 0; ///< total Krylov iterations
  unsigned preconditioner_builds = 0; ///< AMG (or Jacobi) set-ups, total
  /// Material updates of quadrature points computed (not taken from a point's memo), total:
  /// the cost measure of a material that is expensive per point (an RVE).
  unsigned long material_updates = 0;
  /// Assembly passes of the residual alone (the iterates and line-search trials), total.
  unsigned long residual_assemblies = 0;
  double assembly_seconds = 0.0, solve_seconds = 0.0, total_seconds = 0.0;
  /// Residual history |R|/scale of the last converged step (for convergence-rate tests).
  std::vector<double> last_step_residuals;
  unsigned last_step_iterations = 0;
};

/// Fields on the mid-plane y = L/2 of the cube (S0 Fig. 3-5 maps): a 3 x 3 grid of points
/// in each cell the plane cuts, with the displacement there and the cell's volume-averaged
/// equivalent plastic strain kappa. Gathered on rank 0 (empty elsewhere).
struct MidPlaneSample {
  std::vector<double> x, z, ux, uz, kappa;
};

/// Throws std::invalid_argument naming the parameter when `p` is out of range. The
/// constructor calls it; so does the command line's validation of a case before anything
/// runs (compare/cli/CaseValidation.cpp), so that `geocomp check` refuses what the cube would.
void check_cube_parameters(const CubeParameters &p);

class CubeEngine : public LoadingEngine {
public:
  CubeEngine(const CubeParameters &parameters, std::shared_ptr<const MaterialFactory> material,
             MPI_Comm communicator);
  CubeEngine(const CubeParameters &parameters, const MaterialParameters &material, MPI_Comm communicator);
  ~CubeEngine() override;

  std::string name() const override { return "continuum-fe"; }
  std::vector<ExtraColumn> extra_columns() const override;
  void begin_control(const StageControl &control) override;
  void advance_to(double t_end) override;
  ResponseSample measure() override;
  std::unique_ptr<EngineState> save() const override;
  void restore(const EngineState &state) override;
  /// Field output of branch `id` goes to `<basename>-branch<id>.pvd`, the main path's to
  /// `<basename>.pvd` (time increasing).
  void set_branch(int id) override;

  const CubeStatistics &statistics() const;
  unsigned n_dofs() const;
  /// Element size h_e used by the crack band [m].
  double element_size() const;
  /// The current state on the plane y = L/2 (collective: every rank calls it).
  MidPlaneSample mid_plane() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace geocomp::continuum
