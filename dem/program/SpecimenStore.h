// @sect3{The digital core store: many prepared specimens in one HDF5 archive}
//
// Why it exists: S0 starts every test from a library of prepared cubic specimens (the
// "digital core store", 26 specimens varying N, packing fraction, friction and
// viscosity). Preparing a 100 000-sphere specimen takes hours, and results depend on
// how it was prepared, so a specimen is made once (`geocomp pack`), stored with its
// preparation record and the parameters that made it, and loaded by any case with
// `specimen/source = store`.
//
// Layout (docs/specimens.md has the full table): the root carries `format` =
// "geocomp core store" and `format_version`; each specimen is the group
// `/specimens/<name>` with
//  - attributes: N, eta, R, L0, sigma_0, mu_s, mu_p, c_r, E, nu, V_c, k_n, c_n, k_t/k_n,
//    contact model, density, size distribution, seed, aristotelian, dt, the case file,
//    version, creation time, and the preparation record in one sentence;
//  - `particles/`: position (N x 3), radius, mass, orientation (N x 4, w x y z), velocity,
//    angular_velocity (N x 3), all in id order;
//  - `walls/`: point, normal, velocity, force (6 x 3), friction (6);
//  - `contacts/`: wall (0/1), i (particle id or wall), j, overlap, shear (n x 3): the
//    contact histories of DemSystem::export_contact_state();
//  - `record/`: every number of the PreparationRecord as attributes;
//  - `case_text`: the case file that made it;
//  - `state`: the complete DemSystem::write_state() bytes (deflate-compressed).
// Loading reads `state`, so a stored specimen continues bit for bit as the original
// would. A build whose binary layout differs cannot read `state`; it then rebuilds the
// system from the portable datasets (same positions, velocities, radii and contact
// histories, but not the same bits: StoredSpecimen::exact says which).
#pragma once

#include "dem/case/DemParameters.h"
#include "dem/program/SpecimenPreparation.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::dem {

struct StoreError : std::runtime_error
{
  StoreError(const std::string &message, bool missing_name = false)
    : std::runtime_error(message), missing_name(missing_name) {}
  bool missing_name; ///< the file is fine but holds no specimen of that name
};

/// The parameters that made a specimen (from the pack case).
struct SpecimenMetadata
{
  std::size_t particles = 0;
  double packing_fraction = 0.0;       ///< target eta
  double radius = 0.0;                 ///< [m] R given (mean)
  double box_size = 0.0;               ///< [m] L0 of the growth box
  double isotropic_pressure = 0.0;     ///< [Pa] sigma_0, compression positive
  double density = 0.0;
  std::string size_distribution;
  double radius_spread = 0.0, lognormal_sigma = 0.0;
  bool aristotelian = false;
  std::uint64_t seed = 0;
  ContactParameters contact;           ///< mu_s, mu_p, c_r, E, nu, V_c, k_n, ...
  double time_step = 0.0;              ///< [s]
  std::string case_file, case_text, created, version;

  static SpecimenMetadata from_case(const DemCase &c, const PreparedSpecimen &s);
};

struct StoredSpecimen
{
  std::string name;
  SpecimenMetadata metadata;
  PreparationRecord record;
  DemSystem system;
  bool exact = true; ///< restored from the binary state (false: rebuilt from the portable datasets)
};

/// Adds (or replaces) the specimen `name` in the store at `path` (created if absent).
/// The new store is written under a temporary name and renamed over the old one.
void write_stored_specimen(const std::filesystem::path &path, const std::string &name, const PreparedSpecimen &s,
                           const SpecimenMetadata &metadata);
/// Reads the specimen `name`; StoreError (missing_name set when only the name is wrong).
StoredSpecimen read_stored_specimen(const std::filesystem::path &path, const std::string &name);
/// Names of the specimens in a store, in the order they were added.
std::vector<std::string> stored_specimen_names(const std::filesystem::path &path);
/// Letters, digits, '_', '-', '.'; not empty.
bool valid_specimen_name(const std::string &name);

} // namespace geocomp::dem
