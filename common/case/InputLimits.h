#pragma once
// How much a parameter file may hold: the bounds that keep a hostile or mistaken input
// from exhausting memory, the stack or the patience of whoever reads the report.
//
// Why one header: the reader of a case (and of the crush, rate-sweep and shear-box
// files) checks each bound in a different place - opening the file, expanding its
// `include` lines, converting JSON - and the numbers belong together, with the reason for
// each, so that docs/case-files.md and the messages can quote them from one place.
#include <cstddef>

namespace geocomp::input_limits {

/// A parameter file, and a case with everything it includes: 1 MiB. The largest shipped
/// case is under 4 KB; a packing belongs in a text or store file, not in the case.
constexpr std::size_t max_file_bytes = std::size_t(1) << 20;

/// One logical line (continuation lines joined), hence one value: 8 KiB. Room for a path
/// of PATH_MAX bytes or a long hardening table; a title cannot swell a report.
constexpr std::size_t max_line_bytes = 8192;

/// `include` statements nested more deeply than this are refused; a file that includes
/// one of the files that include it is refused at once, whatever the depth.
constexpr unsigned int max_include_depth = 8;

/// Subsections nested more deeply in a .prm case are refused: the deepest declared one is
/// four levels down; the bound keeps the reader's bookkeeping small whatever a file holds.
constexpr unsigned int max_section_depth = 32;

/// Objects nested more deeply in a JSON case: the deepest case section is four levels
/// (program / stage 1 / ...), so 32 leaves room while bounding the parser's work.
constexpr unsigned int max_json_depth = 32;

} // namespace geocomp::input_limits
