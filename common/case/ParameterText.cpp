// See ParameterText.h: include lines expanded under limits, deal.II's line rules kept.
#include "common/case/ParameterText.h"

#include "common/case/CaseParameters.h"
#include "common/case/InputFile.h"
#include "common/case/InputLimits.h"
#include "common/case/TextEncoding.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <utility>

namespace geocomp {

namespace {
using namespace input_limits;

std::string trim(const std::string &s)
{
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  const auto b = std::find_if_not(s.begin(), s.end(), space);
  const auto e = std::find_if_not(s.rbegin(), s.rend(), space).base();
  return b < e ? std::string(b, e) : std::string();
}

bool starts_with(const std::string &s, const char *prefix) { return s.rfind(prefix, 0) == 0; }

/// Lines as std::getline yields them (a final newline ends the last line, it opens none).
std::vector<std::string> physical_lines(const std::string &text)
{
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == std::string::npos ? text.size() : nl;
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

/// The statement ParameterHandler::scan_line sees in a logical line: the comment from the
/// first '#' removed, tabs as spaces, trimmed.
std::string statement_of(std::string line)
{
  const auto hash = line.find('#');
  if (hash != std::string::npos)
    line.erase(hash);
  std::replace(line.begin(), line.end(), '\t', ' ');
  return trim(line);
}

/// A file's identity, to recognise it under another name.
struct FileId {
  dev_t device = 0;
  ino_t inode = 0;
  bool operator==(const FileId &o) const { return device == o.device && inode == o.inode; }
};

bool identify(const std::string &path, FileId &id)
{
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return false;
  id = {st.st_dev, st.st_ino};
  return true;
}

/// CaseError's message without its "file: parameter '...': " prefix.
std::string message_of(const CaseError &e)
{
  const std::string prefix = e.file + ": parameter '" + e.parameter + "': ";
  const std::string what = e.what();
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

/// Walks a file's logical lines, copies them to the output with their origins, and puts
/// the text of each included file in place of its include line.
class Expander {
public:
  Expander(ParameterText &out, std::string path) : out_(out), path_(std::move(path)) {}

  /// `text` is files[file]'s content; `chain` the identities of the files including it.
  void expand(const std::string &text, unsigned int file, unsigned int depth, std::vector<FileId> &chain)
  {
    check_utf8_text(text, out_.files[file]);
    const std::vector<std::string> lines = physical_lines(text);
    const std::size_t depth_at_entry = stack_.size();
    std::string joined;
    std::size_t first = 0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      // Continuation as deal.II's parse_input: a trimmed line ending in '\' goes on.
      std::string piece = trim(lines[k]);
      const bool continued = !piece.empty() && piece.back() == '\\';
      if (continued)
        piece.pop_back();
      joined += piece;
      if (joined.size() > max_line_bytes)
        fail_long_line(file, first, joined);
      if (continued && k + 1 < lines.size())
        continue;
      logical_line(lines, first, k, statement_of(joined), file, depth, chain, continued);
      joined.clear();
      first = k + 1;
    }
    if (file != 0 && stack_.size() != depth_at_entry)
      throw CaseError(path_, "(file)",
                      "the included file '" + out_.files[file] +
                        "' does not close every subsection it opens (unequal numbers of 'subsection' and 'end'): "
                        "expected an included file to be complete in itself");
  }

private:
  ParameterText &out_;
  std::string path_;
  std::vector<unsigned int> stack_;  ///< the sections entered, innermost last
  unsigned int section_ = 0;         ///< the innermost, 0 at the top level
  std::map<std::pair<unsigned int, std::string>, unsigned int> children_; ///< (parent, name) -> section

  std::string where(unsigned int file, std::size_t line) const
  {
    return "line " + std::to_string(line + 1) + (file == 0 ? "" : " of '" + out_.files[file] + "'");
  }

  [[noreturn]] void fail_long_line(unsigned int file, std::size_t first, const std::string &joined) const
  {
    std::string parameter = "(file)";
    const std::string s = statement_of(joined.substr(0, 1024));
    if ((starts_with(s, "set ") || starts_with(s, "SET ")) && s.find('=') != std::string::npos)
      parameter = out_.path_of(section_) + trim(s.substr(4, s.find('=') - 4));
    throw CaseError(path_, parameter,
                    where(file, first) + " is longer than " + std::to_string(max_line_bytes) +
                      " characters: expected shorter values (a packing or a table this long belongs in its own file)");
  }

  void emit(const std::string &line, unsigned int file, std::size_t number)
  {
    out_.text += line;
    out_.text += '\n';
    out_.lines.push_back({file, static_cast<unsigned int>(number + 1), section_});
    if (out_.text.size() > max_file_bytes)
      throw CaseError(path_, "(file)",
                      "with the files it includes, holds more than " + std::to_string(max_file_bytes >> 20) +
                        " MiB: expected a smaller case");
  }

  /// A subsection entered: the section (parent, name), made the first time it is entered.
  void enter(const std::string &name, unsigned int file, std::size_t line)
  {
    if (stack_.size() >= max_section_depth)
      throw CaseError(path_, "(file)",
                      where(file, line) + ": subsections nested more than " + std::to_string(max_section_depth) +
                        " deep: expected the sections of a case file");
    const auto key = std::make_pair(section_, name);
    auto it = children_.find(key);
    if (it == children_.end()) {
      out_.sections.push_back({section_, name});
      it = children_.emplace(key, static_cast<unsigned int>(out_.sections.size() - 1)).first;
    }
    stack_.push_back(it->second);
    section_ = it->second;
  }

  void leave()
  {
    stack_.pop_back();
    section_ = stack_.empty() ? 0 : stack_.back();
  }

  /// Physical lines first..last of one file form one logical line whose statement is `s`.
  void logical_line(const std::vector<std::string> &lines, std::size_t first, std::size_t last, const std::string &s,
                    unsigned int file, unsigned int depth, std::vector<FileId> &chain, bool dangling)
  {
    // "include" alone names no file: deal.II says so, without opening anything.
    if (starts_with(s, "include ") || starts_with(s, "INCLUDE ")) {
      include(trim(s.substr(8)), file, first, depth + 1, chain);
      return;
    }
    for (std::size_t k = first; k <= last; ++k) {
      // A file's last line that ends in '\' is parsed alone by deal.II; expanded, it must
      // not run on into the including file's next line.
      std::string line = lines[k];
      if (dangling && k == last && file != 0)
        line = trim(line).substr(0, trim(line).size() - 1);
      emit(line, file, k);
    }
    if (starts_with(s, "subsection ") || starts_with(s, "SUBSECTION "))
      enter(trim(s.substr(11)), file, first);
    else if ((starts_with(s, "end") || starts_with(s, "END")) && trim(s.substr(3)).empty() && !stack_.empty())
      leave();
  }

  void include(const std::string &written, unsigned int file, std::size_t line, unsigned int depth,
               std::vector<FileId> &chain)
  {
    // Relative to the folder of the file that holds the include line, so that a case and
    // what it includes can be moved together and run from any folder.
    const std::filesystem::path folder = std::filesystem::path(out_.files[file]).parent_path();
    const std::string name = std::filesystem::path(written).is_absolute() || folder.empty()
                               ? written
                               : (folder / written).lexically_normal().string();
    const std::string site = where(file, line) + " includes '" + name + "'";
    if (depth > max_include_depth)
      throw CaseError(path_, "(file)",
                      site + ": includes nested more than " + std::to_string(max_include_depth) +
                        " deep: expected fewer levels of include");
    FileId id;
    if (identify(name, id) && std::find(chain.begin(), chain.end(), id) != chain.end())
      throw CaseError(path_, "(file)", site + ", which includes it (directly or through other files): "
                                              "expected includes without a cycle");
    out_.files.push_back(name);
    const unsigned int index = static_cast<unsigned int>(out_.files.size() - 1);
    try {
      const std::string text = read_input_file(name, "parameter file to include", max_file_bytes);
      chain.push_back(id);
      expand(text, index, depth, chain);
      chain.pop_back();
    } catch (const CaseError &e) {
      if (e.file == path_)
        throw;
      throw CaseError(path_, e.parameter, site + ": " + message_of(e));
    }
  }
};
} // namespace

std::string ParameterText::where(unsigned int line) const
{
  if (line == 0 || line > lines.size())
    return "line " + std::to_string(line);
  const Origin &o = lines[line - 1];
  return "line " + std::to_string(o.line) + (o.file == 0 ? "" : " of '" + files[o.file] + "'");
}

std::string ParameterText::section_at(unsigned int line) const
{
  if (line == 0 || line > lines.size())
    return "";
  return path_of(lines[line - 1].section);
}

std::string ParameterText::path_of(unsigned int section) const
{
  std::string path;
  for (unsigned int s = section; s != 0; s = sections[s].parent)
    path.insert(0, sections[s].name + "/");
  return path;
}

std::string ParameterText::statement_at(unsigned int line) const
{
  std::size_t at = 0;
  for (unsigned int k = 1; k < line && at != std::string::npos; ++k) {
    const std::size_t nl = text.find('\n', at);
    at = nl == std::string::npos ? nl : nl + 1;
  }
  std::string joined;
  while (at != std::string::npos && at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string piece = trim(text.substr(at, end - at));
    const bool continued = !piece.empty() && piece.back() == '\\';
    joined += continued ? piece.substr(0, piece.size() - 1) : piece;
    if (!continued)
      break;
    at = end + 1;
  }
  return statement_of(joined);
}

ParameterText expand_parameter_text(const std::string &text, const std::string &path)
{
  ParameterText out;
  out.files.push_back(path);
  if (text.size() > input_limits::max_file_bytes)
    throw CaseError(path, "(file)", "holds more than " + std::to_string(input_limits::max_file_bytes >> 20) +
                                      " MiB: expected a smaller case");
  std::vector<FileId> chain;
  FileId self;
  if (identify(path, self))
    chain.push_back(self);
  Expander(out, path).expand(text, 0, 0, chain);
  return out;
}

} // namespace geocomp
