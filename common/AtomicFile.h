#pragma once
// Results are written under a temporary name in the target folder and renamed when
// complete, so a crash or a refused input never leaves a half file under the final name.
#include <filesystem>
#include <functional>

namespace geocomp {

/// Calls write(tmp_path), then renames tmp_path to path; removes tmp_path on failure.
void write_atomically(const std::filesystem::path &path,
                      const std::function<void(const std::filesystem::path &)> &write);

/// Builds a folder under a hidden temporary name beside `dir` (write(tmp)), then swaps it into
/// place: an existing `dir` is moved aside first and removed after, so a reader finds the old
/// folder or the new one whole. On failure the temporary folder is removed, `dir` is left as
/// it was and the exception goes on.
void replace_folder_atomically(const std::filesystem::path &dir,
                               const std::function<void(const std::filesystem::path &)> &write);

} // namespace geocomp
