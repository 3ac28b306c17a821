// @sect3{DemSystem: replacing broken spheres by their fragments (S2)}
//
// Why this file exists: particle breakage (S2, Zhao & Chi 2022) deletes a sphere that
// meets the crushing criterion and puts its children in its place. The storage is a
// structure of arrays indexed by storage position while everything persistent (contact
// histories, rolling springs, checkpoints, outputs) is keyed by stable ids, so the
// replacement works through ids only:
//   1. bring the lists up to date and export every contact state by id;
//   2. drop the states that involve a parent; remove each parent from the store (the last
//      particle moves into its slot), mark its id removed (index kNoIndex), append the
//      children with new ids;
//   3. import the remaining states and rebuild the lists, which carries them over by key.
// Children move with the parent's translation and spin as one rigid body about their
// own centre of mass $x_G = \sum m_c x_c / \sum m_c$:
// $$ v_c = v + \omega \times (x_c - x_G), \qquad \omega_c = \omega , $$
// so $\sum m_c v_c = (\sum m_c)\,v$: linear momentum is conserved whenever mass is.
// Children of one parent overlap each other (cube and 4-ball modes) and the neighbours
// the parent touched. With an overlap release at speed u (the default), every contact of
// a child starts with its overlap at placement as placement overlap $\delta_p$
// (ContactMemory.h), which falls at the rate u: at placement the fragments exert nothing
// on each other or their neighbours, and the force comes back over $\delta_p/u$, so the
// replacement neither explodes (a released pair of reduced mass m* gains at most
// $2 m^* u^2$, ContactLaw.h) nor lets the fragments pass through each other (S2's
// criterion 2: the local stress drops at breakage, then recovers).
// The mechanical energy the replacement removes (the parent's contacts) is booked as
// EnergyLedger::dissipated_breakage.
// With sheltering (the former scheme) the children of one parent share a sibling group
// (Types.h) and ignore each other until no two of them overlap; the children of a
// sheltered parent join its group (they overlap its former siblings). Compressed
// siblings never stop overlapping, so they pass through each other for good: kept only
// to reproduce the earlier runs.
#include "dem/DemSystem.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace geocomp::dem {

std::vector<ParticleId> DemSystem::replace_spheres(const std::vector<Replacement>& batch,
                                                  const ReplacementOptions& options)
{
  const bool shelter_siblings = options.shelter_siblings;
  std::vector<ParticleId> new_ids;
  if (batch.empty()) return new_ids;
  if (!(options.release_speed >= 0.0))
    throw std::invalid_argument("DemSystem::replace_spheres: the overlap release speed must be >= 0");
  if (options.release_speed > 0.0 && !law_has_memory())
    throw std::invalid_argument("DemSystem::replace_spheres: the overlap release needs a contact law with memory "
                                "(rolling resistance or bonds)");
  std::vector<ParticleId> parents;
  for (const Replacement& r : batch) {
    if (!alive(r.parent))
      throw std::invalid_argument("DemSystem::replace_spheres: particle " + std::to_string(r.parent) + " does not exist");
    const Index k = index_of_[r.parent];
    if (store_.flags[k] & flag::member)
      throw std::invalid_argument("DemSystem::replace_spheres: particle " + std::to_string(r.parent) +
                                  " is a clump member");
    if (store_.flags[k] & flag::fixed)
      throw std::invalid_argument("DemSystem::replace_spheres: particle " + std::to_string(r.parent) + " is kinematic");
    if (r.children.empty()) throw std::invalid_argument("DemSystem::replace_spheres: a parent without children");
    for (const Fragment& f : r.children)
      if (!(f.radius > 0.0) || !(f.density > 0.0) || !f.centre.allFinite())
        throw std::invalid_argument("DemSystem::replace_spheres: a child needs a finite centre, radius > 0, density > 0");
    parents.push_back(r.parent);
  }
  std::sort(parents.begin(), parents.end());
  if (std::adjacent_find(parents.begin(), parents.end()) != parents.end())
    throw std::invalid_argument("DemSystem::replace_spheres: a parent appears twice");

  // (1) Histories by id, from lists that match the store.
  prepare();
  const double mechanical_before = track_energy_ ? energy().mechanical() : 0.0;
  std::vector<ContactState> states = export_contact_state();
  auto involves_parent = [&](const ContactState& c) {
    if (std::binary_search(parents.begin(), parents.end(), c.j)) return true;
    return !c.wall && std::binary_search(parents.begin(), parents.end(), ParticleId(c.i));
  };
  states.erase(std::remove_if(states.begin(), states.end(), involves_parent), states.end());

  // (2) Parents out, children in.
  // A fresh sibling tag below every tag in use (no counter: nothing new to checkpoint).
  std::int32_t group = kFirstSiblingGroup;
  for (std::int32_t b : store_.body)
    if (b <= kFirstSiblingGroup) group = std::min(group, b - 1);
  for (const Replacement& r : batch) {
    const Index k = index_of_[r.parent];
    const Vec3 v = store_.v[k], w = store_.omega[k];
    const Quat q = store_.orientation[k];
    // A sheltered parent passes its group on: its children overlap its former siblings.
    const std::int32_t inherited = store_.body[k];
    const std::int32_t tag = inherited <= kFirstSiblingGroup ? inherited : group;
    index_of_.remove(store_, r.parent);

    double m_sum = 0.0;
    Vec3 xg = Vec3::Zero();
    for (const Fragment& f : r.children) {
      const double m = 4.0 / 3.0 * M_PI * f.radius * f.radius * f.radius * f.density;
      m_sum += m;
      xg += m * f.centre;
    }
    xg /= m_sum;
    for (const Fragment& f : r.children) {
      const double m = 4.0 / 3.0 * M_PI * f.radius * f.radius * f.radius * f.density;
      const ParticleId id = index_of_.add_sphere(store_, f.centre, f.radius, m);
      const Index c = index_of_[id];
      store_.v[c] = v + w.cross(f.centre - xg);
      store_.omega[c] = w;
      store_.orientation[c] = q;
      if (shelter_siblings && (r.children.size() > 1 || tag == inherited)) store_.body[c] = tag;
      new_ids.push_back(id);
    }
    if (shelter_siblings && tag == group) --group;
  }
  refresh_index();

  // (3) Surviving histories back, lists and forces for the new configuration.
  import_contact_state(states);
  rebuild_requested_ = true;
  invalidate();
  prepare();
  if (options.release_speed > 0.0) {
    std::vector<ParticleId> sorted = new_ids;
    std::sort(sorted.begin(), sorted.end());
    place_fragment_contacts(sorted, options.release_speed);
    invalidate();
    prepare();
  }
  if (track_energy_) energy_.losses().dissipated_breakage += mechanical_before - energy().mechanical();
  return new_ids;
}

