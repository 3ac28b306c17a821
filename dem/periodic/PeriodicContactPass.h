// @sect3{The periodic contact pass: the project's contact laws across the cell's images}
//
// Why it exists: the laws (ContactLaw.h) take a ContactKinematics and know nothing of
// periodicity; this pass feeds them the periodic kinematics. With fluctuating velocities
// u (the lab velocity is $u + Lx$) and j's image at $x_j + Hn$, the relative velocity
// of the two centres is
// $$ (u_j + L(x_j + Hn)) - (u_i + Lx_i) = u_j - u_i + L\,l,\qquad l = x_j + Hn - x_i
//    \qquad\text{(affine field; the } LHn \text{ shift term is inside } Ll), $$
// so sphere_sphere_kinematics() gets $v_i = u_i$, $v_j = u_j + Ll$ and the branch l. The
// affine field turns the grains with the cell's spin too: the lab spin is $\omega + w$,
// $w$ the axial vector of $\tfrac12(L - L^T)$ (the stored $\omega$ is the fluctuation, as u
// is), so a rigid rotation of the cell, $L = W$, moves no contact point relative to the two
// surfaces ($Wl = w\times l$ is cancelled by the spin terms) and the stress turns with the
// cell instead of loading the tangential springs. Rolling laws see $\omega_j - \omega_i$,
// the same either way. The force on j is $F = F_n n + F_t$ (-F on i), the torques
// $T = -(R - \delta/2)\,n\times F_t$ on each (plus $\pm M_r$ for rolling laws), as in the
// wall-box engine (ContactPass.cpp). The same loop sums the Love-Weber stress, its
// elastic share (the normal spring $F_n^{el}$ and the tangential force) and the servo
// stiffness (CellStress.h). Pairs are visited in list order: the same bits on every
// run. Laws with a cohesion part are refused by the cell (their reach beyond contact is
// not in the periodic list).
#pragma once

#include "dem/ContactLaw.h"
#include "dem/ParticleStore.h"
#include "dem/periodic/CellStress.h"
#include "dem/periodic/PeriodicNeighbours.h"

#include <cmath>

namespace geocomp::dem {

struct PeriodicPassInput
{
  ParticleStore& store;
  PeriodicNeighbours& lists;
  const CellMatrix& cell;
  const Mat3& velocity_gradient;  ///< L of this step
  double dt = 0.0;                ///< history increment
  double mu = 0.0;                ///< Coulomb friction coefficient
};

/// The spin of the affine field: the axial vector w of skw L (skw L x = w x x).
inline Vec3 affine_spin(const Mat3& l)
{
  return 0.5 * Vec3(l(2, 1) - l(1, 2), l(0, 2) - l(2, 0), l(1, 0) - l(0, 1));
}

/// Zeroes the loads, adds every contact's load to its two spheres and fills `out`'s
/// contact, skew and stiffness parts, contact count and mean contact force.
template <class Law>
void periodic_contact_pass(const Law& law, const PeriodicPassInput& in, CellStress& out)
{
  static_assert(!Law::has_cohesion, "the periodic cell does not take laws with a cohesion part");
  ParticleStore& s = in.store;
  PeriodicNeighbours& nl = in.lists;
  for (std::size_t p = 0; p < s.size(); ++p) {
    s.force[p].setZero();
    s.torque[p].setZero();
  }
  const Mat3& h = in.cell.h();
  const Vec3 spin = affine_spin(in.velocity_gradient);
  Mat3 fl = Mat3::Zero(), fl_elastic = Mat3::Zero(), stiff = Mat3::Zero();
  double force_sum = 0.0;
  std::size_t carrying = 0;
  for (std::size_t c = 0; c < nl.pairs.size(); ++c) {
    const PeriodicPair& pr = nl.pairs[c];
    const Index i = pr.i, j = pr.j;
    const Vec3 l = s.x[j] + h.col(0) * double(pr.shift[0]) + h.col(1) * double(pr.shift[1]) +
                   h.col(2) * double(pr.shift[2]) - s.x[i];
    const double r2 = l.squaredNorm(), r_sum = s.radius[i] + s.radius[j];
    if (r2 >= r_sum * r_sum) {
      nl.overlap[c] = 0.0;
      nl.shear[c].setZero();
      if constexpr (Law::has_memory) nl.memory[c].rolling.setZero();
      continue;
    }
    ContactKinematics k;
    const Vec3 vj = s.v[j] + in.velocity_gradient * l;  // affine field
    sphere_sphere_kinematics(k, l, std::sqrt(r2), s.radius[i], s.radius[j], s.v[i], vj, s.omega[i] + spin, s.omega[j] + spin,
                             s.inv_mass[i], s.inv_mass[j]);
    k.overlap_old = nl.overlap[c];
    k.dt = in.dt;
    k.mu = in.mu;
    ContactForce f;
    if constexpr (Law::has_memory) {
      if constexpr (Law::has_rolling) k.w_rel = s.omega[j] - s.omega[i];
      f = law.evaluate(k, nl.shear[c], nl.memory[c]);
    } else {
      f = law.evaluate(k, nl.shear[c]);
    }
    nl.overlap[c] = k.overlap;
    const Vec3 load = f.normal * k.normal + f.tangential;
    const Vec3 lever = k.normal.cross(f.tangential);
    s.force[j] += load;
    s.force[i] -= load;
    s.torque[i] -= (s.radius[i] - 0.5 * k.overlap) * lever;  // T = -(R - delta/2) n x F_t
    s.torque[j] -= (s.radius[j] - 0.5 * k.overlap) * lever;
    if constexpr (Law::has_rolling) {
      s.torque[j] += f.moment;
      s.torque[i] -= f.moment;
    }
    fl.noalias() += load * l.transpose();  // Love-Weber
    const NormalResponse nr = law.normal().evaluate(k);
    fl_elastic.noalias() += (nr.elastic * k.normal + f.tangential) * l.transpose();
    stiff.noalias() += nr.stiffness * (k.normal * l.transpose()).cwiseAbs2();  // servo stiffness K_ab
    force_sum += load.norm();
    ++carrying;
  }
  const double inv_v = 1.0 / in.cell.volume();
  const Mat3 sigma = -inv_v * fl;  // tension positive
  out.contact = 0.5 * (sigma + sigma.transpose());
  out.skew = 0.5 * (sigma - sigma.transpose());
  const Mat3 sigma_el = -inv_v * fl_elastic;
  out.elastic = 0.5 * (sigma_el + sigma_el.transpose());
  out.stiffness = inv_v * stiff;
  out.contacts = carrying;
  out.mean_contact_force = carrying > 0 ? force_sum / double(carrying) : 0.0;
}

}  // namespace geocomp::dem
