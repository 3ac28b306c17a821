// The shared benchmark's contact law (../shared/bench/params.sh), set on a DemSystem: linear
// spring-dashpot with k_n = 1e6 N/m, k_t = 285714.2857 N/m, c_n = gamma_n m* (gamma_n =
// 4512.4128 1/s, no clamp, as LIGGGHTS hooke/stiffness), no tangential damping. One place
// for geocomp-dem-bench (which times it) and geocomp-bench-packing (which packs with it).
#pragma once

#include "dem/DemSystem.h"

#include <cstdlib>
#include <string>

namespace geocomp::bench {

struct BenchParameters
{
  double rho = 2650.0, kn = 1.0e6, kt = 285714.2857, gamma_n = 4512.4128, mu = 0.4;
  double dt = 2.70097e-5, skin = 0.00236, v_wall = 0.01, radius = 0.0118;
};

/// GEOCOMP_BENCH_LAW=s0: S0's normal law instead (k_n from E = 7 GPa, nu = 0.25, V_c = 1 m/s,
/// c_n from restitution 0.5: k_n ~ 2.4e6 N/m here, still stable at this dt), to time the
/// law of the S0 cases; not the shared benchmark's figure.
inline void set_bench_law(dem::DemSystem &sys, const BenchParameters &b)
{
  using namespace dem;
  LinearNormal::Parameters np;
  np.k_n = b.kn;
  np.damping_input = LinearNormal::Damping::per_unit_mass;
  np.gamma_n = b.gamma_n;
  np.clamp_tensile = false;
  LinearTangential::Parameters tp;
  tp.stiffness_is_ratio = false;
  tp.k_t = b.kt;
  tp.damping_is_ratio = false;
  tp.c_t = 0.0;
  if (const char *e = std::getenv("GEOCOMP_BENCH_LAW"); e && std::string(e) == "s0") {
    np.stiffness_input = LinearNormal::Stiffness::from_impact_velocity;
    np.youngs_modulus = 7e9;
    np.poisson_ratio = 0.25;
    np.impact_velocity = 1.0;
    np.damping_input = LinearNormal::Damping::restitution;
    np.restitution = 0.5;
  }
  sys.set_contact_model(LinearSpringDashpot(LinearNormal(np), LinearTangential(tp)));
  sys.set_friction(b.mu);
}

} // namespace geocomp::bench