void DemSystem::place_fragment_contacts(const std::vector<ParticleId>& children, double release_speed)
{
  auto is_child = [&](Index k) { return std::binary_search(children.begin(), children.end(), store_.id[k]); };
  auto place = [&](ContactMemory& m, double overlap) {
    if (!(overlap > 0.0)) return;
    m.placement = overlap;
    m.placement_rate = release_speed;
  };
  for (std::size_t c = 0; c < lists_.pairs.size(); ++c) {
    const PairSlot& s = lists_.pairs[c];
    if (!is_child(s.i) && !is_child(s.j)) continue;
    place(lists_.pair_memory[c], store_.radius[s.i] + store_.radius[s.j] - (store_.x[s.j] - store_.x[s.i]).norm());
  }
  for (std::size_t c = 0; c < lists_.walls.size(); ++c) {
    const WallSlot& s = lists_.walls[c];
    if (!is_child(s.particle)) continue;
    Vec3 n;
    place(lists_.wall_memory[c], store_.radius[s.particle] - walls_[s.wall].gap(store_.x[s.particle], n));
  }
}

std::size_t DemSystem::release_separated_siblings()
{
  std::vector<std::pair<std::int32_t, Index>> members;
  for (Index k = 0; k < store_.size(); ++k)
    if (store_.body[k] <= kFirstSiblingGroup) members.emplace_back(store_.body[k], k);
  if (members.empty()) return 0;
  std::sort(members.begin(), members.end());
  std::size_t freed = 0;
  for (std::size_t a = 0; a < members.size();) {
    std::size_t b = a;
    while (b < members.size() && members[b].first == members[a].first) ++b;
    bool overlapping = false;
    for (std::size_t i = a; i < b && !overlapping; ++i)
      for (std::size_t j = i + 1; j < b && !overlapping; ++j) {
        const Index p = members[i].second, q = members[j].second;
        const double reach = store_.radius[p] + store_.radius[q];
        overlapping = (store_.x[p] - store_.x[q]).squaredNorm() < reach * reach;
      }
    if (!overlapping) {
      for (std::size_t i = a; i < b; ++i) store_.body[members[i].second] = kOwnBody;
      ++freed;
    }
    a = b;
  }
  if (freed > 0) rebuild_requested_ = true;  // the freed pairs must be listed
  return freed;
}

std::size_t DemSystem::n_sheltered() const
{
  return std::size_t(std::count_if(store_.body.begin(), store_.body.end(),
                                   [](std::int32_t b) { return b <= kFirstSiblingGroup; }));
}

}  // namespace geocomp::dem
