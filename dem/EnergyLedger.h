// @sect3{The EnergyLedger struct}
//
// Why it exists: an energy balance is the cheapest global check of a DEM run
// (DEM-NOTES section 10.3): stored energy plus what was dissipated must equal the
// initial energy plus the work the walls did,
// $$ E_{kin} + E_{el} + E_{grav} + D_{damp} + D_{fric} + D_{local} = E_0 + W_{walls}. $$
// Kinetic energy is $\sum\tfrac12 m v^2 + \tfrac12 I\omega^2$ (on-step velocities), elastic
// is the normal and tangential springs of all touching contacts (plus rolling springs
// and S3 bonds when the law has them), $E_{grav} = -\sum m g\cdot x$; clumps count as rigid
// bodies, $\tfrac12 Mv_G^2 + \tfrac12 L_b\cdot I^{-1}L_b$.
// Dissipation is accumulated per step only while energy tracking is on.
// Breakage (S2) adds two terms: the mechanical energy a replacement removes (the parent's
// contacts go, the fragments' placement overlaps store nothing at first) counts as
// dissipated, and the work of the gradual placement-overlap release (ContactLaw.h) as an
// input beside the walls' work.
#pragma once

namespace geocomp::dem {

struct EnergyLedger
{
  double kinetic_translational = 0.0;
  double kinetic_rotational = 0.0;
  double elastic_normal = 0.0;
  double elastic_tangential = 0.0;
  double gravitational = 0.0;
  double dissipated_damping = 0.0;   ///< contact dashpots (normal + tangential)
  double dissipated_friction = 0.0;  ///< Coulomb sliding
  double dissipated_local = 0.0;     ///< Cundall local damping
  double dissipated_bonds = 0.0;     ///< bond breakage and adhesion formation (S3)
  double elastic_rolling = 0.0;      ///< rolling springs (S2)
  double elastic_bonds = 0.0;        ///< S3 bond springs + adhesion potential (may be < 0)
  double wall_work = 0.0;            ///< work done by the walls on the particles
  double dissipated_breakage = 0.0;  ///< mechanical energy removed by fragment replacement (S2)
  double release_work = 0.0;         ///< work of the fragments' placement-overlap release (S2)

  double kinetic() const { return kinetic_translational + kinetic_rotational; }
  double elastic() const { return elastic_normal + elastic_tangential + elastic_rolling + elastic_bonds; }
  double mechanical() const { return kinetic() + elastic() + gravitational; }
  double dissipated() const
  {
    return dissipated_damping + dissipated_friction + dissipated_local + dissipated_bonds + dissipated_breakage;
  }
  /// Conserved quantity: mechanical + dissipated - wall work - release work.
  double balance() const { return mechanical() + dissipated() - wall_work - release_work; }
};

}  // namespace geocomp::dem
