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
// `stages.txt` says how each stage ended ("stop" or "max-duration"); a stop is named by the
// first stop condition that holds at the stage's last sample, as the ProgramRunner names it.
#pragma once

#include "common/LoadingProgram.h"
#include "common/Response.h"

#include <filesystem>
#include <stdexcept>

namespace geocomp::dem {

/// samples.txt or stages.txt is missing or malformed; the message names the file and line.
struct LiggghtsSamplesError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The Response of the deck's run in `dir`, its stages named after `program`.
Response read_liggghts_samples(const std::filesystem::path &dir, const LoadingProgram &program);

} // namespace geocomp::dem
