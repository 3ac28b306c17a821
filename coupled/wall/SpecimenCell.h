#pragma once
// @sect3{The wall specimen's own particles as a periodic cell}
//
// Why it exists: the strictest form of "the same packing" - the very spheres of a wall
// specimen, with the walls taken away. dem::cell_from_packing (dem/periodic/
// PeriodicPreparation.h) makes the specimen's box the cell; every centre lies at least its
// radius inside the walls, so nothing overlaps across the new periodic faces, but the two
// wall layers that now face each other are looser than the bulk and carry no force across.
// The cell is therefore compressed again by the RVE's servo to the pressure (the RVE's
// tolerances, RveProtocol), from rest, with the grains' friction and the settings' local
// damping; the contact springs start from zero, as cell_from_packing gives no history.
#include "coupled/RvePreparation.h"
#include "dem/DemSystem.h"
#include "dem/periodic/PeriodicCell.h"

#include <cstdint>

namespace geocomp::coupled {

struct SpecimenCell {
  dem::PeriodicCell cell;
  std::uint64_t compression_steps = 0;
  double volume_change = 0.0;  ///< ln(V / V_box) of the compression (tension positive)
};

/// The cell of `specimen`'s spheres (walls 0..5 the box faces), at the settings' pressure.
/// Throws std::runtime_error when the compression does not converge.
SpecimenCell cell_of_specimen(const dem::DemSystem &specimen, const RveGrains &grains,
                              const RvePreparationSettings &settings, const RveProtocol &protocol = {});

} // namespace geocomp::coupled
