// CubeEngine output: one VTU per rank + a PVTU per sample, and a PVD index over time: the
// main path's in <basename>.pvd, each unloading branch's in <basename>-branch<id>.pvd.
// Kept in its own translation unit: DataOut is the heaviest deal.II template to compile.
//
// Fields: the displacement (nodal vector) and, per cell, the quadrature-point averages of
// the stress components and kappa, the largest state flag, the smallest localization
// indicator q, and the MPI rank (partition).
#include "continuum/fe/CubeEngineImpl.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <filesystem>
#include <fstream>

namespace geocomp::continuum {

using namespace dealii;

void CubeEngine::Impl::write_output(double t)
{
  const unsigned n_cells = tria.n_active_cells();
  const char *names[6] = {"stress_xx", "stress_yy", "stress_zz", "stress_yz", "stress_xz", "stress_xy"};
  const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  std::vector<dealii::Vector<float>> stress(6, dealii::Vector<float>(n_cells));
  dealii::Vector<float> kappa(n_cells), flag(n_cells), q(n_cells), rank(n_cells), weak(n_cells);

  for (const auto &cell : tria.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    const unsigned c = cell->active_cell_index();
    double volume = 0.0, k = 0.0, q_cell = 1.0;
    int f = 0;
    Tensor3 s = Tensor3::Zero();
    bool any_weak = false;
    for (const auto &d : qp_data.get_data(cell)) {
      volume += d->JxW;
      s += from_mandel(d->old_stress) * d->JxW;
      k += d->old_history.kappa * d->JxW;
      f = std::max(f, static_cast<int>(d->old_region));
      q_cell = std::min(q_cell, d->q);
      any_weak = any_weak || d->weak;
    }
    for (unsigned m = 0; m < 6; ++m)
      stress[m][c] = s(ij[m][0], ij[m][1]) / volume;
    kappa[c] = k / volume;
    flag[c] = f;
    q[c] = q_cell;
    weak[c] = any_weak;
    rank[c] = tria.locally_owned_subdomain();
  }

  DataOut<3> data_out;
  data_out.attach_dof_handler(dof_handler);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
    3, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(solution, std::vector<std::string>(3, "displacement"),
                           DataOut<3>::type_dof_data, vector);
  for (unsigned m = 0; m < 6; ++m)
    data_out.add_data_vector(stress[m], names[m], DataOut<3>::type_cell_data);
  data_out.add_data_vector(kappa, "kappa", DataOut<3>::type_cell_data);
  data_out.add_data_vector(flag, "state_flag", DataOut<3>::type_cell_data);
  if (rice_scan) // a point-state material has no indicator (update_localization)
    data_out.add_data_vector(q, "localization_q", DataOut<3>::type_cell_data);
  data_out.add_data_vector(weak, "imperfection", DataOut<3>::type_cell_data);
  data_out.add_data_vector(rank, "rank", DataOut<3>::type_cell_data);
  data_out.build_patches(prm.degree);

  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
  if (root)
    std::filesystem::create_directories(prm.output_directory);
  MPI_Barrier(comm);
  const std::string directory = prm.output_directory + "/";
  const std::string pvtu = data_out.write_vtu_with_pvtu_record(directory, prm.output_basename, output_count++, comm, 5);
  auto &records = branch > 0 ? branch_records[branch] : pvd_records;
  records.emplace_back(t, pvtu);
  if (root) {
    const std::string series = branch > 0 ? "-branch" + std::to_string(branch) : "";
    std::ofstream pvd(directory + prm.output_basename + series + ".pvd");
    DataOutBase::write_pvd_record(pvd, records);
  }
}

// The mid-plane: for each locally owned cell with y0 <= L/2 < y1, the points
// (xi, eta, zeta) = ({1,3,5}/6, (L/2 - y0)/h_y, {1,3,5}/6) in the reference cell (the mesh is
// an axis-aligned brick, so reference and real coordinates map affinely).
MidPlaneSample CubeEngine::mid_plane() const
{
  const Impl &m = *impl_;
  const double y_mid = 0.5 * m.prm.edges()[1];
  MidPlaneSample local;
  const FEValuesExtractors::Vector displacement(0);
  for (const auto &cell : m.dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    double y0 = cell->vertex(0)[1], y1 = y0;
    for (unsigned v = 1; v < GeometryInfo<3>::vertices_per_cell; ++v) {
      y0 = std::min(y0, cell->vertex(v)[1]);
      y1 = std::max(y1, cell->vertex(v)[1]);
    }
    if (!(y0 <= y_mid && y_mid < y1))
      continue;
    const double eta = (y_mid - y0) / (y1 - y0);
    std::vector<Point<3>> points;
    for (double zeta : {1.0 / 6, 0.5, 5.0 / 6})
      for (double xi : {1.0 / 6, 0.5, 5.0 / 6})
        points.emplace_back(xi, eta, zeta);
    const Quadrature<3> plane(points, std::vector<double>(points.size(), 1.0 / points.size()));
    FEValues<3> values(m.fe, plane, update_values | update_quadrature_points);
    values.reinit(cell);
    std::vector<Tensor<1, 3>> u(points.size());
    values[displacement].get_function_values(m.solution, u);
    double volume = 0.0, kappa = 0.0;
    for (const auto &d : m.qp_data.get_data(Impl::Cell(cell))) {
      volume += d->JxW;
      kappa += d->old_history.kappa * d->JxW;
    }
    for (unsigned q = 0; q < points.size(); ++q) {
      local.x.push_back(values.quadrature_point(q)[0]);
      local.z.push_back(values.quadrature_point(q)[2]);
      local.ux.push_back(u[q][0]);
      local.uz.push_back(u[q][2]);
      local.kappa.push_back(kappa / volume);
    }
  }
  MidPlaneSample all;
  for (auto member : {&MidPlaneSample::x, &MidPlaneSample::z, &MidPlaneSample::ux, &MidPlaneSample::uz,
                      &MidPlaneSample::kappa}) {
    const std::vector<std::vector<double>> parts = Utilities::MPI::gather(m.comm, local.*member, 0);
    for (const auto &part : parts)
      (all.*member).insert((all.*member).end(), part.begin(), part.end());
  }
  return all;
}

} // namespace geocomp::continuum
