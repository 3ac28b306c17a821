// CubeEngine: setup, assembly, Newton-Raphson with line search, load stepping,
// measurement, save/restore. The model and the method are described in CubeEngine.h;
// the choices (walls, reactions, crack band) and measured behaviour in docs/continuum-fe.md.
#include "continuum/fe/CubeEngineImpl.h"
#include "continuum/driver/LocalizationColumns.h"
#include "continuum/fe/GaussRule.h"
#include "continuum/fe/SecantPairs.h"
#include "continuum/fe/RigidBodyModes.h"
#include "continuum/models/Mandel.h"
#include "continuum/models/PointStateModel.h"


#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#if defined(GEOCOMP_CUBE_USE_PETSC)
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#else
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#endif
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace geocomp::continuum {

using namespace dealii;

namespace {
/// Mandel vector of a symmetric deal.II tensor (see continuum/models/Mandel.h).
Vector6 mandel(const SymmetricTensor<2, 3> &t)
{
  const double s2 = std::sqrt(2.0);
  Vector6 v;
  v << t[0][0], t[1][1], t[2][2], s2 * t[1][2], s2 * t[0][2], s2 * t[0][1];
  return v;
}

/// F = I + Grad u at a point.
Matrix3 deformation_gradient(const Tensor<2, 3> &grad_u)
{
  Matrix3 F = Matrix3::Identity();
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j)
      F(i, j) += grad_u[i][j];
  return F;
}

/// The trial record of a finite-strain point (QuadraturePointData): Cauchy stress, the
/// logarithmic tangent, region, kappa and the history to commit.
void record_finite(QuadraturePointData &d, const FiniteStrainUpdate &f)
{
  d.trial.stress = to_mandel(f.cauchy_stress());
  d.trial.tangent = f.logarithmic_tangent;
  d.trial.region = f.region;
  d.trial.trial_yield_value = f.trial_yield_value;
  d.trial.local_iterations = f.local_iterations;
  d.trial.history.kappa = f.history.kappa;
  d.trial_finite = f.history;
}

void check_parameters(const CubeParameters &p)
{
  auto fail = [](const std::string &name, const std::string &what) {
    throw std::invalid_argument("continuum cube: parameter '" + name + "' " + what);
  };
  if (!(p.side > 0.0))
    fail("side", "must be > 0");
  if (p.cells_per_side < 1)
    fail("cells per side", "must be >= 1");
  if (!p.box_edges.isZero() && !(p.box_edges.minCoeff() > 0.0))
    fail("box edges", "must all be > 0 (or all 0: the cube)");
  if (p.box_cells[0] != 0 && (p.box_cells[0] < 1 || p.box_cells[1] < 1 || p.box_cells[2] < 1))
    fail("box cells", "must all be >= 1 (or all 0: cells per side on every axis)");
  if (p.degree < 1 || p.degree > 3)
    fail("degree", "must be 1, 2 or 3");
  if (const std::string problem = gauss_points_problem(p.degree, p.quadrature_points); !problem.empty())
    fail("quadrature points", problem);
  if (p.linear_solver != "gmres" && p.linear_solver != "cg" && p.linear_solver != "direct")
    fail("linear solver", "must be gmres, cg or direct");
  if (p.preconditioner != "amg" && p.preconditioner != "boomeramg" && p.preconditioner != "ml" &&
      p.preconditioner != "jacobi")
    fail("preconditioner", "must be amg (aliases: boomeramg, ml) or jacobi");
  if (p.near_null_space != "rigid-body" && p.near_null_space != "translations")
    fail("near null space", "must be rigid-body or translations");
  if (!(p.linear_tolerance > 0.0 && p.linear_tolerance < 1.0))
    fail("linear tolerance", "must be in (0, 1)");
  if (!(p.newton_tolerance > 0.0 && p.newton_tolerance < 1.0))
    fail("newton tolerance", "must be in (0, 1)");
  if (!(p.newton_stagnation_factor >= 0.0 && p.newton_stagnation_factor * p.newton_tolerance < 1.0))
    fail("newton stagnation factor", "must be >= 0, with factor * newton tolerance < 1");
  if (p.threads < 1 || p.threads > 1024)
    fail("threads", "must be in 1..1024");
  if (p.max_newton_iterations < 1 || p.steps_per_advance < 1 || p.stall_iterations < 1)
    fail("max newton iterations / steps per advance / stall iterations", "must be >= 1");
  if (!(p.imperfection_radius >= 0.0))
    fail("imperfection radius", "must be >= 0");
  if (!(p.imperfection_cohesion_factor > 0.0 && p.imperfection_cohesion_factor <= 1.0))
    fail("imperfection cohesion factor", "must be in (0, 1]");
  if (p.regularization != "crack-band" && p.regularization != "none")
    fail("regularization", "must be crack-band or none");
  if (p.volumetric_integration != "full" && p.volumetric_integration != "b-bar")
    fail("volumetric integration", "must be full or b-bar");
  if (p.volumetric_integration == "b-bar" && p.kinematics == Kinematics::finite_strain)
    fail("volumetric integration", "b-bar is a small-strain method: use it with kinematics = small strain");
  if (!(p.band_reference_width >= 0.0))
    fail("band reference width", "must be >= 0");
  if (p.localization_directions < 10)
    fail("localization directions", "must be >= 10");
  if (!(p.amg_rebuild_growth >= 0.0))
    fail("amg rebuild growth", "must be >= 0");
  if (!(p.apex_tangent_fraction >= 0.0 && p.apex_tangent_fraction < 1.0))
    fail("apex tangent fraction", "must be in [0, 1)");
  if (p.output_every < 1)
    fail("output every", "must be >= 1");
}
} // namespace

void check_cube_parameters(const CubeParameters &p) { check_parameters(p); }

// @sect3{Setup}

CubeEngine::Impl::Impl(const CubeParameters &p, std::shared_ptr<const MaterialFactory> f, MPI_Comm c)
  : comm(c)
  , prm(p)
  , factory(std::move(f))
  , pcout(std::cout, p.verbose && Utilities::MPI::this_mpi_process(c) == 0)
  , tria(c)
  , fe(FE_Q<3>(p.degree), 3)
  , dof_handler(tria)
  , quadrature(gauss_rule(p.degree, p.quadrature_points))
  , face_quadrature(p.degree + 1)
  , scan([&] {
    AcousticTensorScan::Options o;
    o.coarse_points = static_cast<int>(p.localization_directions);
    return o;
  }())
{
  check_parameters(prm);
  if (!factory)
    throw std::invalid_argument("continuum cube: no material");
  make_mesh_and_dofs();
  setup_quadrature_data();
}

