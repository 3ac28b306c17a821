#pragma once
// A parameter struct written as canonical text: one `section/entry = value` line per entry,
// in the struct's own order, numbers with 17 significant digits so that the text changes
// exactly when a value does.
//
// Why it exists: a prepared DEM specimen is reused only when every entry it depends on is
// unchanged, and a results file should say with which values it was made. Both read the
// same text, so provenance and reuse are one thing. Each parameter struct lists its entries
// once, in a `visit(struct, visitor)` beside its fields; this class is the visitor that
// writes them (tests use another that changes them one at a time).
#include <string>
#include <utility>
#include <vector>

namespace geocomp {

class CanonicalText
{
public:
  /// Lines are written as `<section>/<entry> = <value>` (`<entry> = <value>` at the top level).
  explicit CanonicalText(std::string section) : section_(std::move(section)) {}

  void operator()(const char *entry, const std::string &value);
  void operator()(const char *entry, double value);
  void operator()(const char *entry, bool value);
  void operator()(const char *entry, unsigned int value) { integer(entry, value); }
  void operator()(const char *entry, unsigned long long value) { integer(entry, value); }
  void operator()(const char *entry, const std::vector<double> &values);
  void operator()(const char *entry, const std::vector<std::string> &values);
  /// A piecewise-linear table: `kappa:value, kappa:value`.
  void operator()(const char *entry, const std::vector<std::pair<double, double>> &points);

  /// Start another section (subsections as `continuum/nikolaevsky`).
  void section(std::string name) { section_ = std::move(name); }
  const std::string &text() const { return text_; }

private:
  void integer(const char *entry, unsigned long long value);
  void line(const char *entry, const std::string &value);
  std::string section_, text_;
};

/// A double as the shortest text that reads back to the same bits (at most 17 digits).
std::string canonical_number(double value);

} // namespace geocomp
