// See JsonCase.h: JSON to .prm through nlohmann-json's SAX interface, nesting bounded.
#include "common/case/JsonCase.h"

#include "common/case/CaseParameters.h"
#include "common/case/InputLimits.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace geocomp {

namespace {
using json = nlohmann::json;

/// Writes .prm lines as the parser reports the document; stops at the first refusal.
class PrmWriter : public nlohmann::json_sax<json> {
public:
  std::string prm;
  std::optional<CaseError> refusal;

  explicit PrmWriter(std::string path) : path_(std::move(path)) {}

  bool null() override { return refuse(entry(), "null is not a value: expected a string, a number or true/false"); }
  bool boolean(bool v) override { return scalar(v ? "true" : "false"); }
  bool number_integer(number_integer_t v) override { return scalar(std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override { return scalar(std::to_string(v)); }
  bool number_float(number_float_t, const string_t &text) override { return scalar(text); }
  bool string(string_t &v) override { return scalar(v); }
  bool binary(binary_t &) override { return refuse(entry(), "binary values are not case-file syntax"); }

  bool start_object(std::size_t) override
  {
    if (path_keys_.size() >= input_limits::max_json_depth)
      return refuse("(file)", "objects nested more than " + std::to_string(input_limits::max_json_depth) +
                                " deep: expected the sections of a case file");
    if (!started_) {
      started_ = true;
      path_keys_.push_back("");
      return true;
    }
    if (!has_key_)
      return refuse(entry(), "JSON arrays are not case-file syntax: expected objects and values");
    prm += "subsection " + key_ + "\n";
    path_keys_.push_back(key_);
    has_key_ = false;
    return true;
  }

  bool key(string_t &k) override
  {
    has_key_ = false;
    if (k.find_first_not_of(" \t") == std::string::npos || k.find_first_of("\n\r#=") != std::string::npos ||
        k.back() == '\\' || k.size() > input_limits::max_line_bytes)
      return refuse(entry(), "a key must be a name: not empty, at most " + std::to_string(input_limits::max_line_bytes) +
                               " characters, without a newline, '#', '=' or a final '\\'");
    key_ = k;
    has_key_ = true;
    return true;
  }

  bool end_object() override
  {
    path_keys_.pop_back();
    if (!path_keys_.empty())
      prm += "end\n";
    return true;
  }

  bool start_array(std::size_t) override
  {
    return refuse(started_ ? entry() : "(file)", "JSON arrays are not case-file syntax: expected objects and values");
  }
  bool end_array() override { return true; }

  bool parse_error(std::size_t, const std::string &, const nlohmann::detail::exception &e) override
  {
    std::string what = e.what();
    const auto bracket = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
      what = what.substr(bracket + 2);
    return refuse("(file)", "not valid JSON: " + what);
  }

private:
  std::string path_;
  std::vector<std::string> path_keys_; ///< "" for the top-level object, then each section
  std::string key_;
  bool has_key_ = false, started_ = false;

  /// The entry being read, with its section path ("specimen/particles").
  std::string entry() const
  {
    std::string out;
    for (std::size_t k = 1; k < path_keys_.size(); ++k)
      out += path_keys_[k] + "/";
    return has_key_ ? out + key_ : (out.empty() ? "(file)" : out.substr(0, out.size() - 1));
  }

  bool refuse(const std::string &parameter, const std::string &message)
  {
    if (!refusal)
      refusal = CaseError(path_, parameter, message);
    return false;
  }

  bool scalar(const std::string &v)
  {
    if (!started_)
      return refuse("(file)", "expected a JSON object holding the case's sections and entries");
    if (!has_key_)
      return refuse(entry(), "JSON arrays are not case-file syntax: expected objects and values");
    if (v.find_first_of("\n\r#") != std::string::npos || (!v.empty() && v.back() == '\\'))
      return refuse(entry(), "a value must fit on one .prm line: no newline, no '#', no final '\\'");
    if (v.size() > input_limits::max_line_bytes)
      return refuse(entry(), "a value longer than " + std::to_string(input_limits::max_line_bytes) +
                               " characters: expected shorter values");
    prm += "set " + key_ + " = " + v + "\n";
    has_key_ = false;
    return true;
  }
};
} // namespace

std::string json_to_prm(const std::string &text, const std::string &path)
{
  PrmWriter writer(path);
  const bool ok = json::sax_parse(text, &writer);
  if (writer.refusal)
    throw *writer.refusal;
  if (!ok)
    throw CaseError(path, "(file)", "not valid JSON");
  return writer.prm;
}

} // namespace geocomp
