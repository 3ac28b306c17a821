// @sect3{The pieces of a LIGGGHTS deck shared by the main deck and its branch decks}
//
// Why it exists: LiggghtsDeck.cpp writes the main deck (in.geocomp), LiggghtsBranchDeck.cpp
// one deck per unloading branch (in.branch_<stage>_<trigger>), which restarts from the
// main run's restart file at the trigger. Both declare the same walls, box variables,
// servo and sample rows; these are the functions that write them (LiggghtsDeck.h says
// what each part of the deck does).
#pragma once

#include "common/LoadingProgram.h"
#include "dem/liggghts/LiggghtsDeck.h"

#include <filesystem>
#include <string>
#include <utility>

namespace geocomp::dem::deck {

inline constexpr const char *kAxis = "xyz";
inline constexpr const char *kWall[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};

/// 17 significant digits.
std::string num(double v);
void write_text(const std::filesystem::path &file, const std::string &text);
/// The deck's test of a stop condition or trigger; CaseError (naming `where`) for one it
/// cannot test.
std::string condition_expression(const Condition &c, const std::string &where, const std::string &file);
/// Units, atoms (read_data specimen.data, or read_restart `restart`), contact law, walls.
std::string header_section(const LiggghtsDeckInput &in, const std::string &restart);
/// Wall positions, edges, strains, the stress tensor, tau_max, the servo's wall stiffness.
std::string geometry_section(const Packing &p, const LiggghtsContact &law);
/// The walls' move/mesh fixes, the force variables, thermo output.
std::string wall_motion_section(long long steps_per_sample);
/// The column names of samples.txt and the print text of one row.
std::pair<std::string, std::string> sample_columns();
/// After each `run`: the step and the walls' normal forces, for the next run's first step.
std::string keep_forces();
/// The wall speeds of stage s for direction +1 (loading) or -1 (every rate reversed): the
/// kinematic axes' rule and the stress axes' servo.
std::string kinematic_and_servo_variables(const Stage &s, double direction, const LiggghtsDeckInput &in);
/// "branch_<stage>_<trigger>" (1-based): the stem of a branch's deck, restart and state files.
std::string branch_name(int stage, int trigger);
/// The deck of trigger `trigger` of stage `stage` (1-based): LiggghtsBranchDeck.cpp.
std::string branch_deck(const Stage &s, int stage, int trigger, long long steps_per_sample,
                        const LiggghtsDeckInput &in);

} // namespace geocomp::dem::deck
