#include "dem/periodic/PeriodicNeighbours.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace geocomp::dem {

void PeriodicNeighbours::collect_history(const std::vector<ParticleId>& id, bool keep_memory)
{
  carried_.clear();
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    const bool active = overlap[c] != 0.0 || shear[c].squaredNorm() != 0.0 || (keep_memory && memory[c].active());
    if (!active) continue;
    carried_.push_back(Carried{pair_key(id[pairs[c].i], id[pairs[c].j]), shear[c],
                               keep_memory ? memory[c] : ContactMemory{}, overlap[c]});
  }
  std::sort(carried_.begin(), carried_.end());
}

void PeriodicNeighbours::restore_history(const std::vector<ParticleId>& id, bool keep_memory)
{
  shear.assign(pairs.size(), Vec3::Zero());
  overlap.assign(pairs.size(), 0.0);
  if (keep_memory) memory.assign(pairs.size(), ContactMemory{});
  else memory.clear();
  if (carried_.empty()) return;
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    const Carried probe{pair_key(id[pairs[c].i], id[pairs[c].j]), Vec3::Zero(), ContactMemory{}, 0.0};
    const auto it = std::lower_bound(carried_.begin(), carried_.end(), probe);
    if (it == carried_.end() || it->key != probe.key) continue;
    shear[c] = it->shear;
    overlap[c] = it->overlap;
    if (keep_memory) memory[c] = it->memory;
  }
}

void PeriodicNeighbours::bin(const BuildInput& in)
{
  const std::size_t n = in.x.size();
  std::uint32_t total = 1;
  for (int a = 0; a < 3; ++a) {
    // No more bins along an axis than particles could fill (bounded memory for sparse cells).
    const double fit = std::floor(in.cell.width(a) / cutoff_);
    const double cap = std::max(1.0, std::ceil(std::cbrt(double(n))) * 2.0);
    dims_[a] = std::int32_t(std::max(1.0, std::min(fit, cap)));
    total *= std::uint32_t(dims_[a]);
  }
  bin_of_.resize(n);
  start_.assign(total + 1, 0u);
  for (std::size_t p = 0; p < n; ++p) {
    const Vec3 s = in.cell.reduced(in.x[p]);
    std::uint32_t b = 0, stride = 1;
    for (int a = 0; a < 3; ++a) {
      const std::int32_t k = std::clamp(std::int32_t(std::floor(s[a] * dims_[a])), 0, dims_[a] - 1);
      b += stride * std::uint32_t(k);
      stride *= std::uint32_t(dims_[a]);
    }
    bin_of_[p] = b;
    ++start_[b + 1];
  }
  for (std::uint32_t b = 0; b < total; ++b) start_[b + 1] += start_[b];
  cursor_.assign(start_.begin(), start_.end() - 1);
  items_.resize(n);
  for (std::size_t p = 0; p < n; ++p) items_[cursor_[bin_of_[p]]++] = std::uint32_t(p);  // stable
}

void PeriodicNeighbours::build(const BuildInput& in)
{
  const std::size_t n = in.x.size();
  r_max_ = 0.0;
  for (double r : in.radius) r_max_ = std::max(r_max_, r);
  cutoff_ = 2.0 * r_max_ + p_.skin;
  if (in.cell.min_width() < 2.0 * cutoff_)
    throw std::runtime_error("PeriodicNeighbours: the cell's narrowest width " + std::to_string(in.cell.min_width()) +
                             " m is below twice the cut-off 2 (2 R_max + skin) = " + std::to_string(2.0 * cutoff_) +
                             " m (minimum image)");
  collect_history(in.id, in.keep_memory);
  bin(in);
  pairs.clear();
  const Mat3& h = in.cell.h();
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t c[3];
    std::uint32_t b = bin_of_[i];
    for (int a = 0; a < 3; ++a) {
      c[a] = std::int32_t(b % std::uint32_t(dims_[a]));
      b /= std::uint32_t(dims_[a]);
    }
    for (int oz = -1; oz <= 1; ++oz)
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
          const int o[3] = {ox, oy, oz};
          std::array<std::int32_t, 3> shift{};
          std::uint32_t nb = 0, stride = 1;
          for (int a = 0; a < 3; ++a) {
            // Bin c + o wrapped into [0, n_a); the wrap is the image shift.
            const std::int32_t k = c[a] + o[a];
            const std::int32_t wrapped = ((k % dims_[a]) + dims_[a]) % dims_[a];
            shift[a] = (k - wrapped) / dims_[a];
            nb += stride * std::uint32_t(wrapped);
            stride *= std::uint32_t(dims_[a]);
          }
          const Vec3 image = h.col(0) * double(shift[0]) + h.col(1) * double(shift[1]) + h.col(2) * double(shift[2]);
          for (std::uint32_t e = start_[nb]; e < start_[nb + 1]; ++e) {
            const std::uint32_t j = items_[e];
            if (j <= i) continue;
            const double range = in.radius[i] + in.radius[j] + p_.skin;
            if ((in.x[j] + image - in.x[i]).squaredNorm() < range * range)
              pairs.push_back(PeriodicPair{Index(i), Index(j), shift});
          }
        }
  }
  restore_history(in.id, in.keep_memory);
  ++builds_;
}

}  // namespace geocomp::dem
