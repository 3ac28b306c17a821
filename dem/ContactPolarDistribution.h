// @sect3{ContactPolarDistribution: contact number and mean contact force by direction}
//
// Why it exists: S2 (Zhao & Chi 2022, Figs. 8-11) compares its fragment replacement modes
// by polar distributions ("roses") of the contact number and of the mean contact force in
// a horizontal and a vertical projection plane, with and without the particles of 0 or 1
// contacts (Thornton 2000: they carry no load). This computes them from
// DemSystem::contacts(), the one list of touching contacts the other measurements use.
//
// Contacts binned: particle-particle contacts with $F_n = F\cdot n > 0$ (S2 counts particle
// contacts; wall contacts only with `include_walls`). The unit normal n is projected onto
//  - the horizontal plane x-y: $\theta = \mathrm{atan2}(n_y, n_x)$ (0 deg = +x, 90 deg = +y);
//  - the vertical planes x-z and y-z: $\theta = \mathrm{atan2}(n_x, n_z)$ and
//    $\mathrm{atan2}(n_y, n_z)$, measured from the loading axis z, so 0 and 180 deg are
//    axial and 90 and 270 deg lateral as in S2's figures. Both vertical planes are binned
//    with weight 1/2 each: the statistics of two planes, the numbers of one.
// The out-of-plane component is dropped (S2 projects): every contact counts in a plane
// with weight one, whatever the length of its projection, at the angle of its projection.
// A normal perpendicular to the plane (projected length below 1e-12) has no angle there
// and is left out of that plane only (a vertical normal is absent from x-y). For normals
// uniform on the sphere the projected angle is uniform in every plane (the projection of
// a rotation-invariant distribution is rotation invariant in the plane), so isotropy
// gives flat roses. A normal is an undirected line: a contact counts in the bins of
// $\theta$ and $\theta + 180$ deg (once seen from each particle), so the bins of a plane sum
// to twice its contacts and every rose is symmetric over 180 deg.
//
// Bins: an even number n (default 36) of width $w = 360/n$ deg centred on 0, w, 2w, ...
// (bin k holds $[(k - 1/2)w, (k + 1/2)w)$), so the axes are bin centres. Per bin: the
// contact number $N_k$ and the mean normal contact force $\bar f_k = \sum F_n / N_k$
// (0 for an empty bin).
//
// Variant "mechanical" (S2 section 3.2): contacts touching a particle with fewer than 2
// contacts are dropped (once, not iterated, like Thornton's $C_m$). A particle's contacts
// are counted over all contacts with $F_n > 0$, walls included whether or not walls are
// binned: a sphere pressed between a wall and a neighbour transmits force. (DemEngine's
// mechanical coordination number counts particle contacts only.)
//
// Summaries of a rose (Rothenburg & Bathurst 1989, second-order Fourier fit
// $N(\theta) \approx \bar N\,[1 + a_c \cos 2\theta + a_s \sin 2\theta]$, exact least squares on
// equal bins): $a_c = 2\sum_k N_k \cos 2\theta_k / \sum_k N_k$, $a_s$ likewise with sin,
// anisotropy $a = \sqrt{a_c^2 + a_s^2}$; $a_c > 0$ means more contacts near 0/180 deg (the
// loading axis in the vertical plane). The same fit of $\bar f_k$ gives $a_{f,c}$. Sectors:
// contacts and pooled mean force ($\sum F_n / \sum N$) of the bins whose centre lies within
// a half-width of 0/180 deg ("axial") or of 90/270 deg ("lateral").
#pragma once

#include "dem/DemSystem.h"

#include <cstddef>
#include <vector>

namespace geocomp::dem {

/// One polar histogram: contact number and force sum per angular bin.
struct PolarRose
{
  std::vector<double> contacts;  ///< N_k (halves in the vertical plane)
  std::vector<double> force;     ///< sum of F_n in bin k [N]

  std::size_t bins() const { return contacts.size(); }
  /// Bin centre [deg]: k 360/n.
  double angle_deg(std::size_t k) const { return 360.0 * double(k) / double(bins()); }
  /// $\bar f_k$ [N]; 0 for an empty bin.
  double mean_force(std::size_t k) const { return contacts[k] > 0.0 ? force[k] / contacts[k] : 0.0; }
  /// $\sum_k N_k$ (twice the contacts of the plane).
  double total() const;
  /// Second-order Fourier coefficients of N (cos, sin) and anisotropy magnitude.
  double contact_cos2() const;
  double contact_sin2() const;
  double contact_anisotropy() const;
  /// Second-order cosine coefficient of the mean force rose $\bar f_k$ (empty bins skipped).
  double force_cos2() const;

  struct Sector
  {
    double contacts = 0.0;
    double mean_force = 0.0;  ///< pooled: sum F_n / sum N [N]
  };
  /// Bins whose centre is within `half_width_deg` of `centre_deg` or of `centre_deg` + 180.
  Sector sector(double centre_deg, double half_width_deg) const;
};

struct ContactPolarSettings
{
  int bins = 36;               ///< even, >= 4 (default 10 deg)
  bool include_walls = false;  ///< bin particle-wall contacts too
};

class ContactPolarDistribution
{
public:
  enum Plane { horizontal = 0, vertical = 1 };
  enum Variant { all = 0, mechanical = 1 };

  using Settings = ContactPolarSettings;

  /// The distributions of the current contacts of `sys` (also counts the particles
  /// without any contact).
  static ContactPolarDistribution of(const DemSystem& sys, const Settings& s = {});
  /// The distributions of a contact list (DemSystem::contacts() or hand-made records).
  static ContactPolarDistribution of(const std::vector<ContactRecord>& contacts, const Settings& s = {});

  const PolarRose& rose(Plane p, Variant v) const { return roses_[p][v]; }
  int bins() const { return bins_; }
  /// Contacts binned (F_n > 0; walls only if included).
  std::size_t contacts(Variant v) const { return contacts_[v]; }
  /// Particles with exactly one contact with F_n > 0 (walls counted).
  std::size_t single_contact_particles() const { return n1_; }
  /// Particles with no contact with F_n > 0 (known only from a DemSystem; else 0).
  std::size_t free_particles() const { return n0_; }

private:
  int bins_ = 0;
  PolarRose roses_[2][2];
  std::size_t contacts_[2] = {0, 0};
  std::size_t n0_ = 0, n1_ = 0, touching_ = 0;
};

const char* to_string(ContactPolarDistribution::Plane p);
const char* to_string(ContactPolarDistribution::Variant v);

}  // namespace geocomp::dem
