#include "compare/HtmlString.h"

namespace geocomp::compare {

std::string html_text(const std::string &s)
{
  std::string out;
  for (char c : s)
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  return out;
}

} // namespace geocomp::compare
