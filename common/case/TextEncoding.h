#pragma once
// A parameter file is UTF-8 text: no NUL byte, no invalid byte sequence.
//
// Why it exists: whatever a case holds travels on - titles and paths into the HDF5
// results, the HTML report and metrics.json, entry values into messages on the terminal.
// A byte sequence that is not UTF-8 makes those files invalid (JSON must be UTF-8) and
// a NUL byte cuts strings short in C interfaces. Refusing such bytes where the file is
// read names the file and the line; nothing downstream has to repair them.
#include <string>

namespace geocomp {

/// Throws CaseError(file, "(file)", ...) naming the line of the first NUL byte or invalid
/// UTF-8 sequence (overlong forms, surrogates and code points above U+10FFFF included).
void check_utf8_text(const std::string &text, const std::string &file);

/// True when `s` is valid UTF-8 (for strings that do not come from a file: paths on the
/// command line, names read from results files).
bool is_valid_utf8(const std::string &s);

} // namespace geocomp
