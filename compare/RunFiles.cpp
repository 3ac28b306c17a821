#include "compare/RunFiles.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace geocomp::compare {

std::string format_number(double v, const char *f)
{
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

void write_text_file(const std::filesystem::path &p, const std::string &text)
{
  std::ofstream out(p);
  out << text;
  if (!out)
    throw std::runtime_error("cannot write " + p.string());
}

std::map<std::string, std::string> read_run_summary(const std::filesystem::path &path)
{
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(path.string() + ": cannot read the run summary");
  std::map<std::string, std::string> kv;
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos)
      kv[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return kv;
}

} // namespace geocomp::compare
