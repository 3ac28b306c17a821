// CubeEngine: the linear solver of the Newton iterations (the model and the method are
// described in CubeEngine.h; measured choices in docs/continuum-fe.md).
#include "continuum/fe/CubeEngineImpl.h"

#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <cmath>
#if defined(GEOCOMP_CUBE_USE_PETSC)
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#else
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#endif

namespace geocomp::continuum {

using namespace dealii;

// @sect3{Linear solver}
//
// GMRES for the non-symmetric tangent of non-associated flow (and of the follower tractions
// at finite strain), CG for a symmetric one, or a direct solver (Amesos/KLU with Trilinos,
// MUMPS with PETSc). The Krylov solvers use algebraic multigrid: ML smoothed aggregation
// (Trilinos), or hypre's BoomerAMG (PETSc; about 9x slower here, the scalar AMG does not know
// the three displacement components belong together). The tolerance is a reduction of the
// initial residual.
//
// ML's near-null space (`near null space`): rigid-body = the six modes of
// rigid_body_modes() handed over as ML "null space: type = pre-computed" (deal.II 9.4's
// AdditionalData::constant_modes is a vector<vector<bool>> and carries only translations),
// or translations = the three DoFTools::extract_constant_modes vectors. Smoothed aggregation
// interpolates exactly what the near-null space spans; with the translations alone the
// coarse levels miss the rotations, which the Chebyshev smoother reduces only slowly, and
// after localization the blocks either side of a band move nearly as rigid bodies. With six
// modes each aggregate carries six coarse unknowns instead of three: ML's set-up and each
// V-cycle cost more, the Krylov iterations drop by 1/4 to 1/3 (docs/continuum-fe.md).
//
// Reuse (Trilinos). The tangent changes at every Newton iteration, but a hierarchy built
// from an earlier tangent still preconditions the new one well while the state changes
// little: ML's fine-level smoother reads the matrix it was built on, which is the same
// object refilled in place, and only the coarse levels are stale. The hierarchy is
// therefore kept across Newton iterations and load steps while it serves. A solve with a
// kept hierarchy may take `amg_rebuild_growth` times the Krylov iterations per decade of
// reduction that the first solve after the last build took (plus 5); when it does not
// converge within that allowance (or breaks down) the hierarchy is rebuilt on the current
// matrix and the solve repeated. It is also rebuilt when the wall constraints change (a new
// control, a restore). amg_rebuild_growth = 0 rebuilds for every solve. PETSc's BoomerAMG
// is rebuilt for every solve.
unsigned CubeEngine::Impl::solve_linear(double reduction)
{
  Timer timer;
  // Relative reduction, with an absolute floor well below what Newton asks for (a right-
  // hand side already at round-off cannot be reduced further).
  ReductionControl control_(prm.max_linear_iterations, 1e-3 * prm.newton_tolerance * residual_scale, reduction);
  update = 0.0;
#if defined(GEOCOMP_CUBE_USE_PETSC)
  if (prm.linear_solver == "direct") {
    PETScWrappers::SparseDirectMUMPS solver(control_, comm);
    solver.solve(matrix, update, rhs);
  } else {
    std::unique_ptr<PETScWrappers::PreconditionBase> preconditioner;
    if (prm.preconditioner != "jacobi") {
      PETScWrappers::PreconditionBoomerAMG::AdditionalData data;
      data.symmetric_operator = prm.linear_solver == "cg";
      data.strong_threshold = 0.7; // measured best for this 3-component problem (docs)
      preconditioner = std::make_unique<PETScWrappers::PreconditionBoomerAMG>(matrix, data);
    } else {
      preconditioner = std::make_unique<PETScWrappers::PreconditionJacobi>(matrix);
    }
    ++stats.preconditioner_builds;
    if (prm.linear_solver == "cg") {
      PETScWrappers::SolverCG solver(control_, comm);
      solver.solve(matrix, update, rhs, *preconditioner);
    } else {
      PETScWrappers::SolverGMRES solver(control_, comm,
                                        PETScWrappers::SolverGMRES::AdditionalData(100, true));
      solver.solve(matrix, update, rhs, *preconditioner);
    }
  }
#else
  if (prm.linear_solver == "direct") {
    TrilinosWrappers::SolverDirect solver(control_);
    solver.solve(matrix, update, rhs);
  } else {
    const bool rebuild = !preconditioner || preconditioner_stale || !(prm.amg_rebuild_growth > 0.0) ||
                         prm.preconditioner == "jacobi"; // a diagonal costs nothing to refresh
    if (rebuild)
      build_preconditioner();
    // A kept hierarchy gets the iterations its first solve needed per decade of reduction,
    // times the growth allowance: past that it no longer serves.
    // A fresh one gets max_linear_iterations (set on every solve: the allowance of a kept
    // one must not carry over to the next build).
    const double decades = std::max(1.0, -std::log10(reduction));
    const bool kept = !rebuild && preconditioner_iterations_per_decade > 0.0;
    control_.set_max_steps(
      kept ? std::min<unsigned>(prm.max_linear_iterations,
                                static_cast<unsigned>(std::ceil(prm.amg_rebuild_growth *
                                                                preconditioner_iterations_per_decade * decades)) +
                                  5)
           : prm.max_linear_iterations);
    auto krylov = [&] {
      if (prm.linear_solver == "cg") {
        TrilinosWrappers::SolverCG solver(control_);
        solver.solve(matrix, update, rhs, *preconditioner);
      } else {
        TrilinosWrappers::SolverGMRES solver(control_, TrilinosWrappers::SolverGMRES::AdditionalData(false, 100));
        solver.solve(matrix, update, rhs, *preconditioner);
      }
    };
    bool fresh = rebuild;
    try {
      krylov();
    } catch (const std::exception &) { // no convergence within the allowance, or a breakdown
      if (fresh)
        throw;
      stats.linear_iterations += control_.last_step(); // the failed attempt counts
      update = 0.0;
      control_.set_max_steps(prm.max_linear_iterations);
      build_preconditioner();
      fresh = true;
      krylov();
    }
    if (fresh)
      preconditioner_iterations_per_decade = std::max(1.0, control_.last_step() / decades);
  }
#endif
  stats.solve_seconds += timer.wall_time();
  stats.linear_iterations += control_.last_step();
  pcout << "      linear: " << control_.last_step() << " its, " << timer.wall_time() << " s, reduction " << reduction << '\n';
  return control_.last_step();
}

#if !defined(GEOCOMP_CUBE_USE_PETSC)
// ML with the near-null space of `near null space`, or Jacobi, built on the current matrix.
void CubeEngine::Impl::build_preconditioner()
{
  if (prm.preconditioner != "jacobi") {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    data.higher_order_elements = prm.degree > 1;
    data.smoother_sweeps = 2;
    data.aggregation_threshold = 0.02;
    data.constant_modes = constant_modes; // the translations, and ML's "PDE equations" = 3
    Teuchos::ParameterList ml;
    std::unique_ptr<Epetra_MultiVector> translations;
    data.set_parameters(ml, translations, matrix);
    if (prm.near_null_space == "rigid-body") {
      ml.set("null space: type", "pre-computed");
      ml.set("null space: dimension", 6);
      ml.set("null space: vectors", rigid_body_modes.data());
    }
    auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(matrix, ml);
    preconditioner = std::move(amg);
  } else {
    auto jacobi = std::make_unique<TrilinosWrappers::PreconditionJacobi>();
    jacobi->initialize(matrix);
    preconditioner = std::move(jacobi);
  }
  preconditioner_stale = false;
  preconditioner_iterations_per_decade = 0.0;
  ++stats.preconditioner_builds;
}
#else
void CubeEngine::Impl::build_preconditioner() {}
#endif

} // namespace geocomp::continuum