// The box is meshed as reps_x x reps_y x reps_z coarse cells refined k times with
// n_a = reps_a 2^k, so p4est has few trees and the refinement is uniform; colorize gives
// the walls the boundary ids 0..5 = x=0, x=L_x, y=0, y=L_y, z=0, z=L_z.
void CubeEngine::Impl::make_mesh_and_dofs()
{
  std::array<unsigned, 3> reps = prm.cells();
  unsigned levels = 0;
  const auto halvable = [&reps] {
    return std::all_of(reps.begin(), reps.end(), [](unsigned n) { return n % 2 == 0 && n > 2; });
  };
  while (halvable()) {
    for (unsigned &n : reps)
      n /= 2;
    ++levels;
  }
  const Vector3 L = prm.edges();
  GridGenerator::subdivided_hyper_rectangle(tria, {reps[0], reps[1], reps[2]}, Point<3>(0, 0, 0),
                                            Point<3>(L[0], L[1], L[2]), /*colorize=*/true);
  tria.refine_global(levels);
  const std::array<unsigned, 3> n = prm.cells();
  h_e = prm.box_edges.isZero() ? prm.side / prm.cells_per_side // the cube, as it always was
                               : std::cbrt(L.prod() / (double(n[0]) * n[1] * n[2])); // the cube root of the cell volume

  dof_handler.distribute_dofs(fe);
  owned = dof_handler.locally_owned_dofs();
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

  for (unsigned a = 0; a < 3; ++a) {
    ComponentMask mask(3, false);
    mask.set(a, true);
    top_face_dofs[a] = DoFTools::extract_boundary_dofs(dof_handler, mask, {types::boundary_id(2 * a + 1)});
    bottom_face_dofs[a] = DoFTools::extract_boundary_dofs(dof_handler, mask, {types::boundary_id(2 * a)});
    top_face_dofs[a] = top_face_dofs[a] & relevant;
    bottom_face_dofs[a] = bottom_face_dofs[a] & relevant;
  }

  // The full coupling pattern: the wall constraints only fix dofs, so one pattern serves
  // every control (the constrained rows are condensed at assembly).
  DynamicSparsityPattern dsp(relevant);
  DoFTools::make_sparsity_pattern(dof_handler, dsp);
  SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
  matrix.reinit(owned, owned, dsp, comm);
  DoFTools::extract_constant_modes(dof_handler, ComponentMask(3, true), constant_modes);
  make_rigid_body_modes();

  solution.reinit(owned, relevant, comm);
  solution_owned.reinit(owned, comm);
  old_solution.reinit(owned, comm);
  rhs.reinit(owned, comm);
  internal_force.reinit(owned, comm);
  update.reinit(owned, comm);
}

// The near-null space of the AMG. Smoothed aggregation builds its coarse spaces from the
// vectors the operator hardly sees; for 3D elasticity these are the rigid-body motions
//     u = a + w x (x - c),   a, w in R^3,
// six modes, K u = 0 for the unconstrained stiffness (rigid motions have zero strain). With
// the translations only, the coarse levels cannot represent rotations, which the fine
// smoother damps at a rate that decays with h^2: the number of Krylov iterations then
// grows with the mesh. The modes are evaluated at the support points of the locally owned
// dofs: column k of the n_owned x 6 block is e_k (k < 3) or e_{k-3} x (x - c).
std::vector<double> rigid_body_modes(const DoFHandler<3> &dof_handler, const IndexSet &owned,
                                     const Point<3> &centre)
{
  const FiniteElement<3> &fe = dof_handler.get_fe();
  const std::size_t n = owned.n_elements();
  std::vector<double> modes(6 * n, 0.0);
  const Quadrature<3> support(fe.get_unit_support_points());
  FEValues<3> fe_values(fe, support, update_quadrature_points);
  std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
  for (const auto &cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue; // every owned dof lies on an owned cell
    fe_values.reinit(cell);
    cell->get_dof_indices(dof_indices);
    for (unsigned i = 0; i < dof_indices.size(); ++i) {
      if (!owned.is_element(dof_indices[i]))
        continue;
      const std::size_t row = owned.index_within_set(dof_indices[i]);
      const unsigned a = fe.system_to_component_index(i).first;
      const Tensor<1, 3> r = fe_values.quadrature_point(i) - centre;
      modes[a * n + row] = 1.0;
      // Component a of e_k x r: eps_{a k m} r_m, m the third index (a != k).
      for (unsigned k = 0; k < 3; ++k)
        if (k != a)
          modes[(3 + k) * n + row] = ((k + 3 - a) % 3 == 1 ? 1.0 : -1.0) * r[3 - a - k];
    }
  }
  return modes;
}

void CubeEngine::Impl::make_rigid_body_modes()
{
  const Vector3 c = 0.5 * prm.edges();
  rigid_body_modes = continuum::rigid_body_modes(dof_handler, owned, Point<3>(c[0], c[1], c[2]));
}

// Every locally owned quadrature point gets its history, its position and its material:
// the base material with the crack-band scale of this mesh, or inside the imperfection
// the same with reduced cohesion.
void CubeEngine::Impl::setup_quadrature_data()
{
  MaterialVariant base, weak;
  if (prm.regularization == "crack-band") {
    const double l_ref = prm.band_reference_width > 0.0 ? prm.band_reference_width
                             : prm.box_edges.isZero() ? prm.side
                                                      : std::cbrt(prm.edges().prod());
    base.softening_scale = l_ref / h_e;
  }
  weak = base;
  weak.cohesion_factor = prm.imperfection_cohesion_factor;
  materials[base] = factory->make(base);
  if (prm.imperfection_radius > 0.0)
    materials[weak] = factory->make(weak);
  rice_scan = materials[base]->has_plastic_tangent();
  elastic_tangent = materials[base]->elasticity().stiffness();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          elastic_tangent_9(pair_index(i, j), pair_index(k, l)) = tensor4_component(elastic_tangent, i, j, k, l);
  prestrain = materials[base]->elasticity().compliance() * to_mandel(prm.initial_stress * Tensor3::Identity());
  // The walls carry the initial stress from the start (the first sample reports it).
  committed_wall_stress = Vector3::Constant(prm.initial_stress);

  FEValues<3> fe_values(fe, quadrature, update_quadrature_points | update_JxW_values);
  const Point<3> centre(prm.imperfection_centre[0], prm.imperfection_centre[1], prm.imperfection_centre[2]);
  for (const auto &cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    qp_data.initialize(Cell(cell), quadrature.size());
    fe_values.reinit(cell);
    const auto data = qp_data.get_data(Cell(cell));
    for (unsigned q = 0; q < quadrature.size(); ++q) {
      QuadraturePointData &d = *data[q];
      const Point<3> &x = fe_values.quadrature_point(q);
      d.position = Vector3(x[0], x[1], x[2]);
      d.JxW = fe_values.JxW(q);
      d.weak = prm.imperfection_radius > 0.0 && x.distance(centre) < prm.imperfection_radius;
      d.material = (d.weak ? materials[weak] : materials[base]).get();
      if (prm.kinematics == Kinematics::finite_strain) {
        d.old_finite = initial_finite_strain_history(*d.material, prm.initial_stress * Tensor3::Identity());
        record_finite(d, finite_strain_update(*d.material, Matrix3::Identity(), d.old_finite));
      } else {
        // Empty for the plasticity models; a point-state model's state anchored at eps_0.
        d.old_history = d.material->initial_history(prestrain);
        d.trial = d.material->update(prestrain, d.old_history);
      }
      d.old_stress = d.trial.stress;
    }
  }
}

