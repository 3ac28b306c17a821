// @sect3{LIGGGHTS' samples of an exported deck as a Response}
//
// Why it exists: `geocomp import liggghts DIR` (issue 34) puts LIGGGHTS' run beside
// geocomp's engines: the same Response (common/Response.h), engine "liggghts", so that
// `compare` and the report read it as any engine. The deck (LiggghtsDeck.h) prints one row
// of `samples.txt` at the start of the program and one per sample interval: time, stage,
// wall positions, edges, the wall stresses, kinetic energies and the force of the spheres
// on each of the six walls. From these:
//  - strain (engineering, tension positive, relative to the first row, the program's start):
//    $\varepsilon_{aa} = L_a/L_{0,a} - 1$; the off-diagonal strain is zero (walls only move
//    along their normals);
//  - stress, from every force component as geocomp's DemEngine measures it:
//    $\sigma_{ba} = -(F^{hi}_b - F^{lo}_b)/(2A_a)$ for the wall pair normal to a,
//    $A_a$ the current face area, symmetrised; LIGGGHTS' forces are those of the spheres on
//    the walls, so compression comes out negative. The stress is the instantaneous one
//    (interval_means false: the deck has no interval mean);
//  - extras: the translational and rotational kinetic energies [J].
// Unloading branches: rows whose `branch` column is k >= 1 were written by branch k's run
// (LiggghtsBranchDeck.cpp); `branches.txt` says where each left the main path (`start ID
// STAGE TRIGGER TIME`) and how it ended (`end ID target|max-duration`). Each branch's rows
// are placed after the main-path sample at its start time, and its BranchRecord computed
// as ProgramRunner::run_branch does (tau_start, the target tau_D of the stage start's
// stress, the residual gamma_max from the stage start).
// `stages.txt` says how each stage ended ("stop" or "max-duration"); a stop is named by the
// first stop condition that holds at the stage's last sample, as the ProgramRunner names it.
#pragma once

#include "common/LoadingProgram.h"
#include "common/Response.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::dem {

/// samples.txt or stages.txt is missing or malformed; the message names the file and line.
struct LiggghtsSamplesError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The decks of the branches the main run of `dir` started (branches.txt's `start` lines),
/// in the order of their ids: "in.branch_<stage>_<trigger>", to run after the main deck.
std::vector<std::string> liggghts_branch_decks(const std::filesystem::path &dir);

/// The Response of the deck's run in `dir`, its stages named after `program`; the branch
/// rows of samples.txt placed after the main-path sample each left from, with their
/// BranchRecords (branches.txt), as geocomp's ProgramRunner records them.
Response read_liggghts_samples(const std::filesystem::path &dir, const LoadingProgram &program);

} // namespace geocomp::dem
