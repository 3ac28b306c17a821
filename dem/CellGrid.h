// @sect3{The CellGrid class}
//
// Why it exists: finding the pairs within interaction range must be O(N). Space is cut
// into cubic cells of edge $\ge 2R_{max} + s$ (s: Verlet skin), so every pair within
// range lies in the same or adjacent cells (27-cell stencil). The particles are binned
// with a counting sort; the resulting cell order is also the storage order used for
// spatial sorting (neighbours near each other in memory).
#pragma once

#include "dem/Types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace geocomp::dem {

class CellGrid
{
public:
  /// Bins positions x into cells of edge >= min_cell_size covering their bounding box.
  void build(const std::vector<Vec3>& x, double min_cell_size);

  /// Particle indices in cell order.
  const std::vector<Index>& sorted() const { return items_; }
  std::uint32_t cell_of_particle(Index p) const { return cell_of_[p]; }
  /// Renames particles after the storage was permuted to sorted() order.
  void adopt_sorted_order();

  /// Calls f(q) for every particle q in the 27 cells around cell c.
  template <class F>
  void for_each_near(std::uint32_t c, F&& f) const
  {
    const int cx = int(c % dims_[0]);
    const int cy = int((c / dims_[0]) % dims_[1]);
    const int cz = int(c / (dims_[0] * dims_[1]));
    for (int dz = -1; dz <= 1; ++dz) {
      const int z = cz + dz;
      if (z < 0 || z >= int(dims_[2])) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        const int y = cy + dy;
        if (y < 0 || y >= int(dims_[1])) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = cx + dx;
          if (xx < 0 || xx >= int(dims_[0])) continue;
          const std::uint32_t cell = std::uint32_t(xx) + dims_[0] * (std::uint32_t(y) + dims_[1] * std::uint32_t(z));
          for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(items_[k]);
        }
      }
    }
  }

  /// Calls f(q) for every particle q > p in the 27 cells around p's cell, in the order
  /// for_each_near() meets them, once storage is in cell order (adopt_sorted_order(), or a
  /// build whose sorted() order was the identity). Then q > p lies in p's cell after p or
  /// in one of the 13 cells after p's cell, so the other 13 cells are not visited.
  template <class F>
  void for_each_after(Index p, F&& f) const
  {
    const std::uint32_t c = cell_of_[p];
    for (std::uint32_t k = p + 1; k < start_[c + 1]; ++k) f(items_[k]);
    const int cx = int(c % dims_[0]);
    const int cy = int((c / dims_[0]) % dims_[1]);
    const int cz = int(c / (dims_[0] * dims_[1]));
    for (int dz = 0; dz <= 1; ++dz) {
      const int z = cz + dz;
      if (z >= int(dims_[2])) continue;
      for (int dy = dz == 0 ? 0 : -1; dy <= 1; ++dy) {
        const int y = cy + dy;
        if (y < 0 || y >= int(dims_[1])) continue;
        for (int dx = (dz == 0 && dy == 0) ? 1 : -1; dx <= 1; ++dx) {
          const int xx = cx + dx;
          if (xx < 0 || xx >= int(dims_[0])) continue;
          const std::uint32_t cell = std::uint32_t(xx) + dims_[0] * (std::uint32_t(y) + dims_[1] * std::uint32_t(z));
          for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(items_[k]);
        }
      }
    }
  }

  std::size_t memory_bytes() const
  {
    return (cell_of_.capacity() + items_.capacity() + start_.capacity() + cursor_.capacity()) * sizeof(std::uint32_t);
  }

private:
  std::array<std::uint32_t, 3> dims_{{1, 1, 1}};
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> cursor_;
  std::vector<Index> items_;
};

}  // namespace geocomp::dem