// Homogeneous wall constraints of the current control: the normal component on the three
// fixed walls, and on the moving walls of kinematic axes.
void CubeEngine::Impl::build_constraints()
{
  constraints.clear();
  constraints.reinit(relevant);
  for (unsigned a = 0; a < 3; ++a) {
    for (const auto i : bottom_face_dofs[a])
      constraints.add_line(i);
    if (control.kinematic(a))
      for (const auto i : top_face_dofs[a])
        constraints.add_line(i);
  }
  constraints.close();
}

double CubeEngine::Impl::target_stress(int axis, double t) const
{
  const double target = control.target_stress(axis);
  if (ramp_t1 <= ramp_t0 || t >= ramp_t1)
    return target;
  const double f = std::clamp((t - ramp_t0) / (ramp_t1 - ramp_t0), 0.0, 1.0);
  return ramp_from[axis] + f * (target - ramp_from[axis]);
}

// @sect3{Assembly}
//
// One pass over the locally owned cells evaluates the material at every quadrature point
// for the current iterate and adds the cell's internal force, tractions and tangent
// (cell_small_strain / cell_finite_strain, cell_tractions). The residual is condensed with
// the homogeneous wall constraints (constrained rows vanish); the unconstrained internal
// force is kept for the wall reactions.
struct CubeEngine::Impl::CellTerms {
  CellTerms(const Impl &m, bool matrix)
    : fe_values(m.fe, m.quadrature, update_gradients | update_JxW_values)
    , fe_face_values(m.fe, m.face_quadrature, update_values | update_gradients | update_JxW_values)
    , with_matrix(matrix)
    , matrix(m.fe.n_dofs_per_cell(), m.fe.n_dofs_per_cell())
    , force(m.fe.n_dofs_per_cell())
    , external(m.fe.n_dofs_per_cell())
    , dof_indices(m.fe.n_dofs_per_cell())
    , strains(m.quadrature.size())
    , gradients(m.quadrature.size())
    , face_gradients(m.face_quadrature.size())
    , b(m.fe.n_dofs_per_cell())
    , Cb(m.fe.n_dofs_per_cell())
    , mean_div(m.fe.n_dofs_per_cell())
    , spatial(m.fe.n_dofs_per_cell())
    , component(m.fe.n_dofs_per_cell())
    , w(9, m.fe.n_dofs_per_cell())
  {
    for (unsigned i = 0; i < component.size(); ++i)
      component[i] = m.fe.system_to_component_index(i).first;
  }
  void reinit(const DoFHandler<3>::active_cell_iterator &c)
  {
    cell = c;
    fe_values.reinit(cell);
    cell->get_dof_indices(dof_indices);
    matrix = 0.0;
    force = 0.0;
    external = 0.0;
  }

  FEValues<3> fe_values;
  FEFaceValues<3> fe_face_values;
  DoFHandler<3>::active_cell_iterator cell;
  bool with_matrix;
  FullMatrix<double> matrix;              ///< K of the cell
  dealii::Vector<double> force, external; ///< F_int, F_ext of the cell
  std::vector<types::global_dof_index> dof_indices;
  // Scratch.
  std::vector<SymmetricTensor<2, 3>> strains;
  std::vector<Tensor<2, 3>> gradients, face_gradients;
  std::vector<Vector6> b, Cb;
  std::vector<double> mean_div;
  std::vector<Vector3> spatial;     ///< grad_x N_i = F^-T Grad N_i (row `component[i]`)
  std::vector<unsigned> component;  ///< the one nonzero component of shape function i
  Eigen::Matrix<double, 9, Eigen::Dynamic> w; ///< (J a) : grad_x N_j, column j
};

// Small strain:
//     R_i = int B_i : sigma dV - int_{Gamma_t} N_i . t dA,   K_ij = int B_i : C_alg : B_j dV.
// With Mandel vectors b_i of sym grad N_i, B_i : sigma = b_i . sigma_M and
// B_i : C : B_j = b_i . (C_M b_j).
//
// B-bar (Hughes 1980, `volumetric integration = b-bar`): the volumetric part of the strain
// and of every b_i is replaced by its cell average,
//     eps_bar = eps + (1/3)(<tr eps> - tr eps) I,   b_bar_i = b_i + (1/3)(<div N_i> - div N_i) m,
// with <.> = int_cell (.) dV / V_cell and m the Mandel identity. Homogeneous fields are
// unchanged; for Q1 the volumetric constraints drop from 8 to 1 per cell, so nearly
// isochoric plastic flow no longer locks. K_ij = int b_bar_i . C b_bar_j stays the exact
// derivative of the B-bar residual.
void CubeEngine::Impl::small_strains(CellTerms &c) const
{
  const FEValuesExtractors::Vector displacement(0);
  FEValues<3> &fv = c.fe_values;
  const unsigned dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
  fv[displacement].get_function_symmetric_gradients(solution, c.strains);
  if (prm.volumetric_integration == "b-bar") {
    double volume = 0.0, mean_trace = 0.0;
    std::fill(c.mean_div.begin(), c.mean_div.end(), 0.0);
    for (unsigned q = 0; q < n_q; ++q) {
      const double JxW = fv.JxW(q);
      volume += JxW;
      mean_trace += trace(c.strains[q]) * JxW;
      for (unsigned i = 0; i < dofs_per_cell; ++i)
        c.mean_div[i] += fv[displacement].divergence(i, q) * JxW;
    }
    mean_trace /= volume;
    for (double &d : c.mean_div)
      d /= volume;
    for (unsigned q = 0; q < n_q; ++q)
      c.strains[q] += ((mean_trace - trace(c.strains[q])) / 3.0) * unit_symmetric_tensor<3>();
  }
}

bool CubeEngine::Impl::cell_small_strain(CellTerms &c)
{
  const FEValuesExtractors::Vector displacement(0);
  FEValues<3> &fv = c.fe_values;
  const unsigned dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
  const bool bbar = prm.volumetric_integration == "b-bar";
  const Vector6 m = mandel_identity();
  small_strains(c);
  const auto data = qp_data.get_data(Cell(c.cell));
  bool ok = true;
  for (unsigned q = 0; q < n_q; ++q) {
    QuadraturePointData &d = *data[q];
    try {
      d.trial = small_update(d, mandel(c.strains[q]) + prestrain);
    } catch (const ReturnMapFailure &) {
      ok = false; // every rank still finishes the pass (collective compress in assemble)
      d.trial.stress = d.old_stress;
      d.trial.tangent = elastic_tangent;
    }
    const Vector6 &sigma = d.trial.stress;
    const double JxW = fv.JxW(q);
    for (unsigned i = 0; i < dofs_per_cell; ++i) {
      c.b[i] = mandel(fv[displacement].symmetric_gradient(i, q));
      if (bbar)
        c.b[i] += ((c.mean_div[i] - fv[displacement].divergence(i, q)) / 3.0) * m;
      c.force(i) += c.b[i].dot(sigma) * JxW;
    }
    if (c.with_matrix) {
      const Matrix6 C = d.trial.region == ReturnRegion::apex
                          ? Matrix6(d.trial.tangent + prm.apex_tangent_fraction * elastic_tangent)
                          : d.trial.tangent;
      for (unsigned j = 0; j < dofs_per_cell; ++j)
        c.Cb[j] = C * c.b[j];
      for (unsigned i = 0; i < dofs_per_cell; ++i)
        for (unsigned j = 0; j < dofs_per_cell; ++j)
          c.matrix(i, j) += c.b[i].dot(c.Cb[j]) * JxW;
    }
  }
  return ok;
}

