// @sect3{What a normal contact part returns}
//
// Why it exists: the tangential part of a composed law needs the normal part's result
// (Coulomb cap $\mu F_n$, and "k_t as a ratio of k_n" / "c_t as a ratio of c_n"), and the
// energy ledger needs the elastic share of the force. One small struct carries these.
#pragma once

namespace geocomp::dem {

struct NormalResponse
{
  double force = 0.0;     ///< F_n on j along n (> 0 repulsive), after the tensile clamp
  double elastic = 0.0;   ///< elastic (spring) part of F_n
  double stiffness = 0.0; ///< normal stiffness at this overlap (k_n, or the Hertz tangent S_n)
  double damping = 0.0;   ///< normal dashpot coefficient at this overlap (c_n or eta_n)
};

}  // namespace geocomp::dem
