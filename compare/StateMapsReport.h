#pragma once
// The report's section "Maps at named states" (SectionMaps.h): for each named state a heading
// with its strain, or the reason it is missing, then one row per quantity, one panel per
// engine (DEM | FE cube | FEM x DEM, those that recorded a section) on one colour scale. Report.cpp calls these for the plots, the HTML and
// metrics.json, so the three read the same StateMaps.
#include "compare/SectionMaps.h"

#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::compare {

/// PNG file name (without ".png") of the panel of `engine` in state s, row r: the label in
/// lower case, other characters as one '-' ("state1_2_fem-x-dem").
std::string state_map_png(std::size_t s, std::size_t r, const std::string &engine);

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