// Finite strain, total Lagrangian (the reference mesh is integrated; deal.II step-44):
//     F = I + Grad u,   R_i = int_Omega0 grad_x N_i : tau dV0 - F_ext,i,
//     K_ij = int_Omega0 grad_x N_i : (J a) : grad_x N_j dV0 + (load stiffness),
// with grad_x N = Grad N F^{-1}, tau the Kirchhoff stress and J a the spatial tangent of
// FiniteStrain.h (geometric stiffness included: (J a) : H = d tau - tau H^T). For the
// primitive vector element every shape function has one nonzero component a_i, so
// grad_x N_i has one nonzero row, F^-T Grad N_i.
bool CubeEngine::Impl::cell_finite_strain(CellTerms &c)
{
  const FEValuesExtractors::Vector displacement(0);
  FEValues<3> &fv = c.fe_values;
  const unsigned dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
  fv[displacement].get_function_gradients(solution, c.gradients);
  const auto data = qp_data.get_data(Cell(c.cell));
  bool ok = true;
  auto &w = c.w;
  for (unsigned q = 0; q < n_q; ++q) {
    QuadraturePointData &d = *data[q];
    Matrix3 F = deformation_gradient(c.gradients[q]);
    Matrix3 tau;
    Matrix9 T;
    try {
      const FiniteStrainUpdate f = finite_update(d, F);
      record_finite(d, f);
      tau = f.kirchhoff_stress;
      T = f.region == ReturnRegion::apex ? Matrix9(f.spatial_tangent + prm.apex_tangent_fraction * elastic_tangent_9)
                                         : f.spatial_tangent;
    } catch (const ReturnMapFailure &) {
      ok = false; // every rank still finishes the pass (collective compress in assemble)
      F = d.old_finite.deformation_gradient;
      tau = from_mandel(d.old_stress) * F.determinant();
      T = elastic_tangent_9;
    }
    const Matrix3 F_inv_T = F.inverse().transpose();
    const double JxW = fv.JxW(q);
    for (unsigned i = 0; i < dofs_per_cell; ++i) {
      const Tensor<1, 3> G = fv.shape_grad(i, q);
      c.spatial[i] = F_inv_T * Vector3(G[0], G[1], G[2]);
      c.force(i) += c.spatial[i].dot(tau.row(c.component[i])) * JxW;
    }
    if (!c.with_matrix)
      continue;
    // w_j = (J a) : grad_x N_j, then K_ij = grad_x N_i : w_j.
    for (unsigned j = 0; j < dofs_per_cell; ++j)
      w.col(j) = T.middleCols<3>(3 * c.component[j]) * c.spatial[j];
    for (unsigned i = 0; i < dofs_per_cell; ++i) {
      const unsigned a = c.component[i];
      for (unsigned j = 0; j < dofs_per_cell; ++j)
        c.matrix(i, j) += c.spatial[i].dot(w.col(j).segment<3>(3 * a)) * JxW;
    }
  }
  return ok;
}

// Tractions on the moving walls of stress axes: a frictionless wall pushes along e_a only,
// with the program's stress per CURRENT area of the face projected on the wall (the DEM's
// wall force over the wall area):
//     F_ext,i = int_{Gamma0_a} N_i sigma*_a cof(F)_aa dA0,   cof(F)_aa = F_bb F_cc - F_bc F_cb
// (Nanson: n da = cof(F) N dA, N = e_a), a follower load whose linearization
// d cof(F)_aa = F_cc dF_bb + F_bb dF_cc - F_cb dF_bc - F_bc dF_cb enters K as -dF_ext/du.
// At small strain cof(F)_aa = 1: the load per initial area.
void CubeEngine::Impl::cell_tractions(CellTerms &c, double t)
{
  const bool finite = prm.kinematics == Kinematics::finite_strain;
  const FEValuesExtractors::Vector displacement(0);
  FEFaceValues<3> &fv = c.fe_face_values;
  const unsigned dofs_per_cell = fe.n_dofs_per_cell();
  for (unsigned a = 0; a < 3; ++a) {
    if (control.kinematic(a))
      continue;
    const double traction = target_stress(a, t);
    const unsigned b = (a + 1) % 3, e = (a + 2) % 3;
    for (const unsigned f : c.cell->face_indices()) {
      if (!c.cell->face(f)->at_boundary() || c.cell->face(f)->boundary_id() != 2 * a + 1)
        continue;
      fv.reinit(c.cell, f);
      if (finite)
        fv[displacement].get_function_gradients(solution, c.face_gradients);
      for (unsigned q = 0; q < face_quadrature.size(); ++q) {
        Matrix3 F = Matrix3::Identity();
        if (finite)
          for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
              F(i, j) += c.face_gradients[q][i][j];
        const double area = F(b, b) * F(e, e) - F(b, e) * F(e, b);
        for (unsigned i = 0; i < dofs_per_cell; ++i) {
          if (c.component[i] != a)
            continue;
          const double load = fv.shape_value(i, q) * traction * fv.JxW(q);
          c.external(i) += load * area;
          if (!finite || !c.with_matrix)
            continue;
          for (unsigned j = 0; j < dofs_per_cell; ++j) {
            const Tensor<1, 3> G = fv.shape_grad(j, q);
            double d_area = 0.0;
            if (c.component[j] == b)
              d_area = F(e, e) * G[b] - F(e, b) * G[e];
            else if (c.component[j] == e)
              d_area = F(b, b) * G[e] - F(b, e) * G[b];
            c.matrix(i, j) -= load * d_area;
          }
        }
      }
    }
  }
}

// @sect4{The points' updates: memorized, and on threads}
//
// A material update is a pure function of the point's input (its strain, or F) and its
// committed history. Each point keeps its last update with that input (QuadraturePointData::
// Memo), valid while the committed history is unchanged (history_epoch: raised by commit and
// restore); an update asked again for the same doubles takes the memo, bit for bit. Newton
// asks twice at every iterate: the line search evaluates the residual at u + alpha du, and the
// next iteration assembles its tangent at the same u - for an RVE per point the second
// evaluation was half the cost of a load step.
//
// With threads > 1 each assembly pass first computes every locally owned point's input (its
// strain, or F, exactly as the pass will: the same FEValues calls) and then the updates its
// memo does not hold, on `threads` OpenMP threads, one point per task (an RVE per point costs
// 10^5 to 10^7 times a return map, and the points' costs differ: dynamic schedule). The pass
// then finds them in the memos. The pass sums in cell order as before: the same bits for any
// thread count.
namespace {
template <class Input>
bool memo_holds(const QuadraturePointData::Memo &memo, unsigned long epoch, const Input &memorized,
                const Input &input)
{
  return memo.epoch == epoch && memorized == input;
}
} // namespace

