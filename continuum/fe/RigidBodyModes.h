#pragma once
// The six rigid-body modes of a 3-component displacement field, the near-null space that
// the FE cube hands to ML's smoothed aggregation (CubeEngine.cpp, "Linear solver").
#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace geocomp::continuum {

/// u = a + w x (x - centre) at the support points of the locally owned dofs of a
/// FESystem(FE_Q(p), 3) DoFHandler: an n_owned x 6 column-major block (entry (row, k) at
/// k * n_owned + row, rows in the order of `owned`), columns = the translations along x,
/// y, z and the rotations about x, y, z through `centre`, i.e. e_k x (x - centre).
/// Every rigid-body mode is a zero-energy mode of the unconstrained stiffness matrix.
std::vector<double> rigid_body_modes(const dealii::DoFHandler<3> &dof_handler, const dealii::IndexSet &owned,
                                     const dealii::Point<3> &centre);

} // namespace geocomp::continuum
