// @sect3{The case's contact law as LIGGGHTS 3.8 sees it}
//
// Why it exists: a deck that replays a case in LIGGGHTS (issue 34) is only a cross-check
// if the two engines compute the same force at every contact. This mapping takes the
// case's `contact` section (and the `dem` entries that act as physics) and gives the
// LIGGGHTS pair style and its per-type-pair properties, or refuses the case with a
// CaseError naming the file, the entry and what LIGGGHTS would need (exit 2 on the
// command line). Atom type 1 is the spheres, type 2 the six wall meshes.
//  - `linear`: `hooke/stiffness` with `absolute_damping on` and `limitForce on` (geocomp
//    clamps F_n >= 0). Its k_n, k_t, gamma_n, gamma_t are numbers per type pair, so the
//    constants are taken from geocomp's own law (make_contact_model) evaluated for the
//    specimen's sphere-sphere and sphere-wall pairs; a law whose constants differ between
//    the specimen's pairs (S0's k_n or a restitution dashpot on a polydisperse specimen)
//    has no such numbers and is refused.
//  - `hertz-mindlin`: `hertz` with Young's modulus and Poisson's ratio per type (walls of
//    the particles' material, geocomp's like-material E* and G*) and the restitution per
//    pair; LIGGGHTS' hertz has the same Tsuji dashpots as geocomp's S4 law.
//  - both: `tangential history` (incremental spring, Coulomb cap), `coefficientFriction`
//    mu_s between spheres and mu_p with walls.
// Refused: S3 stick-slip, rolling friction, bonds and adhesion, wall bonding, and the
// Cundall local damping of `dem` (LIGGGHTS has none of them as geocomp defines them).
#pragma once

#include "dem/case/DemParameters.h"
#include "dem/specimen/Packing.h"

#include <string>
#include <vector>

namespace geocomp::dem {

/// The LIGGGHTS side of a contact law: what the deck writes.
struct LiggghtsContact
{
  std::string model;                   ///< "hooke/stiffness" or "hertz"
  std::string options;                 ///< model options after `tangential history`
  std::vector<std::string> properties; ///< `fix ... property/global ...` lines
  /// Per-atom expression of the normal stiffness of one sphere's contact with a wall at
  /// overlap `delta` (a LIGGGHTS variable expression in the word DELTA and c_rad): the
  /// servo's wall stiffness is its sum over the wall's touching spheres.
  std::string wall_stiffness_expression;
  /// c_n/k_n of a wall contact of the mean sphere at overlap 0.1 % of R: geocomp's
  /// DemEngine takes the same constant for its servo's one-step stiffness.
  double dashpot_time = 0.0;
};

/// Inputs of the mapping: the case file (for messages) and its sections, and the specimen.
struct LiggghtsContactInput
{
  std::string case_file;
  const ContactParameters *contact = nullptr;
  const DemParameters *dem = nullptr;
  const Packing *packing = nullptr;
};

/// The mapping above; throws CaseError (file, "contact/<entry>" or "dem/<entry>", what
/// LIGGGHTS needs) for an entry it cannot carry over.
LiggghtsContact map_contact_to_liggghts(const LiggghtsContactInput &in);

} // namespace geocomp::dem
