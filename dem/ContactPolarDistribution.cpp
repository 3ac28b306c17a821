#include "dem/ContactPolarDistribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace geocomp::dem {

namespace {
constexpr double kDeg = 180.0 / M_PI;

/// Angular distance between two directions [deg], in [0, 180].
double angular_distance(double a, double b)
{
  const double d = std::fmod(std::fabs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

/// Adds a line of direction (u, v) in a plane, at the angle atan2(u, v) and its opposite,
/// with weight w and force w F (S2 Figs. 8-11). No angle for a zero-length projection.
void add_line(PolarRose& r, double u, double v, double w, double f)
{
  if (std::hypot(u, v) < 1e-12) return;
  const int n = int(r.bins());
  const double width = 360.0 / n;
  const int k = int(std::floor(std::atan2(u, v) * kDeg / width + 0.5));
  for (int kk : {k, k + n / 2}) {
    const int b = ((kk % n) + n) % n;
    r.contacts[std::size_t(b)] += w;
    r.force[std::size_t(b)] += w * f;
  }
}
}  // namespace

// @sect4{Rose summaries}

double PolarRose::total() const
{
  double s = 0.0;
  for (double c : contacts) s += c;
  return s;
}

double PolarRose::contact_cos2() const
{
  const double t = total();
  if (t <= 0.0) return 0.0;
  double s = 0.0;
  for (std::size_t k = 0; k < bins(); ++k) s += contacts[k] * std::cos(2.0 * angle_deg(k) / kDeg);
  return 2.0 * s / t;
}

double PolarRose::contact_sin2() const
{
  const double t = total();
  if (t <= 0.0) return 0.0;
  double s = 0.0;
  for (std::size_t k = 0; k < bins(); ++k) s += contacts[k] * std::sin(2.0 * angle_deg(k) / kDeg);
  return 2.0 * s / t;
}

double PolarRose::contact_anisotropy() const { return std::hypot(contact_cos2(), contact_sin2()); }

double PolarRose::force_cos2() const
{
  double s = 0.0, t = 0.0;
  for (std::size_t k = 0; k < bins(); ++k) {
    if (!(contacts[k] > 0.0)) continue;
    s += mean_force(k) * std::cos(2.0 * angle_deg(k) / kDeg);
    t += mean_force(k);
  }
  return t > 0.0 ? 2.0 * s / t : 0.0;
}

PolarRose::Sector PolarRose::sector(double centre_deg, double half_width_deg) const
{
  Sector s;
  double f = 0.0;
  for (std::size_t k = 0; k < bins(); ++k) {
    const double a = angle_deg(k);
    if (angular_distance(a, centre_deg) <= half_width_deg + 1e-9 ||
        angular_distance(a, centre_deg + 180.0) <= half_width_deg + 1e-9) {
      s.contacts += contacts[k];
      f += force[k];
    }
  }
  s.mean_force = s.contacts > 0.0 ? f / s.contacts : 0.0;
  return s;
}

// @sect4{Binning the contacts}

ContactPolarDistribution ContactPolarDistribution::of(const std::vector<ContactRecord>& contacts, const Settings& s)
{
  if (s.bins < 4 || s.bins % 2 != 0)
    throw std::invalid_argument("ContactPolarDistribution: bins must be even and >= 4");
  ContactPolarDistribution d;
  d.bins_ = s.bins;
  for (auto& plane : d.roses_)
    for (PolarRose& r : plane) {
      r.contacts.assign(std::size_t(s.bins), 0.0);
      r.force.assign(std::size_t(s.bins), 0.0);
    }
  // Contacts per particle (F_n > 0, walls included) for Thornton's classification.
  std::unordered_map<ParticleId, int> count;
  for (const ContactRecord& c : contacts) {
    if (!(c.normal_force > 0.0)) continue;
    ++count[c.j];
    if (!c.wall) ++count[ParticleId(c.i)];
  }
  for (const auto& [id, n] : count) d.n1_ += n == 1 ? 1 : 0;
  d.touching_ = count.size();
  for (const ContactRecord& c : contacts) {
    if (!(c.normal_force > 0.0) || (c.wall && !s.include_walls)) continue;
    const bool mechanical = count[c.j] >= 2 && (c.wall || count[ParticleId(c.i)] >= 2);
    const Vec3& n = c.normal;
    const double f = c.normal_force;
    for (int v = 0; v < (mechanical ? 2 : 1); ++v) {
      ++d.contacts_[v];
      add_line(d.roses_[horizontal][v], n.y(), n.x(), 1.0, f);  // S2 Figs. 8, 10
      add_line(d.roses_[vertical][v], n.x(), n.z(), 0.5, f);    // S2 Figs. 9, 11 (x-z)
      add_line(d.roses_[vertical][v], n.y(), n.z(), 0.5, f);    // (y-z)
    }
  }
  return d;
}

ContactPolarDistribution ContactPolarDistribution::of(const DemSystem& sys, const Settings& s)
{
  ContactPolarDistribution d = of(sys.contacts(), s);
  d.n0_ = sys.n_particles() - d.touching_;
  return d;
}

const char* to_string(ContactPolarDistribution::Plane p)
{
  return p == ContactPolarDistribution::horizontal ? "horizontal" : "vertical";
}

const char* to_string(ContactPolarDistribution::Variant v)
{
  return v == ContactPolarDistribution::all ? "all" : "mechanical";
}

}  // namespace geocomp::dem
