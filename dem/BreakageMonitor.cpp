#include "dem/BreakageMonitor.h"

#include <algorithm>

namespace geocomp::dem {

BreakageMonitor::BreakageMonitor(const Settings& s) : settings_(s), rng_(s.seed)
{
  settings_.criterion.validate();
  if (settings_.interval == 0) throw std::invalid_argument("BreakageMonitor: interval must be >= 1");
}

std::vector<double> max_contact_forces(const DemSystem& sys)
{
  std::vector<double> f(sys.id_bound(), 0.0);
  for (const ContactRecord& c : sys.contacts()) {
    const double m = c.force.norm();
    f[c.j] = std::max(f[c.j], m);
    if (!c.wall) f[c.i] = std::max(f[c.i], m);
  }
  return f;
}

std::size_t BreakageMonitor::check(DemSystem& sys)
{
  if (settings_.replacement.shelter_siblings) sys.release_separated_siblings();
  f_max_ = max_contact_forces(sys);
  const ParticleStore& p = sys.particles();
  std::vector<Replacement> batch;
  std::vector<BreakageEvent> found;
  for (ParticleId id = 0; id < f_max_.size(); ++id) {
    if (!(f_max_[id] > 0.0) || !sys.alive(id)) continue;
    const Index k = sys.index_of(id);
    if (p.flags[k] & (flag::member | flag::fixed)) continue;
    const double d = 2.0 * p.radius[k];
    if (d < settings_.rules.breakage_limit) continue;          // S2: below d_L never breaks
    if (!settings_.criterion.breaks(f_max_[id], d)) continue;  // S2 eq. (3)
    const double density = p.mass[k] / (4.0 / 3.0 * M_PI * p.radius[k] * p.radius[k] * p.radius[k]);
    Fragmentation fr = fragment({p.x[k], p.radius[k], density}, settings_.rules, rng_);
    if (fr.children.empty()) continue;  // every child below d_M: stays whole
    BreakageEvent e;
    e.time = sys.time();
    e.parent = id;
    e.diameter = d;
    e.max_force = f_max_[id];
    e.children = int(fr.children.size());
    e.lost_mass = fr.lost_volume * density;
    found.push_back(e);
    batch.push_back({id, std::move(fr.children)});
  }
  if (batch.empty()) return 0;
  sys.replace_spheres(batch, settings_.replacement);
  for (const BreakageEvent& e : found) lost_mass_ += e.lost_mass;
  events_.insert(events_.end(), found.begin(), found.end());
  return found.size();
}

}  // namespace geocomp::dem
