// @sect3{Critical time steps and contact durations}
//
// Why it exists: explicit integration is stable only below $2/\omega_{max}$, and a
// collision is resolved only with tens of steps per contact. These closed forms give
// the run's time step (times a safety factor) and the tests' reference values
// (DEM-NOTES section 3, S4).
//  - Linear springs: $\Delta t_{crit} = \sqrt{m_{min}/k_{max}}$, $k_{max} = \max(k_n, 3.5 k_t)$
//    (the tangential mode of a sphere has effective mass $\tfrac27 m$); use 0.1-0.2 of it.
//  - Hertz (S4 Rayleigh step): $T_R = \pi R_{min}\sqrt{\rho/G}/(0.1631\nu + 0.8766)$;
//    use 0.2 T_R for dense packings (coordination > 4), up to 0.4 T_R when loose.
//  - Linear damped oscillator: $t_c = \pi/\sqrt{k/m^* - (c/2m^*)^2}$,
//    $e = \exp(-\pi\zeta/\sqrt{1-\zeta^2})$, $\zeta = c/(2\sqrt{m^*k})$.
//  - Elastic Hertz impact: $t_H = 2.868\,(m^{*2}/(R^* E^{*2} v_0))^{1/5}$,
//    $\delta_{max} = (15 m^* v_0^2/(16 E^*\sqrt{R^*}))^{2/5}$.
#pragma once

namespace geocomp::dem {

/// sqrt(m/k): the linear-spring time scale (multiply by a safety factor 0.1-0.2).
double spring_time_scale(double mass, double stiffness);
/// S4 Rayleigh time step T_R (multiply by 0.2 dense, up to 0.4 loose).
double rayleigh_time_step(double radius, double density, double shear_modulus, double poisson_ratio);
/// Contact duration of the unclamped linear spring-dashpot.
double linear_contact_duration(double m_eff, double k, double c);
/// Restitution of the unclamped linear spring-dashpot.
double linear_restitution(double m_eff, double k, double c);
/// Duration of an elastic Hertz impact at relative approach speed v0.
double hertz_contact_duration(double m_eff, double r_eff, double e_eff, double v0);
/// Largest overlap of an elastic Hertz impact at relative approach speed v0.
double hertz_max_overlap(double m_eff, double r_eff, double e_eff, double v0);

}  // namespace geocomp::dem
