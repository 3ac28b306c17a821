#pragma once
// Bad input in a case or parameter file: which file, which parameter, what was expected.
// Every reader throws it; the command line turns it into exit code 2 with nothing written.
#include <stdexcept>
#include <string>
#include <utility>

namespace geocomp {

/// Bad input: which file, which parameter, what was expected. Exit code 2.
struct CaseError : std::runtime_error {
  CaseError(std::string file, std::string parameter, const std::string &message)
    : std::runtime_error(file + ": parameter '" + parameter + "': " + message),
      file(std::move(file)), parameter(std::move(parameter)) {}
  std::string file, parameter;
};

} // namespace geocomp
