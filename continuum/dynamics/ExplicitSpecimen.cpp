#include "continuum/dynamics/ExplicitSpecimen.h"

#include "continuum/kinetic/PlaneStress.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace geocomp::dynamics {

using namespace dealii;
using kinetic::KineticState;

namespace {
constexpr unsigned int dofs_per_cell = 8, points_per_cell = 4;
}

// @sect4{The mesh and its constant element data}
// For every cell: its 8 global dof indices, and at each Gauss point the weight JxW and,
// per local dof, the component it moves (0 = x, 1 = y) and the gradient of its shape
// function. That is all the explicit loop needs: strains are B u, forces B^T sigma JxW.
struct ExplicitSpecimen::Mesh {
  Triangulation<2> triangulation;
  FESystem<2> fe{FE_Q<2>(1), 2};
  DoFHandler<2> dof_handler;
  struct CellData {
    std::array<types::global_dof_index, dofs_per_cell> dofs;
    std::array<unsigned int, dofs_per_cell> component;
    std::array<double, points_per_cell> JxW;
    std::array<std::array<Tensor<1, 2>, dofs_per_cell>, points_per_cell> grad;
  };
  std::vector<CellData> cells;
  std::vector<double> mass_per_density; ///< lumped mass / rho, per dof
  std::vector<types::global_dof_index> bottom_y, top_y, pinned_x, end_x;
  double h_min = 0.0;
};

