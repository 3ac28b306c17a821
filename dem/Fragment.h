// @sect3{The Fragment struct: one child sphere of a broken particle}
//
// Why it exists: breakage (S2) is split into a pure geometric part, which turns a parent
// sphere into a list of children (BreakageModes.h), and an engine part, which puts them
// into the DemSystem in place of the parent (DemSystem::replace_spheres). This struct
// is the only thing the two share: centre, radius and density of a child, SI units.
#pragma once

#include "dem/Types.h"

#include <vector>

namespace geocomp::dem {

struct Fragment
{
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
  double density = 0.0;
};

/// How DemSystem::replace_spheres puts the children in.
struct ReplacementOptions
{
  bool shelter_siblings = false;     ///< children of one parent ignore each other until apart (former scheme)
  double release_speed = 0.05;        ///< u [m/s]: placement overlaps fall at u (0: released at once)
};

/// One parent sphere (by stable id) and the children that replace it.
struct Replacement
{
  ParticleId parent = 0;
  std::vector<Fragment> children;
};

}  // namespace geocomp::dem
