// `geocomp material-point` on a program the material cannot follow (issue 29): a stress axis
// driven into tension past the Mohr-Coulomb apex has no solution and no kinematic axis to
// hand to plastic-strain control, so the run stops with exit 1, says why, and leaves a
// readable results file with the samples so far and /meta/status saying where and why.
#include "common/ResponseFile.h"
#include "tests/common/CommandRun.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(ContinuumFailure, AMaterialPointBeyondItsStrengthLeavesItsSamplesAndStatus)
{
  const fs::path dir = fs::temp_directory_path() / ("geocomp-point-failure-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path c = dir / "apex.prm";
  std::ofstream(c) << "set engines = material-point\n"
                      "subsection specimen\n  set isotropic pressure = 1e5\nend\n"
                      "subsection continuum\n  set cohesion = 0:10e3\n  set friction angle = 0:30\n"
                      "  set dilatancy angle = 0:0\nend\n"
                      "subsection program\n  set sampling interval = 0.1\n  subsection stage 1\n"
                      "    set x = stress -1e5\n    set y = stress -1e5\n    set z = stress 1e6\n"
                      "    set stop when = stage_time >= 2\n    set max duration = 4\n  end\nend\n"
                      "subsection output\n  set directory = "
                   << (dir / "out").string() << "\n  set report = false\nend\n";
  const auto r = geocomp::test::run_program({GEOCOMP_EXE, "material-point", c.string()}, {}, 120.0);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("did not converge"), std::string::npos) << r.err;
  geocomp::RunMeta meta;
  const geocomp::Response q = geocomp::read_response(dir / "out/material-point.h5", &meta);
  EXPECT_EQ(meta.status.rfind("failed", 0), 0u) << meta.status;
  EXPECT_NE(meta.status.find("did not converge"), std::string::npos) << meta.status;
  EXPECT_EQ(meta.kinematics, "finite strain");
  ASSERT_GE(q.samples.size(), 1u);
  EXPECT_NEAR(q.samples.front().stress(0, 0), -1e5, 1e-6);
  fs::remove_all(dir);
}
