// The process's peak resident memory, for the benchmarks' memory lines.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

namespace geocomp::bench {

/// Peak resident memory in MB (Linux: VmHWM in /proc/self/status), 0 elsewhere.
inline double peak_resident_mb()
{
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0.0;
}

}  // namespace geocomp::bench
