#pragma once
// Internal: the deal.II state of CubeEngine, shared by its two translation units
// (CubeEngine.cpp: setup, assembly, Newton, measurement; CubeOutput.cpp: VTU/PVD output).
// Not installed; include only from continuum/fe/*.cpp.
#include "continuum/fe/CubeEngine.h"
#include "continuum/models/AcousticTensorScan.h"
#include "continuum/models/FiniteStrain.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/generic_linear_algebra.h>

// Linear algebra, chosen at configure time (CMake GEOCOMP_CUBE_LINEAR_ALGEBRA):
// Trilinos (Epetra + ML smoothed-aggregation multigrid with the six rigid-body modes as
// near-null space; the default, see docs/continuum-fe.md for the timings) or PETSc
// (BoomerAMG).
#if defined(GEOCOMP_CUBE_USE_PETSC)
namespace geocomp::continuum {
namespace LA = dealii::LinearAlgebraPETSc;
}
#else
#include <deal.II/lac/trilinos_precondition.h>
namespace geocomp::continuum {
namespace LA = dealii::LinearAlgebraTrilinos;
}
#endif

#include <map>
#include <utility>
#include <vector>

namespace geocomp::continuum {

namespace dl = dealii;

/// History and trial state of one quadrature point. Small strain: `old_history` and `trial`.
/// Finite strain: `old_finite` and `trial_finite` carry F and b^e; `trial` then holds the
/// Cauchy stress, the logarithmic tangent (for the localization scan), kappa and the region,
/// so that measurement and output read one record whatever the kinematics.
struct QuadraturePointData {
  // Converged at the end of the last committed load step.
  PlasticHistory old_history;
  FiniteStrainHistory old_finite;
  Vector6 old_stress = Vector6::Zero(); ///< Cauchy stress, Mandel
  ReturnRegion old_region = ReturnRegion::elastic;
  // Trial values of the current Newton iterate (committed on convergence); after a
  // commit, trial.tangent is the consistent tangent of the converged state.
  MaterialPointUpdate trial;
  FiniteStrainHistory trial_finite;
  // Geometry and material of the point.
  const ConstitutiveModel *material = nullptr;
  bool weak = false;    ///< inside the imperfection
  double JxW = 0.0;     ///< quadrature weight times Jacobian
  Vector3 position = Vector3::Zero();
  // Localization indicator at the last committed state.
  double q = 1.0;
  Vector3 normal = Vector3::Zero();
  /// The point's last material update and the input it was computed from (CubeEngine.cpp,
  /// "The points' updates"): an update is a pure function of (input, committed history), so
  /// while the committed history is the one of `epoch` the same input takes this result, bit
  /// for bit, instead of computing it again (a tangent assembled at the iterate whose residual
  /// the line search just evaluated; the updates of threads > 1 computed ahead of a pass).
  struct Memo {
    unsigned long epoch = 0; ///< Impl::history_epoch it belongs to; 0: none
    bool failed = false;     ///< the update threw ReturnMapFailure
    Vector6 strain = Vector6::Zero();
    Matrix3 deformation_gradient = Matrix3::Identity();
    MaterialPointUpdate small;
    FiniteStrainUpdate finite;
  } memo;
};

struct CubeEngine::Impl {
  using Cell = dl::Triangulation<3>::cell_iterator;

  Impl(const CubeParameters &prm, std::shared_ptr<const MaterialFactory> factory, MPI_Comm comm);

  // ---- setup (CubeEngine.cpp)
  void make_mesh_and_dofs();
  void setup_quadrature_data();
  void build_constraints(); ///< homogeneous constraints of the current control

  // ---- load stepping
  double target_stress(int axis, double t) const;
  bool solve_step(double t);  ///< Newton for the load step to time t; false: cut back
  /// Evaluates every quadrature point at `solution` and assembles the residual (free
  /// rows), the unconstrained internal force, and if `matrix` the tangent. With
  /// `predictor` the inhomogeneous predictor constraints are used for the matrix rows.
  /// Returns |R_free|.
  double assemble(double t, bool matrix, bool predictor);
  /// Per-cell parts of assemble(): the internal force and tangent of one cell, small strain
  /// (with B-bar) or finite strain (total Lagrangian); false when a return map failed.
  struct CellTerms;
  bool cell_small_strain(CellTerms &terms);
  /// The strains of a cell's points at `solution` into terms.strains (B-bar: with the cell's
  /// mean volumetric strain, and terms.mean_div the mean divergences).
  void small_strains(CellTerms &terms) const;
  /// The points' updates of the coming pass computed ahead in parallel over the points
  /// (threads > 1) into their memos; small_update / finite_update take a point's memo when
  /// its input and committed history are the same and compute (and memorize) otherwise.
  void update_points_ahead();
  /// Computes the point's update for F (finite strain) or the strain (small) into its memo;
  /// a ReturnMapFailure is memorized as failed, any other exception leaves it invalid.
  void memorize(QuadraturePointData &d, const Matrix3 &F, const Vector6 &strain) const;
  MaterialPointUpdate small_update(QuadraturePointData &d, const Vector6 &strain);
  FiniteStrainUpdate finite_update(QuadraturePointData &d, const Matrix3 &F);
  /// Numbers the committed histories: raised whenever the points' committed history changes
  /// (commit, restore), which invalidates every memo.
  unsigned long history_epoch = 1;
  bool cell_finite_strain(CellTerms &terms);
  /// Wall tractions sigma*_a e_a on the faces x_a = L of stress axes, per current projected
  /// area at finite strain (with the load stiffness when the matrix is assembled).
  void cell_tractions(CellTerms &terms, double t);
  // ---- linear solver (CubeSolver.cpp)
  unsigned solve_linear(double reduction); ///< K du = rhs to a relative reduction; iterations
  void build_preconditioner();             ///< the preconditioner on the current matrix (Trilinos)
  void commit();
  void revert();
  void update_localization(double t);

