// The whole text of a file a test wrote or a program under test wrote ("" when it is missing),
// for tests that look for strings in reports, scripts and logs.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace geocomp::test {

inline std::string file_text(const std::filesystem::path &file)
{
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

} // namespace geocomp::test
