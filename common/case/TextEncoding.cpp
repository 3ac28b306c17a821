// See TextEncoding.h: UTF-8 checked with Boost.Locale's decoder (header only).
#include "common/case/TextEncoding.h"

#include "common/case/CaseParameters.h"

#include <boost/locale/utf.hpp>

#include <algorithm>

namespace geocomp {

namespace {
/// Offset of the first invalid UTF-8 sequence of `s`, or s.size() when there is none.
std::size_t first_invalid_utf8(const std::string &s)
{
  namespace utf = boost::locale::utf;
  auto it = s.begin();
  while (it != s.end()) {
    const auto start = it;
    const utf::code_point c = utf::utf_traits<char>::decode(it, s.end());
    if (c == utf::illegal || c == utf::incomplete)
      return std::size_t(start - s.begin());
  }
  return s.size();
}

std::size_t line_at(const std::string &s, std::size_t offset)
{
  return 1 + std::size_t(std::count(s.begin(), s.begin() + std::ptrdiff_t(offset), '\n'));
}
} // namespace

bool is_valid_utf8(const std::string &s) { return first_invalid_utf8(s) == s.size(); }

void check_utf8_text(const std::string &text, const std::string &file)
{
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos)
    throw CaseError(file, "(file)",
                    "contains a NUL byte at line " + std::to_string(line_at(text, nul)) + ": expected a text file");
  const std::size_t bad = first_invalid_utf8(text);
  if (bad != text.size())
    throw CaseError(file, "(file)",
                    "line " + std::to_string(line_at(text, bad)) + " is not valid UTF-8: expected UTF-8 text");
}

} // namespace geocomp
