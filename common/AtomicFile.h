#pragma once
// Results are written under a temporary name in the target folder and renamed when
// complete, so a crash or a refused input never leaves a half file under the final name.
#include <filesystem>
#include <functional>

namespace geocomp {

/// Calls write(tmp_path), then renames tmp_path to path; removes tmp_path on failure.
void write_atomically(const std::filesystem::path &path,
                      const std::function<void(const std::filesystem::path &)> &write);

} // namespace geocomp
