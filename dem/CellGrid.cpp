#include "dem/CellGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

void CellGrid::build(const std::vector<Vec3>& x, double min_cell_size)
{
  const std::size_t n = x.size();
  if (!(min_cell_size > 0.0)) throw std::invalid_argument("CellGrid: cell size must be positive");
  Vec3 lo = Vec3::Constant(0.0), hi = Vec3::Constant(0.0);
  if (n > 0) {
    lo = x[0];
    hi = x[0];
    for (const Vec3& p : x) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  if (!lo.allFinite() || !hi.allFinite()) throw std::runtime_error("CellGrid: non-finite particle position");
  // Cell edge >= min_cell_size; enlarge it if the box is so sparse that cells would
  // outnumber particles by far (memory stays O(N)).
  double size = min_cell_size;
  const double max_cells = 8.0 * double(n) + 1024.0;
  for (;;) {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a) cells *= std::max(1.0, std::floor((hi[a] - lo[a]) / size) + 1.0);
    if (cells <= max_cells) break;
    size *= 1.5;
  }
  for (int a = 0; a < 3; ++a)
    dims_[a] = std::uint32_t(std::max(1.0, std::floor((hi[a] - lo[a]) / size) + 1.0));
  const std::size_t n_cells = std::size_t(dims_[0]) * dims_[1] * dims_[2];
  const double inv = 1.0 / size;

  cell_of_.resize(n);
  start_.assign(n_cells + 1, 0);
  for (std::size_t p = 0; p < n; ++p) {
    std::uint32_t c[3];
    for (int a = 0; a < 3; ++a)
      c[a] = std::min(dims_[a] - 1, std::uint32_t((x[p][a] - lo[a]) * inv));
    const std::uint32_t cell = c[0] + dims_[0] * (c[1] + dims_[1] * c[2]);
    cell_of_[p] = cell;
    ++start_[cell + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) start_[c + 1] += start_[c];
  items_.resize(n);
  // Stable counting sort: within a cell, ascending storage index.
  cursor_.assign(start_.begin(), start_.end() - 1);
  for (std::size_t p = 0; p < n; ++p) items_[cursor_[cell_of_[p]]++] = Index(p);
}

void CellGrid::adopt_sorted_order()
{
  // After permuting storage to items_ order, particle k is the old items_[k]; its cell
  // is unchanged and the cells are now contiguous ranges of the identity.
  std::vector<std::uint32_t>& c = cell_of_;
  const std::size_t n = items_.size();
  // Cells along items_ are non-decreasing: rebuild cell_of_ from start_.
  std::size_t cell = 0;
  for (std::size_t k = 0; k < n; ++k) {
    while (start_[cell + 1] <= k) ++cell;
    c[k] = std::uint32_t(cell);
    items_[k] = Index(k);
  }
}

}  // namespace geocomp::dem
