// @sect3{A case as a LIGGGHTS 3.8 run: data file, wall meshes and an input deck}
//
// Why it exists: issue 34 pairs geocomp's DEM with an independent engine on one specimen
// and one loading program. write_liggghts_case() writes, into one folder:
//  - `specimen.data`: atom_style granular (id type diameter density x y z, type 1) with a
//    Velocities section when the specimen moves; the domain reaches half an edge beyond
//    each wall so that servo walls may move out (boundary f f f);
//  - `wall_{x,y,z}{lo,hi}.stl`: each face of the box as two triangles reaching a quarter
//    edge beyond the box, so the six meshes act as the infinite planes of geocomp's walls;
//  - `in.geocomp`: the deck. Walls are `fix mesh/surface/stress` meshes (type 2) with a
//    reference point on their plane, so f_ID[1..3] is the force of the spheres on the wall
//    and f_ID[7..9] where the wall now is; `fix move/mesh ... linear/variable` moves them
//    by equal-style variables evaluated every step. Meshes, not `fix wall/gran` planes:
//    this build's planar walls cannot move by a variable.
// Each stage of the program is a loop of `run` chunks of one sample interval, with the
// stop conditions tested after each chunk (as geocomp tests them at each sample) and the
// max duration as the loop's count. Kinematic axes: the outward speed of both walls is
// $v = \tfrac12(L_0(1+\varepsilon(t_{n+1})) - L)/\Delta t$, geocomp's DemEngine rule, so
// the edge follows StageControl::strain (S0 eq. (3) included: $L_z = V_0/(L_xL_y)$ as a
// time-varying wall speed). Stress axes: geocomp's AxisServo (ServoControl.h) written out
// in variables: the error $e = \sigma^{goal} - \sigma$, $G = A/(K\Delta t)$ with $K$ the
// mean over the axis' two walls of the summed normal stiffness of their touching spheres
// (a per-atom overlap test) times $(1 + c_n/(k_n\Delta t))$, the proportional part
// $g_P G e$, and the integral part kept as the running sum of its increments in a `fix
// ave/time ... ave running` (mean x count), with geocomp's anti-windup, clamp and reset at
// each stage. LIGGGHTS computes no wall force in a run's setup and adds it twice in later
// setups: the deck takes one step at rest before the program (t = 0 after it), and from a
// run's setup to the end of its first step the servo reads the wall forces kept at the end
// of the previous run. Outputs: `samples.txt`, a row at t = 0 and one per sample interval
// (time, stage, wall positions, edges, the wall stresses tension positive, kinetic
// energies, the six walls' forces), and `stages.txt`, how each stage ended
// (LiggghtsSamples.h reads both).
// Unloading branches (S0 Fig. 2): after each main-path sample the deck tests the stage's
// `unload at` conditions; one that holds for the first time gets the next branch id, a
// `write_restart branch_<stage>_<trigger>.restart`, a state file beside it and a `start`
// line in branches.txt, and the main path goes on in the same run (writing a restart file
// leaves the run's state bit for bit as it is: measured). Each trigger has its own deck,
// `in.branch_<stage>_<trigger>` (LiggghtsBranchDeck.cpp), a second LIGGGHTS run from that
// restart with every rate reversed until tau_max is back to the target; its rows carry the
// branch id. A "peak" trigger and `locate elastic limit` are refused (CaseError).
#pragma once

#include "common/LoadingProgram.h"
#include "dem/liggghts/LiggghtsContact.h"
#include "dem/program/ServoControl.h"
#include "dem/specimen/Packing.h"

#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::dem {

struct LiggghtsDeckInput
{
  std::string case_file;            ///< for messages
  const Packing *packing = nullptr; ///< the specimen in its box, velocities when known
  const LoadingProgram *program = nullptr;
  LiggghtsContact contact;
  ServoParameters servo;
  double time_step = 0.0; ///< [s] geocomp's dt for this specimen (the deck's is the sample
                          ///< interval divided into whole steps no longer than it)
  double skin = 0.0;      ///< [m] neighbour skin
};

/// What was written, for the command's summary.
struct LiggghtsDeckSummary
{
  std::filesystem::path deck, data;
  long long steps_per_sample = 0;
  double time_step = 0.0; ///< [s] the deck's: the sample interval over whole steps, at most geocomp's dt
  std::vector<std::string> notes;                  ///< what the deck does not play
  std::vector<std::filesystem::path> branch_decks; ///< in.branch_<stage>_<trigger>, one per trigger
};

/// Writes the folder's files; throws CaseError for a program entry LIGGGHTS cannot play
/// (a stop condition or trigger on peak_drop, servo_error or stress_ratio, a "peak"
/// trigger, `locate elastic limit`) before writing anything.
LiggghtsDeckSummary write_liggghts_case(const std::filesystem::path &dir, const LiggghtsDeckInput &in);

/// The program entries the deck cannot play, refused as write_liggghts_case() refuses
/// them (CaseError naming "program/stage N/stop when", ".../unload at" or ".../locate
/// elastic limit"), without a specimen: the command checks them before it prepares one.
void check_liggghts_program(const LoadingProgram &program, const std::string &case_file);

/// The specimen data file alone (2 atom types: spheres 1, walls 2).
void write_liggghts_data(const std::filesystem::path &file, const Packing &p);

} // namespace geocomp::dem
