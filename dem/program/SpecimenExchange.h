// @sect3{Specimen exchange: a specimen to and from other tools' packing files}
//
// Why it exists: a specimen made here should be testable in LIGGGHTS, Yade or PFC, and a
// packing made there should be testable here (issue 4, item 6). The exchange unit is the
// plain Packing of dem/specimen/Packing.h: sphere centres, radii, one density and the box.
// Two formats, chosen by the file's extension:
//  - `.data`: LAMMPS/LIGGGHTS data file, atom_style granular ("id type diameter density x y z");
//  - anything else: text "x y z r" per line with the box in a '#' header line (the format
//    of ../shared/bench/data/*.xyzr).
// A specimen's box is the box of its six walls (x-, x+, y-, y+, z-, z+, add_box() order),
// so a consolidated specimen exports with the box its walls hold it in. Velocities, contact
// histories and wall forces have no place in these formats: an imported packing is relaxed
// and consolidated again (SpecimenPreparation.h, `source = text`); for an exact restart use
// the core store (SpecimenStore.h).
#pragma once

#include "dem/DemSystem.h"
#include "dem/specimen/Packing.h"

#include <filesystem>

namespace geocomp::dem {

/// True for the LAMMPS/LIGGGHTS data format (extension `.data`), false for xyzr text.
bool is_lammps_data_file(const std::filesystem::path &file);

/// Reads either format (by extension); PackingFileError names the file and line.
Packing read_packing_file(const std::filesystem::path &file);

/// Writes either format (by extension) with 17 significant digits, under a temporary name
/// renamed when complete, so a failed write leaves no partial file.
void write_packing_file(const std::filesystem::path &file, const Packing &packing);

/// The spheres of `system` in id order, with the box of its first six walls; `density`
/// is the material's (one density per packing).
Packing packing_of(const DemSystem &system, double density);

} // namespace geocomp::dem