void CubeEngine::Impl::update_points_ahead()
{
  if (prm.threads <= 1)
    return;
  const bool finite = prm.kinematics == Kinematics::finite_strain;
  CellTerms terms(*this, false);
  std::vector<QuadraturePointData *> points;
  std::vector<Matrix3> gradients;
  std::vector<Vector6> strains;
  for (const auto &cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    terms.reinit(cell);
    if (finite)
      terms.fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(solution, terms.gradients);
    else
      small_strains(terms);
    const auto data = qp_data.get_data(Cell(cell));
    for (unsigned q = 0; q < data.size(); ++q) {
      QuadraturePointData &d = *data[q];
      const Matrix3 F = finite ? deformation_gradient(terms.gradients[q]) : Matrix3::Identity();
      const Vector6 strain = finite ? Vector6::Zero() : Vector6(mandel(terms.strains[q]) + prestrain);
      if (finite ? memo_holds(d.memo, history_epoch, d.memo.deformation_gradient, F)
                 : memo_holds(d.memo, history_epoch, d.memo.strain, strain))
        continue;
      points.push_back(&d);
      gradients.push_back(F);
      strains.push_back(strain);
    }
  }
  std::vector<std::string> errors(points.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(prm.threads)
  for (std::size_t k = 0; k < points.size(); ++k) {
    try {
      memorize(*points[k], gradients[k], strains[k]);
    } catch (const std::exception &e) {
      errors[k] = e.what(); // no exception leaves an OpenMP region (the memo stays invalid)
    }
  }
  stats.material_updates += points.size();
  for (const std::string &e : errors)
    if (!e.empty())
      throw std::runtime_error(e);
}

void CubeEngine::Impl::memorize(QuadraturePointData &d, const Matrix3 &F, const Vector6 &strain) const
{
  QuadraturePointData::Memo &memo = d.memo;
  memo.epoch = 0;
  memo.failed = false;
  memo.deformation_gradient = F;
  memo.strain = strain;
  try {
    if (prm.kinematics == Kinematics::finite_strain)
      memo.finite = finite_strain_update(*d.material, F, d.old_finite);
    else
      memo.small = d.material->update(strain, d.old_history);
  } catch (const ReturnMapFailure &) {
    memo.failed = true;
  }
  memo.epoch = history_epoch;
}

MaterialPointUpdate CubeEngine::Impl::small_update(QuadraturePointData &d, const Vector6 &strain)
{
  if (!memo_holds(d.memo, history_epoch, d.memo.strain, strain)) {
    ++stats.material_updates;
    memorize(d, Matrix3::Identity(), strain);
  }
  if (d.memo.failed)
    throw ReturnMapFailure("the point's material update failed");
  return d.memo.small;
}

FiniteStrainUpdate CubeEngine::Impl::finite_update(QuadraturePointData &d, const Matrix3 &F)
{
  if (!memo_holds(d.memo, history_epoch, d.memo.deformation_gradient, F)) {
    ++stats.material_updates;
    memorize(d, F, Vector6::Zero());
  }
  if (d.memo.failed)
    throw ReturnMapFailure("the point's material update failed");
  return d.memo.finite;
}

double CubeEngine::Impl::assemble(double t, bool with_matrix, bool predictor)
{
  Timer timer;
  if (!with_matrix)
    ++stats.residual_assemblies;
  update_points_ahead();
  CellTerms terms(*this, with_matrix);
  if (with_matrix)
    matrix = 0.0;
  rhs = 0.0;
  internal_force = 0.0;
  double external_norm2 = 0.0;
  bool failed = false;

  for (const auto &cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    terms.reinit(cell);
    const bool ok = prm.kinematics == Kinematics::finite_strain ? cell_finite_strain(terms) : cell_small_strain(terms);
    failed = failed || !ok;
    cell_tractions(terms, t);
    external_norm2 += terms.external.norm_sqr(); // |F_ext|^2 up to shared-node cross terms
    internal_force.add(terms.dof_indices, terms.force);
    terms.external -= terms.force; // -R = F_ext - F_int
    if (with_matrix)
      (predictor ? predictor_constraints : constraints)
        .distribute_local_to_global(terms.matrix, terms.external, terms.dof_indices, matrix, rhs);
    else
      constraints.distribute_local_to_global(terms.external, terms.dof_indices, rhs);
  }
  if (with_matrix)
    matrix.compress(VectorOperation::add);
  rhs.compress(VectorOperation::add);
  internal_force.compress(VectorOperation::add);

  const double f_int = internal_force.l2_norm();
  const double f_ext = std::sqrt(Utilities::MPI::sum(external_norm2, comm));
  // Floor: the force of a stress of 1e-6 of the elastic modulus on one cell face.
  const double floor = 1e-6 * elastic_tangent(0, 0) * h_e * h_e;
  residual_scale = std::max({f_int, f_ext, floor});
  stats.assembly_seconds += timer.wall_time();
  if (Utilities::MPI::max(failed ? 1 : 0, comm) != 0)
    return std::numeric_limits<double>::quiet_NaN(); // a return map failed: cut back
  return rhs.l2_norm();
}

// @sect3{Newton-Raphson for one load step}
//
// Predictor: the tangent at the committed state with the increments of the wall
// displacements as inhomogeneous constraints (exact for a linear problem). Corrector:
// K du = -R with homogeneous wall constraints, u <- u + alpha du, alpha halved (at most
// `line_search_steps` times) until |R(u + alpha du)| <= (1 - 1e-4 alpha) |R(u)|.
// Converged when |R_free| <= newton_tolerance * max(|F_int|, |F_ext|).
bool CubeEngine::Impl::solve_step(double t)
{
  const Vector3 L = prm.edges();
  std::array<double, 3> wall{};
  for (unsigned a = 0; a < 3; ++a)
    wall[a] = control.kinematic(a) ? control.strain(a, t) * L[a] : 0.0;

  predictor_constraints.clear();
  predictor_constraints.reinit(relevant);
  for (unsigned a = 0; a < 3; ++a) {
    for (const auto i : bottom_face_dofs[a])
      predictor_constraints.add_line(i);
    if (control.kinematic(a))
      for (const auto i : top_face_dofs[a]) {
        predictor_constraints.add_line(i);
        predictor_constraints.set_inhomogeneity(i, wall[a] - solution(i));
      }
  }
  predictor_constraints.close();

  stats.last_step_residuals.clear();
  try {
    assemble(t, true, true);
    solve_linear(prm.linear_tolerance); // exact predictor: one solve per elastic step
  } catch (const std::exception &e) {
    pcout << "    predictor failed: " << e.what() << '\n';
    return false;
  }
  predictor_constraints.distribute(update);
  solution_owned = old_solution;
  solution_owned += update;
  // The walls exactly where the program puts them (no accumulated round-off).
  for (unsigned a = 0; a < 3; ++a)
    if (control.kinematic(a))
      for (const auto i : top_face_dofs[a])
        if (owned.is_element(i))
          solution_owned(i) = wall[a];
  solution_owned.compress(VectorOperation::insert);
  solution = solution_owned;

  unsigned iterations = 1;
  double r = assemble(t, false, false), previous = std::numeric_limits<double>::infinity();
  const bool quasi_newton = prm.secant_pairs > 0;
  SecantPairs<LA::MPI::Vector> pairs(prm.secant_pairs);
  bool no_descent = false;
  while (true) {
    const double rel = r / residual_scale;
    stats.last_step_residuals.push_back(rel);
    pcout << "    t = " << t << "  it " << iterations << "  |R|/F = " << rel << '\n';
    if (!std::isfinite(rel))
      return false;
    if (rel <= prm.newton_tolerance)
      break;
    // Stagnation at a kink: where points cross a breakpoint of a piecewise-linear c, phi or
    // psi table the return is not differentiable and Newton can only creep; a residual
    // below newton_stagnation_factor * newton_tolerance that an iteration no longer halves
    // is accepted.
    if (rel <= prm.newton_stagnation_factor * prm.newton_tolerance && rel > 0.5 * previous) {
      ++interval_relaxed;
      ++stats.relaxed_steps;
      break;
    }
    // With secant pairs, a line search that lowered |R| at no step length has found the floor
    // of the material's answer (a DEM cell's: its grains' fluctuation): above the stagnation
    // tolerance the step is cut back rather than iterated further from a worse iterate.
    if (no_descent)
      return false;
    previous = rel;
    // A step whose last `stall_iterations` iterations have not halved the residual is cut
    // back at once: it stalls at a floor (loading/unloading switches near a bifurcation)
    // that the remaining iterations do not lower, and a smaller step is the cheaper remedy.
    const auto &h = stats.last_step_residuals;
    const std::size_t window = prm.stall_iterations;
    if (iterations >= prm.max_newton_iterations || (h.size() > window && rel > 0.5 * h[h.size() - 1 - window]))
      return false;
    ++iterations;
    // The tangent of every iterate (Newton), or of the step's first corrector only, its
    // pairs then updating the step (BFGS, SecantPairs.h).
    if (!quasi_newton || iterations == 2)
      assemble(t, true, false);
    try {
      // Inexact Newton (Eisenstat-Walker type forcing): the Krylov reduction follows the
      // Newton residual, eta = 0.1 |R|/F, which keeps the quadratic rate
      // (|R_next| ~ max(eta |R|, C |R|^2)) at a fraction of the iterations; safeguard
      // against over-solving: the linear residual need not go below 0.1 newton_tolerance F,
      // so eta >= 0.1 tol / (|R|/F); eta within [linear_tolerance, 1e-3].
      const double rel = r / residual_scale;
      const double eta =
        std::clamp(std::max(std::min(0.1 * rel, 1e-3), std::min(0.1 * prm.newton_tolerance / rel, 1e-3)),
                   prm.linear_tolerance, 1e-3);
      if (quasi_newton) {
        LA::MPI::Vector direction(rhs);
        pairs.apply(direction, [&](LA::MPI::Vector &w) {
          const LA::MPI::Vector residual(rhs);
          rhs = w;
          solve_linear(eta);
          w = update;
          rhs = residual;
        });
        update = direction;
      } else {
        solve_linear(eta);
      }
    } catch (const std::exception &e) {
      pcout << "    linear solve failed: " << e.what() << '\n';
      return false;
    }
    constraints.distribute(update);
    const LA::MPI::Vector base(solution_owned), base_rhs(rhs);
    double alpha = 1.0, r_trial = 0.0;
    for (unsigned ls = 0;; ++ls) {
      solution_owned = base;
      solution_owned.add(alpha, update);
      solution = solution_owned;
      r_trial = assemble(t, false, false);
      if (r_trial <= (1.0 - 1e-4 * alpha) * r || ls >= prm.line_search_steps)
        break;
      alpha *= 0.5;
    }
    if (alpha < 1.0)
      pcout << "      line search: alpha = " << alpha << '\n';
    no_descent = quasi_newton && !(r_trial < r);
    if (quasi_newton && std::isfinite(r_trial)) {
      LA::MPI::Vector s(update), y(base_rhs);
      s *= alpha;
      y -= rhs; // y = R(u + alpha du) - R(u), rhs being -R
      pairs.add(s, y);
    }
    r = r_trial;
  }
  stats.last_step_iterations = iterations;
  interval_iterations += iterations;
  stats.newton_iterations += iterations;
  return true;
}

void CubeEngine::Impl::commit()
{
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : qp_data.get_data(cell)) {
        d->old_history = d->trial.history;
        d->old_finite = d->trial_finite;
        d->old_stress = d->trial.stress;
        d->old_region = d->trial.region;
      }
  ++history_epoch; // every memo belonged to the history just replaced
  old_solution = solution_owned;
  committed_wall_stress = wall_stresses();
}