ExplicitSpecimen::ExplicitSpecimen(const KineticNikolaevsky &model, SpecimenGeometry geometry,
                                   DynamicsControls controls)
  : model_(model), geometry_(geometry), controls_(controls), mesh_(std::make_unique<Mesh>())
{
  if (!(geometry_.width > 0.0 && geometry_.height > 0.0) || geometry_.cells_x < 2 || geometry_.cells_y < 2 ||
      geometry_.cells_x % 2 != 0)
    throw std::invalid_argument("ExplicitSpecimen: expected positive sizes, >= 2 cells per side and an even "
                                "number of cells across the width");
  if (!(controls_.time_step_safety > 0.0 && controls_.time_step_safety <= 1.0) ||
      !(controls_.quasi_static_transits >= 1.0) || !(controls_.min_steps_to_static >= 1.0))
    throw std::invalid_argument("ExplicitSpecimen: expected 0 < time step safety <= 1 and >= 1 transit");
  Mesh &m = *mesh_;
  GridGenerator::subdivided_hyper_rectangle(m.triangulation, {geometry_.cells_x, geometry_.cells_y}, Point<2>(0, 0),
                                            Point<2>(geometry_.width, geometry_.height), true);
  m.dof_handler.reinit(m.triangulation);
  m.dof_handler.distribute_dofs(m.fe);
  m.mass_per_density.assign(m.dof_handler.n_dofs(), 0.0);
  m.h_min = std::min(geometry_.width / geometry_.cells_x, geometry_.height / geometry_.cells_y);

  const QGauss<2> quadrature(2);
  FEValues<2> fe_values(m.fe, quadrature, update_gradients | update_values | update_JxW_values);
  std::vector<types::global_dof_index> local(dofs_per_cell);
  for (const auto &cell : m.dof_handler.active_cell_iterators()) {
    fe_values.reinit(cell);
    cell->get_dof_indices(local);
    Mesh::CellData d;
    for (unsigned int i = 0; i < dofs_per_cell; ++i) {
      d.dofs[i] = local[i];
      d.component[i] = m.fe.system_to_component_index(i).first;
    }
    for (unsigned int q = 0; q < points_per_cell; ++q) {
      d.JxW[q] = fe_values.JxW(q);
      for (unsigned int i = 0; i < dofs_per_cell; ++i) {
        d.grad[q][i] = fe_values.shape_grad(i, q);
        // Row-sum lumping: sum_j phi_i phi_j = phi_i, since the Q1 functions sum to one.
        m.mass_per_density[local[i]] += fe_values.shape_value(i, q) * d.JxW[q];
      }
    }
    m.cells.push_back(d);
    // Platen dofs (y on the ends) and the mid-width x pins.
    for (unsigned int v = 0; v < GeometryInfo<2>::vertices_per_cell; ++v) {
      const Point<2> &p = cell->vertex(v);
      const bool bottom = std::abs(p[1]) < 1e-12 * geometry_.height;
      const bool top = std::abs(p[1] - geometry_.height) < 1e-12 * geometry_.height;
      if (bottom)
        m.bottom_y.push_back(cell->vertex_dof_index(v, 1));
      if (top)
        m.top_y.push_back(cell->vertex_dof_index(v, 1));
      if ((bottom || top) && std::abs(p[0] - 0.5 * geometry_.width) < 1e-9 * geometry_.width)
        m.pinned_x.push_back(cell->vertex_dof_index(v, 0));
      if (bottom || top)
        m.end_x.push_back(cell->vertex_dof_index(v, 0));
    }
  }
  for (auto *list : {&m.bottom_y, &m.top_y, &m.pinned_x, &m.end_x}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
}

ExplicitSpecimen::~ExplicitSpecimen() = default;

unsigned int ExplicitSpecimen::n_dofs() const { return mesh_->dof_handler.n_dofs(); }
unsigned int ExplicitSpecimen::n_points() const { return mesh_->cells.size() * points_per_cell; }

// @sect4{One test}
SpecimenRunResult ExplicitSpecimen::run(LoadingMode mode, double strain_rate) const
{
  if (!(strain_rate > 0.0) || !std::isfinite(strain_rate))
    throw std::invalid_argument("ExplicitSpecimen::run: expected a positive strain rate");
  const Mesh &m = *mesh_;
  const auto &mat = model_.material();
  const bool compression = mode == LoadingMode::compression;
  const double sign = compression ? -1.0 : 1.0;
  const double strength = compression ? mat.compressive_strength : mat.tensile_strength;
  const double t_static = strength / (mat.youngs_modulus * strain_rate);
  const double wave_speed = std::sqrt(mat.youngs_modulus / (mat.density * (1.0 - mat.poisson_ratio * mat.poisson_ratio)));
  const double transit = geometry_.height / wave_speed;
  // Density scaling: t_static >= N transits, never below the true density.
  const double scale = std::max(1.0, std::pow(t_static / (controls_.quasi_static_transits * transit), 2.0));
  const double c = wave_speed / std::sqrt(scale);
  const double dt = std::min(controls_.time_step_safety * m.h_min / c, t_static / controls_.min_steps_to_static);
  const double k_s1 = compression ? kinetic::compressive_strength_factor(strain_rate)
                                  : kinetic::tensile_strength_factor(strain_rate);
  const double t_end = controls_.max_time_factor * std::max(1.0, k_s1) * t_static;
  const long max_steps = static_cast<long>(std::ceil(t_end / dt));
  // Each platen moves at epsdot H / 2, or the top one alone at epsdot H.
  const double top_speed = (controls_.fixed_bottom ? 1.0 : 0.5) * strain_rate * geometry_.height;
  const double bottom_speed = controls_.fixed_bottom ? 0.0 : top_speed;

  const std::size_t n = m.dof_handler.n_dofs();
  std::vector<double> u(n, 0.0), v(n, 0.0), f(n, 0.0), inv_mass(n);
  for (std::size_t i = 0; i < n; ++i)
    inv_mass[i] = 1.0 / (mat.density * scale * m.mass_per_density[i]);
  std::vector<char> prescribed(n, 0);
  for (auto i : m.bottom_y)
    prescribed[i] = 1;
  for (auto i : m.top_y)
    prescribed[i] = 1;
  // Smooth platens pin u_x at the middle node of each end only; bonded ones hold every end node.
  const auto &pinned_x = controls_.bonded_platens ? m.end_x : m.pinned_x;
  for (auto i : pinned_x)
    prescribed[i] = 1;
  std::vector<KineticState> states(n_points(), model_.initial_state());

  SpecimenRunResult r;
  r.strain_rate = strain_rate;
  r.density_scale = scale;
  r.time_step = dt;
  r.points = n_points();
  const long sample_every = std::max(1L, max_steps / std::max(1u, controls_.curve_samples));
  const double area = geometry_.width; // unit thickness
  double peak = 0.0;
  bool fractured_any = false;
  std::array<double, dofs_per_cell> du;
  const double rise_time = controls_.platen_rise_fraction * t_static;
  double platen_gap_change = 0.0; // top minus bottom platen displacement
  for (long step = 1; step <= max_steps; ++step) {
    // Platen velocities (a smooth half-cosine rise over rise_time, then constant);
    // the pinned x dofs stay at rest.
    const double t_mid = dt * (step - 0.5);
    const double ramp = t_mid < rise_time ? 0.5 * (1.0 - std::cos(M_PI * t_mid / rise_time)) : 1.0;
    platen_gap_change += sign * ramp * (top_speed + bottom_speed) * dt;
    for (auto i : m.bottom_y)
      v[i] = -sign * ramp * bottom_speed;
    for (auto i : m.top_y)
      v[i] = sign * ramp * top_speed;
    for (auto i : pinned_x)
      v[i] = 0.0;
    // Strain increments through the kinetic points, internal forces.
    std::fill(f.begin(), f.end(), 0.0);
    for (std::size_t cell = 0; cell < m.cells.size(); ++cell) {
      const auto &d = m.cells[cell];
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        du[i] = dt * v[d.dofs[i]];
      for (unsigned int q = 0; q < points_per_cell; ++q) {
        Eigen::Vector3d de = Eigen::Vector3d::Zero(); // (d eps_xx, d eps_yy, d gamma_xy)
        for (unsigned int i = 0; i < dofs_per_cell; ++i) {
          const Tensor<1, 2> &g = d.grad[q][i];
          if (d.component[i] == 0) {
            de(0) += du[i] * g[0];
            de(2) += du[i] * g[1];
          } else {
            de(1) += du[i] * g[1];
            de(2) += du[i] * g[0];
          }
        }
        KineticState &s = states[cell * points_per_cell + q];
        s = kinetic::plane_stress_step(model_, s, de, dt);
        const double sxx = s.stress(0), syy = s.stress(1), sxy = s.stress(5) / std::sqrt(2.0);
        for (unsigned int i = 0; i < dofs_per_cell; ++i) {
          const Tensor<1, 2> &g = d.grad[q][i];
          f[d.dofs[i]] += d.JxW[q] * (d.component[i] == 0 ? sxx * g[0] + sxy * g[1] : sxy * g[0] + syy * g[1]);
        }
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      u[i] += dt * v[i];
      if (!prescribed[i])
        v[i] -= dt * f[i] * inv_mass[i]; // M a = -f_int (no body forces)
    }
    // End stress: the platens' forces are the internal forces at their dofs.
    double top = 0.0, bottom = 0.0;
    for (auto i : m.top_y)
      top += f[i];
    for (auto i : m.bottom_y)
      bottom += f[i];
    const double stress = (controls_.fixed_bottom ? top : 0.5 * (top - bottom)) / area;
    const double strain = platen_gap_change / geometry_.height;
    if (sign * stress > peak) {
      peak = sign * stress;
      r.peak_stress = peak;
      r.strain_at_peak = std::abs(strain);
    }
    if (step % sample_every == 0)
      r.curve.push_back({dt * step, strain, stress});
    r.steps = step;
    unsigned int fractured = 0;
    for (const auto &s : states)
      fractured += s.fractured ? 1u : 0u;
    r.fractured_points = fractured;
    fractured_any = fractured_any || fractured > 0;
    if (fractured_any && sign * stress < controls_.stop_load_fraction * peak)
      break;
  }
  return r;
}

} // namespace geocomp::dynamics
