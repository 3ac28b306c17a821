// @sect3{Reading DemSystem states written before contact memory and clumps (version 2)}
//
// Why it exists: DemSystem states are stored for restarts and inside the HDF5 core
// store (exact specimens, e.g. cases/store/small.h5). Version 3 of the state added the
// contact memory, the clumps and three ledger entries, and the law variant gained
// alternatives, so version 2 bytes no longer match the current structs. These are the
// version 2 layouts, member for member, so an old state is read and converted instead
// of being refused: the old law alternatives were `ContactLaw<Normal, Tangential>` with
// exactly two members, and the old ledger had nine doubles in this order.
#pragma once

#include "dem/ContactLaw.h"
#include "dem/ContactLists.h"
#include "dem/EnergyLedger.h"
#include "dem/PlaneWall.h"

#include <stdexcept>
#include <variant>

namespace geocomp::dem::legacy {

template <class Normal, class Tangential>
struct LawV2
{
  Normal normal;
  Tangential tangential;
};

using ContactModelV2 = std::variant<LawV2<LinearNormal, LinearTangential>, LawV2<HertzNormal, MindlinTangential>>;

inline ContactModel convert(const ContactModelV2& m)
{
  if (const auto* l = std::get_if<0>(&m)) return LinearSpringDashpot(l->normal, l->tangential);
  if (const auto* h = std::get_if<1>(&m)) return HertzMindlin(h->normal, h->tangential);
  throw std::runtime_error("legacy DEM state: empty contact law");
}

// PlaneWall before bounded walls (S4's split box added axis, half_u, half_v): the states
// in the committed core stores hold walls in this layout; they read as unbounded walls.
struct PlaneWallV3
{
  Vec3 point, normal, velocity;
  double mu;
  Vec3 force, torque;
  double work, stiffness;
  std::size_t n_contacts;
};

inline PlaneWall convert(const PlaneWallV3& o)
{
  PlaneWall w;
  w.point = o.point;
  w.normal = o.normal;
  w.velocity = o.velocity;
  w.mu = o.mu;
  w.force = o.force;
  w.torque = o.torque;
  w.work = o.work;
  w.stiffness = o.stiffness;
  w.n_contacts = o.n_contacts;
  return w;
}

// Pair and wall slots up to version 3: the history and the last loads in one 88-byte record
// (i or the wall, j or the particle, overlap, shear, force, lever). Version 4 keeps the
// loads beside the slots (ContactLists.h).
struct SlotV3
{
  Index a = 0, b = 0;
  double overlap = 0.0;
  Vec3 shear, force, lever;
};

/// The history and loads of an old slot, the bodies set by the caller.
template <class Slot>
inline void convert_history(const SlotV3& o, Slot& s, SlotLoad& load)
{
  s.overlap = o.overlap;
  s.shear = o.shear;
  load.force = o.force;
  load.lever = o.lever;
}
inline void convert(const SlotV3& o, PairSlot& s, SlotLoad& load)
{
  s.i = o.a;
  s.j = o.b;
  convert_history(o, s, load);
}
inline void convert(const SlotV3& o, WallSlot& s, SlotLoad& load)
{
  s.wall = o.a;
  s.particle = o.b;
  convert_history(o, s, load);
}

// Versions 3 to 5: contact memory without the fragments' placement overlap and a ledger
// without the breakage terms (S2 overlap release, version 6).
struct ContactMemoryV5
{
  Vec3 rolling, bond;
  double bond_origin;
  std::uint32_t state;
};

inline ContactMemory convert(const ContactMemoryV5& o)
{
  ContactMemory m;
  m.rolling = o.rolling;
  m.bond = o.bond;
  m.bond_origin = o.bond_origin;
  m.state = o.state;
  return m;
}

struct EnergyLedgerV5
{
  double kinetic_translational, kinetic_rotational, elastic_normal, elastic_tangential, gravitational,
    dissipated_damping, dissipated_friction, dissipated_local, dissipated_bonds, elastic_rolling, elastic_bonds,
    wall_work;
};

inline EnergyLedger convert(const EnergyLedgerV5& o)
{
  EnergyLedger e;
  e.kinetic_translational = o.kinetic_translational;
  e.kinetic_rotational = o.kinetic_rotational;
  e.elastic_normal = o.elastic_normal;
  e.elastic_tangential = o.elastic_tangential;
  e.gravitational = o.gravitational;
  e.dissipated_damping = o.dissipated_damping;
  e.dissipated_friction = o.dissipated_friction;
  e.dissipated_local = o.dissipated_local;
  e.dissipated_bonds = o.dissipated_bonds;
  e.elastic_rolling = o.elastic_rolling;
  e.elastic_bonds = o.elastic_bonds;
  e.wall_work = o.wall_work;
  return e;
}

struct EnergyLedgerV2
{
  double kinetic_translational, kinetic_rotational, elastic_normal, elastic_tangential, gravitational,
    dissipated_damping, dissipated_friction, dissipated_local, wall_work;
};

/// Version 2 had no bond or rolling terms: they start at zero.
inline EnergyLedger convert(const EnergyLedgerV2& o)
{
  return convert(EnergyLedgerV5{o.kinetic_translational, o.kinetic_rotational, o.elastic_normal, o.elastic_tangential,
                                o.gravitational, o.dissipated_damping, o.dissipated_friction, o.dissipated_local, 0.0,
                                0.0, 0.0, o.wall_work});
}

/// A memory array of version 3 to 5 as the current struct.
inline void convert_memory(const std::vector<ContactMemoryV5>& old, std::vector<ContactMemory>& out)
{
  out.resize(old.size());
  for (std::size_t c = 0; c < old.size(); ++c) out[c] = convert(old[c]);
}

}  // namespace geocomp::dem::legacy