void CubeEngine::Impl::revert()
{
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : qp_data.get_data(cell)) {
        d->trial.history = d->old_history;
        d->trial_finite = d->old_finite;
        d->trial.stress = d->old_stress;
        d->trial.region = d->old_region;
      }
  solution_owned = old_solution;
  solution = solution_owned;
}

// @sect3{Localization indicator}
//
// Rice's indicator at every plastic quadrature point of the committed state (elastic
// points have q = 1), the global minimum, and the first time it reaches 0: that point's
// position and band normal are the onset record. A material without a plastic tangent (a
// point-state model) has nothing to scan: no indicator, no columns (extra_columns()).
void CubeEngine::Impl::update_localization(double t)
{
  if (!rice_scan)
    return;
  struct {
    double q;
    int rank;
  } local{1.0, static_cast<int>(Utilities::MPI::this_mpi_process(comm))}, global{};
  Vector3 where = Vector3::Zero(), normal = Vector3::Zero();
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : qp_data.get_data(cell)) {
        if (d->old_region == ReturnRegion::elastic) {
          d->q = 1.0;
          continue;
        }
        const LocalizationResult loc = scan.scan(d->trial.tangent, d->material->elasticity().stiffness());
        d->q = loc.min_ratio;
        d->normal = loc.normal;
        int big = 0; // sign convention: the largest component positive
        d->normal.cwiseAbs().maxCoeff(&big);
        if (d->normal[big] < 0)
          d->normal = -d->normal;
        if (loc.min_ratio < local.q) {
          local.q = loc.min_ratio;
          where = d->position;
          normal = loc.normal;
        }
      }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
  double buffer[6] = {where[0], where[1], where[2], normal[0], normal[1], normal[2]};
  MPI_Bcast(buffer, 6, MPI_DOUBLE, global.rank, comm);
  q_min = global.q;
  if (onset_time < 0.0 && q_min <= 0.0) {
    onset_time = t;
    onset_position = Vector3(buffer[0], buffer[1], buffer[2]);
    onset_normal = Vector3(buffer[3], buffer[4], buffer[5]);
  }
}

// @sect3{Measurement}

