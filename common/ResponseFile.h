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
};

void write_response(const std::filesystem::path &path, const Response &response, RunMeta meta);
Response read_response(const std::filesystem::path &path, RunMeta *meta = nullptr);

} // namespace geocomp
