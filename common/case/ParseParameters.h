#pragma once
// Reading a parameter file and parsing its text with deal.II's ParameterHandler, bad
// input reported as one CaseError (file, parameter, expectation; exit code 2).
//
// Why a function of its own: every command with a parameter file (the case file, and
// rate-sweep, crush and shear-box with their own sections) reads it the same way, and
// deal.II's exception text (library file and line, stack trace) is not for users. This
// keeps the line number and names the entry with its section path, e.g. 'loading/mode'.
// Every file goes through the same guards (InputFile.h, TextEncoding.h, ParameterText.h):
// a regular file of at most 1 MiB, UTF-8, bounded lines, includes expanded under limits.
#include "common/case/CaseParameters.h"
#include "common/case/ParameterText.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace geocomp {

/// The whole text of a parameter file: a regular file of at most input_limits::max_file_bytes
/// (read_input_file), UTF-8 without NUL bytes. Throws CaseError(path, "(file)", ...)
/// otherwise, "cannot be read: expected a readable " + `kind` when it cannot be opened.
std::string read_parameter_file(const std::string &path, const std::string &kind);

/// Parses `text` (.prm syntax, read from `path`) into `prm`, whose entries are declared,
/// its include lines expanded first (expand_parameter_text). Throws CaseError naming
/// `path`, the entry (with its section path) and what was expected.
void parse_parameter_text(dealii::ParameterHandler &prm, const std::string &text, const std::string &path);
/// The same for a text already expanded.
void parse_parameter_text(dealii::ParameterHandler &prm, const ParameterText &text, const std::string &path);

/// The CaseError for a deal.II exception raised while reading `text` (as `path`) into a
/// ParameterHandler or reading values back from it; lines are those the user wrote.
CaseError parameter_error(const dealii::ExceptionBase &e, const ParameterText &text, const std::string &path);

} // namespace geocomp
