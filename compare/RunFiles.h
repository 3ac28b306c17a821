#pragma once
// Small file helpers shared by the reports that read programs' run folders (the S4 shear box,
// the S2 crush runs): a number printed with a printf format, a text file written or an
// exception naming it, and a run summary (`name<TAB>value` lines) read as a map.
#include <filesystem>
#include <map>
#include <string>

namespace geocomp::compare {

/// `v` printed with the printf format `f` (default %.4g).
std::string format_number(double v, const char *f = "%.4g");
/// Writes `text` to `p`; throws std::runtime_error naming the file when it cannot.
void write_text_file(const std::filesystem::path &p, const std::string &text);
/// The `name<TAB>value` lines of a run summary; throws naming the file when it cannot be read.
std::map<std::string, std::string> read_run_summary(const std::filesystem::path &path);

} // namespace geocomp::compare
