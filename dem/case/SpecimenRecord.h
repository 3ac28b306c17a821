#pragma once
// The record of everything a prepared DEM specimen depends on: the build, the seed, and
// every entry of the `specimen`, `contact` and `dem` sections, as canonical text
// (CanonicalText.h) - except the few entries that cannot change the prepared specimen,
// each listed below with the reason.
//
// Why it exists: `pair` and `dem` keep the prepared specimen (`dem-specimen.bin`) and reuse
// it when the case is run again. A specimen is reused only when its whole record matches,
// so a change of any entry it depends on (a rolling friction, a servo gain) prepares it
// again; the contact law in the cached engine is therefore always the case's. The record
// is built from the structs' `visit` lists, so an entry added to a DEM section joins it
// without another line anywhere (a test checks the lists name every declared entry).
#include "dem/case/DemParameters.h"

#include <string>
#include <vector>

namespace geocomp::dem {

/// An entry (as `section/entry`) that cannot change the prepared specimen, and why.
struct SpecimenIndependentEntry {
  const char *entry;
  const char *reason;
};

/// The entries left out of the specimen record, each with its reason.
const std::vector<SpecimenIndependentEntry> &specimen_independent_entries();

/// The record: `build = <build>`, `seed = <seed>`, then the DEM sections' canonical lines
/// without the independent entries.
std::string specimen_record(const DemCase &c, const std::string &build);

/// The DEM sections' canonical text, every entry.
std::string dem_parameters_text(const DemCase &c);

} // namespace geocomp::dem