/// Calls visit(a) with `fv` reinitialized on every locally owned face x_a = L (boundary id 2a+1).
template <class Visit>
void CubeEngine::Impl::for_each_moving_face(FEFaceValues<3> &fv, Visit visit) const
{
  for (const auto &cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned() || !cell->at_boundary())
      continue;
    for (const unsigned f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary() || cell->face(f)->boundary_id() % 2 == 0)
        continue;
      fv.reinit(cell, f);
      visit(cell->face(f)->boundary_id() / 2);
    }
  }
}

// Wall stress = reaction force / wall area: the current area of the face projected on the
// wall at finite strain (the Cauchy stress a DEM wall measures), the initial area L^2 at
// small strain (force over initial area, the work conjugate of the engineering strain).
Vector3 CubeEngine::Impl::wall_stresses() const
{
  Vector3 force = Vector3::Zero();
  for (unsigned a = 0; a < 3; ++a)
    for (const auto i : top_face_dofs[a])
      if (owned.is_element(i))
        force[a] += internal_force(i);
  for (unsigned a = 0; a < 3; ++a)
    force[a] = Utilities::MPI::sum(force[a], comm);
  if (prm.kinematics == Kinematics::finite_strain)
    return force.cwiseQuotient(face_areas());
  const Vector3 L = prm.edges();
  return force.cwiseQuotient(Vector3(L[1] * L[2], L[0] * L[2], L[0] * L[1]));
}

