// See GnuplotString.h.
#include "compare/GnuplotString.h"

namespace geocomp::compare {

std::string gnuplot_quoted(const std::string &text)
{
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "''";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

} // namespace geocomp::compare
