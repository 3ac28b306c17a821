#include "dem/EnergyAccounting.h"

#include <type_traits>
#include <variant>

namespace geocomp::dem {

void EnergyAccounting::add_contact_blocks(std::size_t n)
{
  for (std::size_t b = 0; b < n; ++b) {
    losses_.dissipated_damping += blocks_[kBlockTerms * b];
    losses_.dissipated_friction += blocks_[kBlockTerms * b + 1];
    losses_.dissipated_bonds += blocks_[kBlockTerms * b + 2];
    losses_.release_work += blocks_[kBlockTerms * b + 3];
  }
}

namespace {
/// The law's elastic energy of every listed pair and wall slot, into e.
template <class Law>
void add_elastic(const Law& law, const EnergySources& s, EnergyLedger& e)
{
  const ParticleStore& store = s.store;
  const ContactLists& lists = s.lists;
  const auto add = [&e](const ContactEnergy& c) {
    e.elastic_normal += c.normal;
    e.elastic_tangential += c.tangential;
    e.elastic_rolling += c.rolling;
    e.elastic_bonds += c.bond;
  };
  for (std::size_t c = 0; c < lists.pairs.size(); ++c) {
    const PairSlot& p = lists.pairs[c];
    const double m_eff = 1.0 / (store.inv_mass[p.i] + store.inv_mass[p.j]);
    const double Ri = store.radius[p.i], Rj = store.radius[p.j];
    if constexpr (Law::has_memory) {
      ContactKinematics k;
      k.overlap = p.overlap;
      k.m_eff = m_eff;
      k.r_eff = Ri * Rj / (Ri + Rj);
      k.mu = s.mu;
      add(law.elastic_energy(k, p.shear, lists.pair_memory[c]));
    } else if (p.overlap > 0.0) {
      add(law.elastic_energy(p.overlap, m_eff, Ri * Rj / (Ri + Rj), p.shear));
    }
  }
  for (std::size_t c = 0; c < lists.walls.size(); ++c) {
    const WallSlot& w = lists.walls[c];
    if constexpr (Law::has_memory) {
      ContactKinematics k;
      k.overlap = w.overlap;
      k.m_eff = store.mass[w.particle];
      k.r_eff = store.radius[w.particle];
      k.mu = s.walls[w.wall].mu;
      add(law.elastic_energy(k, w.shear, lists.wall_memory[c]));
    } else if (w.overlap > 0.0) {
      add(law.elastic_energy(w.overlap, store.mass[w.particle], store.radius[w.particle], w.shear));
    }
  }
}
}  // namespace

EnergyLedger EnergyAccounting::ledger(const EnergySources& s) const
{
  EnergyLedger e = losses_;
  const ClumpSet& clumps = s.clumps;
  const ParticleStore& store = s.store;
  for (std::size_t c = 0; c < clumps.size(); ++c) {
    e.kinetic_translational += 0.5 * clumps.mass[c] * clumps.v[c].squaredNorm();
    e.kinetic_rotational += clumps.kinetic_energy(c) - 0.5 * clumps.mass[c] * clumps.v[c].squaredNorm();
    e.gravitational -= clumps.mass[c] * s.gravity.dot(clumps.x[c]);
  }
  for (Index p = 0; p < store.size(); ++p) {
    if (store.inv_mass[p] == 0.0 || (store.flags[p] & flag::member)) continue;
    e.kinetic_translational += 0.5 * store.mass[p] * store.v[p].squaredNorm();
    e.kinetic_rotational += 0.5 / store.inv_inertia[p] * store.omega[p].squaredNorm();
    e.gravitational -= store.mass[p] * s.gravity.dot(store.x[p]);
  }
  std::visit([&](const auto& law) { add_elastic(law, s, e); }, s.model);
  return e;
}

}  // namespace geocomp::dem