// A_a = int_{Gamma0_a} cof(F)_aa dA0 over the face x_a = L (Nanson's formula, projected on e_a).
Vector3 CubeEngine::Impl::face_areas() const
{
  FEFaceValues<3> fe_face_values(fe, face_quadrature, update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  std::vector<Tensor<2, 3>> grad(face_quadrature.size());
  Vector3 area = Vector3::Zero();
  for_each_moving_face(fe_face_values, [&](unsigned a) {
    const unsigned b = (a + 1) % 3, e = (a + 2) % 3;
    fe_face_values[displacement].get_function_gradients(solution, grad);
    for (unsigned q = 0; q < face_quadrature.size(); ++q) {
      const double Fbb = 1.0 + grad[q][b][b], Fee = 1.0 + grad[q][e][e];
      area[a] += (Fbb * Fee - grad[q][b][e] * grad[q][e][b]) * fe_face_values.JxW(q);
    }
  });
  for (unsigned a = 0; a < 3; ++a)
    area[a] = Utilities::MPI::sum(area[a], comm);
  return area;
}

Vector3 CubeEngine::Impl::face_strains() const
{
  FEFaceValues<3> fe_face_values(fe, face_quadrature, update_values | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  std::vector<Tensor<1, 3>> u(face_quadrature.size());
  Vector3 integral = Vector3::Zero();
  for_each_moving_face(fe_face_values, [&](unsigned a) {
    fe_face_values[displacement].get_function_values(solution, u);
    for (unsigned q = 0; q < face_quadrature.size(); ++q)
      integral[a] += u[q][a] * fe_face_values.JxW(q);
  });
  for (unsigned a = 0; a < 3; ++a)
    integral[a] = Utilities::MPI::sum(integral[a], comm);
  return integral / prm.edges().prod(); // (mean u_a over the face of area V / L_a) / L_a
}

// Volume average of the Cauchy stress over the current configuration (dv = J dV0).
Tensor3 CubeEngine::Impl::volume_average_stress() const
{
  Tensor3 s = Tensor3::Zero();
  double volume = 0.0;
  const bool finite = prm.kinematics == Kinematics::finite_strain;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : qp_data.get_data(cell)) {
        const double dv = d->JxW * (finite ? d->old_finite.deformation_gradient.determinant() : 1.0);
        s += from_mandel(d->old_stress) * dv;
        volume += dv;
      }
  Tensor3 global;
  MPI_Allreduce(s.data(), global.data(), 9, MPI_DOUBLE, MPI_SUM, comm);
  return global / Utilities::MPI::sum(volume, comm);
}

// @sect3{The LoadingEngine interface}

CubeEngine::CubeEngine(const CubeParameters &parameters, std::shared_ptr<const MaterialFactory> material,
                       MPI_Comm communicator)
  : impl_(std::make_unique<Impl>(parameters, std::move(material), communicator))
{}

CubeEngine::CubeEngine(const CubeParameters &parameters, const MaterialParameters &material,
                       MPI_Comm communicator)
  : CubeEngine(parameters, make_material_factory(material), communicator)
{}

CubeEngine::~CubeEngine() = default;

const CubeStatistics &CubeEngine::statistics() const { return impl_->stats; }
unsigned CubeEngine::n_dofs() const { return impl_->dof_handler.n_dofs(); }
double CubeEngine::element_size() const { return impl_->h_e; }

std::vector<ExtraColumn> CubeEngine::extra_columns() const
{
  std::vector<ExtraColumn> columns{
    {"newton_iterations", "1", "mean Newton iterations (linear solves) per load step in the last interval"},
    {"load_steps", "1", "converged load steps in the last interval"},
    {"cutbacks", "1", "load-step cut-backs in the last interval"},
    {"relaxed_steps", "1", "load steps accepted at the stagnation tolerance (a table kink) in the last interval"},
    {"plastic_fraction", "1", "volume fraction of plastic quadrature points"},
    {"kappa_max", "1", "largest equivalent plastic strain"}};
  if (impl_->rice_scan) {
    const std::vector<ExtraColumn> localization =
      localization_columns({"min over points of min_n det(n.C_ep.n)/det(n.C_e.n) (<= 0 localized)", true});
    columns.insert(columns.end(), localization.begin(), localization.end());
  }
  columns.push_back({"material_updates", "1",
                     "quadrature-point material updates computed in the last interval (FEM x DEM: RVE runs, its cost)"});
  return columns;
}

void CubeEngine::begin_control(const StageControl &control)
{
  Impl &m = *impl_;
  m.control = control;
  m.has_control = true;
  m.build_constraints();
  m.preconditioner_stale = true; // other constrained rows
  // Ramp only the stress targets that change (a control resumed after a branch must
  // follow exactly the path it would have followed without the branch).
  bool changes = false;
  for (int a = 0; a < 3; ++a) {
    m.ramp_from[a] = m.committed_wall_stress[a];
    if (!control.kinematic(a)) {
      const double target = control.target_stress(a);
      const double scale = std::max({std::abs(target), std::abs(m.ramp_from[a]), 1.0});
      if (std::abs(m.ramp_from[a] - target) > 1e-6 * scale)
        changes = true;
      else
        m.ramp_from[a] = target;
    }
  }
  m.ramp_t0 = m.time;
  m.ramp_t1 = changes ? -1.0 : m.ramp_t0; // -1: set by the first advance
}

void CubeEngine::advance_to(double t_end)
{
  Impl &m = *impl_;
  if (!m.has_control)
    throw std::logic_error("CubeEngine::advance_to before begin_control");
  Timer timer;
  if (m.ramp_t1 < 0.0)
    m.ramp_t1 = t_end;
  m.interval_steps = m.interval_iterations = m.interval_cutbacks = m.interval_relaxed = 0;
  m.interval_updates_from = m.stats.material_updates;
  const double dt_nominal = (t_end - m.time) / m.prm.steps_per_advance;
  double dt = dt_nominal;
  unsigned level = 0; // current number of halvings below the nominal step
  unsigned easy = 0;  // consecutive converged steps within half the Newton limit
  while (m.time < t_end) {
    const bool last = is_last_step(m.time, dt, t_end, dt_nominal);
    const double t = last ? t_end : m.time + dt;
    if (m.solve_step(t)) {
      m.commit();
      m.time = t;
      ++m.interval_steps;
      ++m.stats.steps;
      // After a cut-back the step doubles again after a step that converged in at most
      // four iterations, or after two in a row within half the Newton limit (a step near a
      // kink may need five or six iterations at any size; growing only on <= 4 left such
      // runs at the smallest step to the end).
      const unsigned its = m.stats.last_step_iterations;
      easy = 2 * its <= m.prm.max_newton_iterations ? easy + 1 : 0;
      if (level > 0 && (its <= 4 || easy >= 2)) {
        dt *= 2.0;
        --level;
        easy = 0;
      }
      continue;
    }
    m.revert();
    easy = 0;
    ++m.interval_cutbacks;
    ++m.stats.cutbacks;
    if (++level > m.prm.max_cutbacks) {
      std::ostringstream msg;
      msg << "continuum cube: Newton did not converge at t = " << t << " after " << m.prm.max_cutbacks
          << " cut-backs of the load step (last residuals:";
      for (double r : m.stats.last_step_residuals)
        msg << ' ' << r;
      msg << ")";
      throw std::runtime_error(msg.str());
    }
    dt *= 0.5;
    m.pcout << "  cut back to dt = " << dt << '\n';
  }
  m.stats.total_seconds += timer.wall_time();
}

ResponseSample CubeEngine::measure()
{
  Impl &m = *impl_;
  m.update_localization(m.time);
  ResponseSample s;
  s.time = m.time;
  const Vector3 eps = m.face_strains();
  const Tensor3 average = m.volume_average_stress();
  s.strain = eps.asDiagonal();
  s.stress = average;
  for (int a = 0; a < 3; ++a)
    s.stress(a, a) = m.committed_wall_stress[a];

  double plastic_volume = 0.0, kappa_max = 0.0;
  for (const auto &cell : m.tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : m.qp_data.get_data(cell)) {
        if (d->old_region != ReturnRegion::elastic)
          plastic_volume += d->JxW;
        kappa_max = std::max(kappa_max, d->old_history.kappa);
      }
  if (m.prm.verbose) {
    double kmin = 1e300, kweak = 0.0;
    unsigned n_weak = 0;
    for (const auto &cell : m.tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &d : m.qp_data.get_data(cell)) {
          kmin = std::min(kmin, d->old_history.kappa);
          if (d->weak) {
            ++n_weak;
            kweak = std::max(kweak, d->old_history.kappa);
          }
        }
    m.pcout << "  t = " << m.time << " kappa min " << Utilities::MPI::min(kmin, m.comm) << " max " << Utilities::MPI::max(kappa_max, m.comm)
            << " weak points " << Utilities::MPI::sum(n_weak, m.comm) << " kappa(weak) max " << Utilities::MPI::max(kweak, m.comm) << '\n';
  }
  plastic_volume = Utilities::MPI::sum(plastic_volume, m.comm);
  kappa_max = Utilities::MPI::max(kappa_max, m.comm);

  s.extras = {m.interval_steps ? double(m.interval_iterations) / m.interval_steps : 0.0,
              double(m.interval_steps),
              double(m.interval_cutbacks),
              double(m.interval_relaxed),
              plastic_volume / (m.prm.box_edges.isZero() ? std::pow(m.prm.side, 3) : m.prm.edges().prod()),
              kappa_max};
  if (m.rice_scan)
    s.extras.insert(s.extras.end(), {m.q_min, m.onset_time, m.onset_position[0], m.onset_position[1],
                                     m.onset_position[2], m.onset_normal[0], m.onset_normal[1], m.onset_normal[2]});
  s.extras.push_back(double(Utilities::MPI::sum(m.stats.material_updates - m.interval_updates_from, m.comm)));

  if (!m.prm.output_directory.empty() && m.measure_count % m.prm.output_every == 0)
    m.write_output(m.time);
  ++m.measure_count;
  return s;
}

namespace {
struct PointSnapshot {
  PlasticHistory history;
  FiniteStrainHistory finite;
  Vector6 stress;
  ReturnRegion region;
  Matrix6 tangent;
  double q;
  Vector3 normal;
};
struct CubeState : EngineState {
  explicit CubeState(const LA::MPI::Vector &u, const LA::MPI::Vector &f)
    : solution(u), internal_force(f)
  {}
  LA::MPI::Vector solution, internal_force;
  std::vector<PointSnapshot> points; ///< locally owned cells in iteration order
  double time, onset_time, q_min;
  Vector3 wall_stress, onset_position, onset_normal;
};
} // namespace

std::unique_ptr<EngineState> CubeEngine::save() const
{
  const Impl &m = *impl_;
  auto s = std::make_unique<CubeState>(m.old_solution, m.internal_force);
  for (const auto &cell : m.tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : m.qp_data.get_data(cell))
        s->points.push_back({d->old_history, d->old_finite, d->old_stress, d->old_region, d->trial.tangent, d->q, d->normal});
  s->time = m.time;
  s->onset_time = m.onset_time;
  s->q_min = m.q_min;
  s->wall_stress = m.committed_wall_stress;
  s->onset_position = m.onset_position;
  s->onset_normal = m.onset_normal;
  return s;
}

void CubeEngine::set_branch(int id) { impl_->branch = id; }

void CubeEngine::restore(const EngineState &state)
{
  Impl &m = *impl_;
  const auto &s = dynamic_cast<const CubeState &>(state);
  std::size_t k = 0;
  for (const auto &cell : m.tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &d : m.qp_data.get_data(cell)) {
        const PointSnapshot &p = s.points.at(k++);
        d->old_history = d->trial.history = p.history;
        d->old_finite = d->trial_finite = p.finite;
        d->old_stress = d->trial.stress = p.stress;
        d->old_region = d->trial.region = p.region;
        d->trial.tangent = p.tangent;
        d->q = p.q;
        d->normal = p.normal;
      }
  ++m.history_epoch;
  m.old_solution = s.solution;
  m.solution_owned = s.solution;
  m.solution = m.solution_owned;
  m.internal_force = s.internal_force;
  m.time = s.time;
  m.onset_time = s.onset_time;
  m.q_min = s.q_min;
  m.committed_wall_stress = s.wall_stress;
  m.onset_position = s.onset_position;
  m.onset_normal = s.onset_normal;
  m.preconditioner_stale = true;
  // Field output past the restored time belongs to a path that was not kept (a branch's
  // step redone to land on its target): out of the series.
  auto &records = m.branch > 0 ? m.branch_records[m.branch] : m.pvd_records;
  while (!records.empty() && records.back().first > m.time)
    records.pop_back();
}

} // namespace geocomp::continuum
