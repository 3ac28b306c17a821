#pragma once
// HDF5 results file of one engine run: the Response record plus what made it.
// Layout documented in docs/results-format.md; written atomically (tmp + rename).
#include "common/Response.h"

#include <filesystem>
#include <string>

namespace geocomp {

/// Provenance stored under /meta of every results file.
struct RunMeta {
  std::string case_file;   ///< path as given
  std::string case_text;   ///< full text of the case file
  std::string command;     ///< command line
  unsigned long long seed = 0;
  std::string version;     ///< filled from Version.h when empty
  std::string git_hash;    ///< filled from Version.h when empty
  /// /meta kinematics: what the engine's strain and stress mean ("finite strain", "small
  /// strain" for the continuum; the DEM's particles move at finite strain); empty: not written.
  std::string kinematics;
  /// /meta/status: "complete", or where and why the run stopped early ("failed at t = ...:
  /// ..."; "stopped at t = ...: ..."); a file without it (older) reads as "complete".
  std::string status = "complete";
  /// /meta/parameters: every entry of every section of the case as parsed, canonical text
  /// (compare/case/CaseDescription.h, parameters_text); empty: not written.
  std::string parameters;
  /// /meta/specimen_record (DEM): what the prepared specimen depends on, the key of its reuse
  /// (dem/case/SpecimenRecord.h); empty: not written.
  std::string specimen_record;
};

void write_response(const std::filesystem::path &path, const Response &response, RunMeta meta);
Response read_response(const std::filesystem::path &path, RunMeta *meta = nullptr);

} // namespace geocomp
