// @sect3{The CellStress struct: Love-Weber stress over the periodic cell}
//
// Why it exists: the RVE's answer to a deformation is its average stress. In a periodic
// cell every contact's branch vector $l_c = x_j + Hn - x_i$ is well defined (across the
// images), and the average of the stress over the cell volume V reduces to a sum over the
// contacts (Love-Weber; Christoffersen, Mehrabadi & Nemat-Nasser 1981):
// $$ \sigma^{c} = -\frac{1}{V}\sum_c F_c\otimes l_c \qquad\text{(Love-Weber)}, $$
// with $F_c$ the force on j (the body at the head of $l_c$); the minus sign gives the
// project's convention, tension positive (a repulsive contact has $F_c\parallel l_c$ and
// gives compression). Its symmetric part is reported; the skew part is the unbalanced
// moment of the contact forces and vanishes at equilibrium. The kinetic (Reynolds) part of
// the fluctuating velocities u is optional,
// $$ \sigma^{k} = -\frac{1}{V}\sum_p m_p\,u_p\otimes u_p \qquad\text{(kinetic stress)}. $$
// The servo reads the elastic share $\sigma^{el}$ (the normal dashpots left out): their
// force $c_n v_n$ is proportional to L itself ($v_n$ contains $n\cdot Ll$), and it would feed
// the servo's output straight back into its input (measured: the normal stresses then
// chattered between the two rate limits 0.5 % short of the target).
// The servo needs the cell's stiffness against each component of L: an affine strain
// increment $\Delta\varepsilon_{ab}$ changes overlap c by $-n_a l_b\Delta\varepsilon_{ab}$ and the
// stress by
// $$ \Delta\sigma_{ab} \approx K_{ab}\,\Delta\varepsilon_{ab},\qquad K_{ab} = \frac1V\sum_c k_{n,c}\,(n_a l_b)^2
//    \qquad\text{(normal springs only: an upper bound of the servo's step)}. $$
#pragma once

#include "dem/periodic/CellMatrix.h"

#include <cstddef>

namespace geocomp::dem {

struct CellStress
{
  Mat3 contact = Mat3::Zero();    ///< symmetric Love-Weber contact stress [Pa], tension positive
  Mat3 kinetic = Mat3::Zero();    ///< kinetic stress of the fluctuations [Pa] (zero unless asked for)
  Mat3 elastic = Mat3::Zero();    ///< the same with the normal dashpots left out [Pa] (what the servo reads)
  Mat3 skew = Mat3::Zero();       ///< skew part of -(1/V) sum F (x) l [Pa] (unbalanced contact moments)
  Mat3 stiffness = Mat3::Zero();  ///< K_ab [Pa] of the servo
  std::size_t contacts = 0;       ///< pairs carrying force
  double mean_contact_force = 0.0;///< [N] mean |F_c| over those contacts

  Mat3 total() const { return contact + kinetic; }
  /// Mean pressure p = -tr(sigma)/3 (compression positive) [Pa].
  double pressure() const { return -total().trace() / 3.0; }
};

}  // namespace geocomp::dem
