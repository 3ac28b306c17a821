#include "common/case/CanonicalText.h"

#include <cstdio>
#include <cstdlib>

namespace geocomp {

std::string canonical_number(double value)
{
  char buffer[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value)
      break;
  }
  return buffer;
}

void CanonicalText::line(const char *entry, const std::string &value)
{
  if (!section_.empty()) {
    text_ += section_;
    text_ += '/';
  }
  text_ += entry;
  text_ += " = ";
  text_ += value;
  text_ += '\n';
}

void CanonicalText::operator()(const char *entry, const std::string &value) { line(entry, value); }
void CanonicalText::operator()(const char *entry, double value) { line(entry, canonical_number(value)); }
void CanonicalText::operator()(const char *entry, bool value) { line(entry, value ? "true" : "false"); }
void CanonicalText::integer(const char *entry, unsigned long long value) { line(entry, std::to_string(value)); }

void CanonicalText::operator()(const char *entry, const std::vector<double> &values)
{
  std::string s;
  for (std::size_t k = 0; k < values.size(); ++k)
    s += (k ? ", " : "") + canonical_number(values[k]);
  line(entry, s);
}

void CanonicalText::operator()(const char *entry, const std::vector<std::string> &values)
{
  std::string s;
  for (std::size_t k = 0; k < values.size(); ++k)
    s += (k ? ", " : "") + values[k];
  line(entry, s);
}

void CanonicalText::operator()(const char *entry, const std::vector<std::pair<double, double>> &points)
{
  std::string s;
  for (std::size_t k = 0; k < points.size(); ++k)
    s += (k ? ", " : "") + canonical_number(points[k].first) + ":" + canonical_number(points[k].second);
  line(entry, s);
}

} // namespace geocomp
