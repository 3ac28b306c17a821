// @sect3{Particle fields: HDF5 snapshots with an XDMF sidecar}
//
// Why it exists: localization is seen in fields, not in the box curves (S0 Fig. 3-5).
// A run appends ParticleFields snapshots (positions, displacements since the start of the
// program, velocities, spins, radii, ids, and the touching contacts with their forces) to
// one HDF5 file. Each append rewrites the file under a temporary name and renames it
// (common/AtomicFile.h), so an interrupted run never leaves a broken file, and rewrites
// the XDMF sidecar `<file>.xdmf`: a temporal collection in which every snapshot is a
// Polyvertex grid of the particles (point data: displacement, velocity, angular velocity,
// radius, id) and a Polyline grid of the particle-particle contacts (cell data: force,
// normal force, overlap), so ParaView shows both over time.
//
// Layout: /snapshots/s000000, s000001, ... each with attributes time and label and the
// datasets named as the ParticleFields members (n x 3 for vectors, c x 2 int64 for
// contact pairs). Reading back (read_snapshots) gives the same numbers bit for bit:
// the reference and current states for compare::local_strain.
#pragma once

#include "dem/program/DemEngine.h"

#include <filesystem>
#include <vector>

namespace geocomp::dem {

/// Appends one snapshot to `h5_file` (created if absent) and rewrites its XDMF sidecar.
/// Returns the snapshot's index in the file.
std::size_t append_snapshot(const std::filesystem::path &h5_file, const ParticleFields &fields);

/// All snapshots of a file, in order.
std::vector<ParticleFields> read_snapshots(const std::filesystem::path &h5_file);

/// The XDMF sidecar's path for an HDF5 fields file (same name, extension .xdmf).
std::filesystem::path xdmf_path(const std::filesystem::path &h5_file);

} // namespace geocomp::dem
