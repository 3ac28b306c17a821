// @sect3{The "none" rolling and cohesion parts}
//
// Why they exist: ContactLaw<Normal, Tangential, Rolling, Cohesion> composes optional
// parts (MercuryDPM's Species<..., Empty>). A law without rolling resistance or bonds
// names these empty types; ContactLaw tests `Part::enabled` with `if constexpr`, so
// nothing of a disabled part is compiled into the contact loop, and a law made only of
// "none" parts has no per-contact memory at all (ContactMemory.h). Sphere-only runs
// are therefore exactly as fast as before the parts existed.
#pragma once

namespace geocomp::dem {

/// No rolling resistance.
struct NoRolling
{
  static constexpr bool enabled = false;
};

/// No cohesion and no adhesion: contacts end at delta = 0.
struct NoCohesion
{
  static constexpr bool enabled = false;
};

}  // namespace geocomp::dem
