#pragma once
// The mid-sections a pair's engines recorded (the DEM's slab, DemSection.h; each FE engine's
// mid-plane, MidPlane.h), read once from the results folder for the two things the report
// draws from them: the maps at the named states (PairMaps.h), one panel per section, and the
// strain-field localization onset of each FE engine (compare/SectionLocalization.h), a row of
// the Rudnicki-Rice verdict beside its acoustic-tensor onset.
#include "compare/LocalizationOnsets.h"
#include "compare/Report.h"
#include "compare/SectionMaps.h"
#include "compare/case/CaseDescription.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace geocomp::cli {

/// An engine that ran and the section it left in the results folder (none: it left none).
struct PairSection {
  std::string engine; ///< "dem", "continuum", "fem-dem"
  std::optional<compare::SectionSeries> series;
};

/// The sections of the engines of `c` that ran, in the maps' order DEM | FE cube | FEM x DEM.
/// The DEM's only when the FE engines' mesh is a cube (or none of them runs): the DEM box is a
/// cube, a box mesh is not drawn beside it.
std::vector<PairSection> recorded_sections(const CaseDescription &c, const std::filesystem::path &dir);

/// The Response labelled `label` in `in` (engine_label), or none.
const Response *response_of(const compare::ReportInput &in, const std::string &label);

/// A section with the curve strains and stress axes of its engine's Response in `in`; without
/// a series or a Response, only the label (its panels and onset then say why).
compare::StrainedSection strained(const PairSection &section, const compare::ReportInput &in);

/// The strain-field onset of the FE engine `engine` ("<label> (strain field)") from its
/// section among `sections`, appended to `onsets`; nothing for an engine without a section entry.
void add_strain_field_onset(const compare::ReportInput &in, const std::vector<PairSection> &sections,
                            const std::string &engine, std::vector<compare::OnsetEstimate> &onsets);

} // namespace geocomp::cli
