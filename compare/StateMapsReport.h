#pragma once
// The report's section "Maps at named states" (SectionMaps.h): for each named state a heading
// with its strain, or the reason it is missing, then one row per quantity, the DEM panel
// beside the FE one on one colour scale. Report.cpp calls these for the plots, the HTML and
// metrics.json, so the three read the same StateMaps.
#include "compare/SectionMaps.h"

#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::compare {

/// PNG file name of a panel: state s, row r, side 0 (left, DEM) or 1 (right, FE).
std::string state_map_png(std::size_t s, std::size_t r, int side);

/// Writes the panels' data under `dir`/data and returns their gnuplot commands; appends the
/// PNG names to `pngs`.
std::string state_maps_script(const std::vector<StateMaps> &maps, const std::filesystem::path &dir,
                              std::vector<std::string> &pngs);

/// The HTML section (empty without states); `made` are the PNGs gnuplot produced.
std::string state_maps_html(const std::vector<StateMaps> &maps, const std::string &note,
                            const std::vector<std::string> &made);

/// The JSON value of "named_states".
std::string state_maps_json(const std::vector<StateMaps> &maps);

} // namespace geocomp::compare
