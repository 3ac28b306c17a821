// @sect3{The PeriodicNeighbours class: pairs within range through the cell's images}
//
// Why it exists: in a periodic cell a sphere near one face touches spheres near the
// opposite face, through an image $x_j + Hn$ (n an integer shift). The pair list holds
// each touching-or-nearly-touching pair once with its shift, and the branch vector
// $$ l = x_j + Hn - x_i $$
// is recomputed from the current H every step, so the list stays valid while the cell
// deforms. Binning is done in reduced coordinates $s = H^{-1}x \in [0,1)^3$ with
// $n_a = \lfloor w_a / r_c\rfloor$ bins along cell vector a ($w_a$ the perpendicular
// width, $r_c = 2R_{max} + s$ the cut-off with the Verlet skin s): a pair within $r_c$
// differs by at most $r_c/w_a \le 1/n_a$ in $s_a$, so it lies in neighbouring bins
// (27-bin stencil, wrapped, the wrap giving the shift). The minimum-image condition
// $w_a \ge 2r_c$ is required: then a pair has at most one image within range, the list
// needs no duplicate check even with one or two bins along an axis, and the contact
// history is keyed by the pair alone.
//
// Rebuild criterion (the list must hold every pair that can touch before the next
// build). With $F = H H_{ref}^{-1}$ the deformation since the build and
// $\delta = \max_p |x_p - F x_{p,ref}|$ the largest fluctuating displacement, a pair now
// touching was within $\|F^{-1}\|(2R_{max} + 2\delta)$ at the build; with
// $\|F^{-1}\|_2 \le 1 + e$, $e = \|F^{-1} - I\|_F$, the list is safe while
// $$ 2R_{max}\,e + 2(1+e)\,\delta \le s. $$
// Deterministic: particles are visited in storage order, the 27 bins in a fixed order and
// each bin's particles in storage order (a stable counting sort); the tangential
// history is carried across builds by the pair's key (its two ids).
#pragma once

#include "dem/ContactMemory.h"
#include "dem/periodic/CellMatrix.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace geocomp::dem {

/// One pair of the list: j's image at x_j + H shift is the partner of i (i < j).
struct PeriodicPair
{
  Index i = 0, j = 0;
  std::array<std::int32_t, 3> shift{{0, 0, 0}};
};

class PeriodicNeighbours
{
public:
  struct Parameters
  {
    double skin = 0.0;  ///< [m] Verlet skin s
  };

  /// Positions (wrapped into the cell), radii and ids; the tangential history of the
  /// previous list is carried over to the pairs that are in both.
  struct BuildInput
  {
    const std::vector<Vec3>& x;
    const std::vector<double>& radius;
    const std::vector<ParticleId>& id;
    const CellMatrix& cell;
    bool keep_memory = false;  ///< carry ContactMemory too (laws with memory)
  };

  PeriodicNeighbours() = default;
  explicit PeriodicNeighbours(const Parameters& p) : p_(p) {}

  const Parameters& parameters() const { return p_; }
  /// The skin of the next build [m].
  void set_skin(double skin) { p_.skin = skin; }
  double cutoff() const { return cutoff_; }

  /// Builds the list; throws std::runtime_error when a perpendicular width of the cell
  /// is below twice the cut-off (the minimum-image condition).
  void build(const BuildInput& in);

  /// True when the particles may have moved far enough for a touching pair to be missing.
  bool needs_rebuild(double fluctuation, double deformation) const
  {
    return 2.0 * r_max_ * deformation + 2.0 * (1.0 + deformation) * fluctuation > p_.skin;
  }

  std::vector<PeriodicPair> pairs;
  std::vector<Vec3> shear;             ///< tangential history per pair (acting on j)
  std::vector<ContactMemory> memory;   ///< per pair, laws with memory only
  std::vector<double> overlap;         ///< overlap at the last evaluation (0: apart)

  std::size_t builds() const { return builds_; }

private:
  struct Carried
  {
    std::uint64_t key;
    Vec3 shear;
    ContactMemory memory;
    double overlap;
    bool operator<(const Carried& o) const { return key < o.key; }
  };
  void bin(const BuildInput& in);
  void collect_history(const std::vector<ParticleId>& id, bool keep_memory);
  void restore_history(const std::vector<ParticleId>& id, bool keep_memory);

  Parameters p_{};
  double cutoff_ = 0.0, r_max_ = 0.0;
  std::size_t builds_ = 0;
  std::array<std::int32_t, 3> dims_{{1, 1, 1}};
  std::vector<std::uint32_t> bin_of_, start_, cursor_, items_;
  std::vector<Carried> carried_;
};

}  // namespace geocomp::dem
