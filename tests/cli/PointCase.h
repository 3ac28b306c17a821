// A material-point case that runs in under a second (a few hundred samples of axial
// compression under 0.2 MPa lateral stress), written for the command-line tests that need a
// quick real run; its results go to `output`.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace geocomp::test {

inline std::filesystem::path write_point_case(const std::filesystem::path &dir, const std::string &output)
{
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "point.prm";
  std::ofstream(file) << "set engines = material-point\n"
                      << "subsection program\n  set sampling interval = 0.002\n  subsection stage 1\n"
                      << "    set x = stress -2e5\n    set y = stress -2e5\n    set z = rate -1\n"
                      << "    set stop when = eps_zz <= -0.02\n    set max duration = 1\n  end\nend\n"
                      << "subsection output\n  set directory = " << output << "\n  set fields = false\nend\n";
  return file;
}

} // namespace geocomp::test