  // ---- measurement
  Vector3 wall_stresses() const;       ///< from the internal-force reactions, per current area
  Vector3 face_areas() const;          ///< current areas of the faces x_a = L projected on e_a
  template <class Visit>
  void for_each_moving_face(dl::FEFaceValues<3> &fv, Visit visit) const;
  Vector3 face_strains() const;        ///< mean normal displacement / L
  Tensor3 volume_average_stress() const;

  // ---- output (CubeOutput.cpp)
  void write_output(double time);

  MPI_Comm comm;
  CubeParameters prm;
  std::shared_ptr<const MaterialFactory> factory;
  dl::ConditionalOStream pcout;

  dl::parallel::distributed::Triangulation<3> tria;
  dl::FESystem<3> fe;
  dl::DoFHandler<3> dof_handler;
  dl::Quadrature<3> quadrature; ///< QAnisotropic of continuum/quadrature points (GaussPoints.h)
  dl::QGauss<2> face_quadrature;
  dl::IndexSet owned, relevant;
  double h_e = 0.0; ///< element size (cube root of the cell volume)

  /// Dofs of component a on the face x_a = L (boundary id 2a+1), locally relevant.
  std::array<dl::IndexSet, 3> top_face_dofs;
  std::array<dl::IndexSet, 3> bottom_face_dofs;
  dl::AffineConstraints<double> constraints;           ///< homogeneous, current control
  dl::AffineConstraints<double> predictor_constraints; ///< with the step's wall increments

  LA::MPI::SparseMatrix matrix;
#if !defined(GEOCOMP_CUBE_USE_PETSC)
  /// Kept across solves while it serves (CubeSolver.cpp).
  std::unique_ptr<dealii::TrilinosWrappers::PreconditionBase> preconditioner;
#endif
  bool preconditioner_stale = true;                ///< rebuild before the next solve
  double preconditioner_iterations_per_decade = 0.0; ///< of the first solve after a build
  std::vector<std::vector<bool>> constant_modes; ///< components of the dofs, for ML
  /// The six rigid-body modes over the locally owned dofs (row map order), column-major,
  /// n_owned x 6: translations x, y, z, then rotations about x, y, z through the centre.
  std::vector<double> rigid_body_modes;
  void make_rigid_body_modes();
  LA::MPI::Vector solution;        ///< ghosted current iterate
  LA::MPI::Vector solution_owned;  ///< same, owned entries
  LA::MPI::Vector old_solution;    ///< owned, last committed
  LA::MPI::Vector rhs;             ///< -R (free rows)
  LA::MPI::Vector internal_force;  ///< unconstrained int B^T sigma
  LA::MPI::Vector update;          ///< Newton update (owned)
  double residual_scale = 0.0; ///< max(|F_int|, |F_ext|) of the last assembly

  dl::CellDataStorage<Cell, QuadraturePointData> qp_data;
  std::map<MaterialVariant, std::shared_ptr<const ConstitutiveModel>> materials;
  Matrix6 elastic_tangent;
  Vector6 prestrain = Vector6::Zero(); ///< elastic strain of the initial stress
  Matrix9 elastic_tangent_9;           ///< elastic_tangent as a full 9x9 (apex blending)
  AcousticTensorScan scan;

  // Control and time.
  StageControl control;
  bool has_control = false;
  double time = 0.0;
  Vector3 ramp_from = Vector3::Zero();
  double ramp_t0 = 0.0, ramp_t1 = -1.0;
  Vector3 committed_wall_stress = Vector3::Zero();

  // Localization onset (Rice's indicator: only when the material has a plastic tangent).
  bool rice_scan = true;
  double onset_time = -1.0;
  Vector3 onset_position = Vector3::Zero(), onset_normal = Vector3::Zero();
  double q_min = 1.0;

  // Statistics.
  CubeStatistics stats;
  unsigned interval_steps = 0, interval_iterations = 0, interval_cutbacks = 0, interval_relaxed = 0;
  unsigned long interval_updates_from = 0; ///< stats.material_updates at the interval's start

  // Output bookkeeping.
  unsigned measure_count = 0, output_count = 0;
  std::vector<std::pair<double, std::string>> pvd_records;  ///< the main path's series
  std::map<int, std::vector<std::pair<double, std::string>>> branch_records; ///< one series per branch
  int branch = 0;                                           ///< the series being written (0: main)
};

} // namespace geocomp::continuum
