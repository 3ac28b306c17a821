#pragma once
// A parameter file's text as deal.II's ParameterHandler is given it: every `include` line
// replaced by the text of the file it names, with a map back to where each line came from.
//
// Why it exists: ParameterHandler opens included files itself, with no depth limit and no
// cycle check (a case that includes itself overflows the stack), with std::ifstream (a
// FIFO blocks, /dev/zero never ends), and with no bound on what it reads. Here each
// included file is read by read_input_file() and checked like the file itself (UTF-8, line
// length), nesting is limited to input_limits::max_include_depth, a file that includes one
// of its includers is refused, and the whole text is bounded by input_limits::max_file_bytes.
// deal.II's own rules are kept: an include line is a logical line (continuations joined,
// comment and tabs removed) starting with "include " or "INCLUDE "; an included file must
// close every subsection it opens. One rule differs: a relative path is taken relative to
// the folder of the file that holds the include line (deal.II takes the working
// directory), so that a case and the files it includes work from any folder. What ParameterHandler then reads holds no include line, so it
// never opens a file; its messages give lines of the expanded text, which where() maps
// back to the file and line the user wrote.
#include <string>
#include <vector>

namespace geocomp {

struct ParameterText {
  std::string text;                ///< the expanded text: no include line left
  std::vector<std::string> files;  ///< [0] the file itself, then each included file as named
  /// Where a line of `text` came from, and the subsection path it sits in.
  struct Origin {
    unsigned int file = 0;         ///< index into `files`
    unsigned int line = 0;         ///< 1-based line in that file
    unsigned int section = 0;      ///< index into `sections`
  };
  std::vector<Origin> lines;       ///< one per line of `text`
  /// The subsections entered, each once however often it is entered: its name and the
  /// index of the subsection it sits in. [0] is the top level (no name, its own parent).
  struct Section {
    unsigned int parent = 0;
    std::string name;
  };
  std::vector<Section> sections{Section{}};

  /// "line 12" for a line of the file itself, "line 3 of <included file>" otherwise;
  /// `line` is 1-based in `text`.
  std::string where(unsigned int line) const;
  /// The subsection path ("program/stage 1/", or "") at the start of 1-based `line`.
  std::string section_at(unsigned int line) const;
  /// The path of a section ("program/stage 1/"; "" for the top level).
  std::string path_of(unsigned int section) const;
  /// The statement deal.II reads from the logical line that starts at 1-based `line`:
  /// continuations joined, the comment removed, tabs as spaces, trimmed.
  std::string statement_at(unsigned int line) const;
};

/// Expands the include lines of `text` (read from `path`, which names it in messages).
/// Throws CaseError naming `path` (and the included file concerned) for text that is not
/// UTF-8 or holds a NUL byte, a logical line longer than input_limits::max_line_bytes,
/// subsections nested deeper than input_limits::max_section_depth,
/// an included file that cannot be read (read_input_file), includes nested too deeply or
/// in a cycle, an included file with unbalanced subsections, and an expanded text larger
/// than input_limits::max_file_bytes.
ParameterText expand_parameter_text(const std::string &text, const std::string &path);

} // namespace geocomp
