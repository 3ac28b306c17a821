// `geocomp calibrate` end to end: a material-point target with known parameters, a case
// whose continuum section is off, the calibrated section written, verified on the deal.II
// cube, and pulled into another case file with deal.II's `include`.
#include "compare/case/CaseDescription.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {
int run(const std::string &cmd)
{
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const fs::path &p)
{
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Axial compression at 200 kPa lateral pressure to 4 %, two-cell-per-edge cube for --verify.
std::string axial_case(const fs::path &output, double E, double nu, double phi_peak)
{
  std::ostringstream o;
  o << "set engines = material-point\n"
    << "subsection specimen\n  set isotropic pressure = 2e5\nend\n"
    << "subsection continuum\n  set model = mohr-coulomb\n  set youngs modulus = " << E
    << "\n  set poisson ratio = " << nu << "\n  set cohesion = 0:30e3\n"
    << "  set friction angle = 0:20, 0.02:" << phi_peak << ", 0.08:27\n  set dilatancy angle = 0:0, 0.02:8\n"
    << "  set cells per edge = 2\n  set point substeps per sample = 10\nend\n"
    << "subsection program\n  set sampling interval = 0.002\n  subsection stage 1\n"
    << "    set x = stress -2e5\n    set y = stress -2e5\n    set z = rate -1\n"
    << "    set stop when = eps_zz <= -0.04\n    set max duration = 1\n  end\nend\n"
    << "subsection output\n  set directory = " << output.string() << "\n  set fields = false\nend\n";
  return o.str();
}

double number_after(const std::string &text, const std::string &key)
{
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(key + "\\s*[=:]\\s*([-+0-9.eE]+)")))
    return std::nan("");
  return std::stod(m[1]);
}
} // namespace

TEST(CalibrateCommand, WritesAnIncludableSectionAndVerifiesItOnTheCube)
{
  const fs::path dir = fs::temp_directory_path() / ("geocomp-calibrate-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string exe = std::string("'") + GEOCOMP_EXE + "' ";

  // The target: the material point with E = 80 MPa, nu = 0.3, phi peak 32 deg.
  std::ofstream(dir / "target.prm") << axial_case(dir / "target", 80e6, 0.3, 32.0);
  ASSERT_EQ(run(exe + "material-point '" + (dir / "target.prm").string() + "' > '" + (dir / "o1").string() + "' 2>&1"), 0)
    << read(dir / "o1");

  // The same test with E, nu and the peak friction off, calibrated back and verified.
  std::ofstream(dir / "cal.prm") << axial_case(dir / "cal", 110e6, 0.22, 27.0) << "subsection calibration\n"
                                 << "  set targets = " << (dir / "target/material-point.h5").string() << "\n"
                                 << "  set free parameters = E, nu, friction[1]\n"
                                 << "  set quantities = q, eps_v:2\n  set starting values = case\nend\n";
  ASSERT_EQ(run(exe + "calibrate '" + (dir / "cal.prm").string() + "' --verify > '" + (dir / "o2").string() + "' 2>&1"), 0)
    << read(dir / "o2");
  const fs::path out = dir / "cal/calibration";
  const std::string fragment = read(out / "calibrated.prm");
  EXPECT_NEAR(number_after(fragment, "set youngs modulus") / 80e6, 1.0, 1e-6) << fragment;
  EXPECT_NEAR(number_after(fragment, "set poisson ratio"), 0.3, 1e-6) << fragment;
  const std::string json = read(out / "fit.json");
  EXPECT_NE(json.find("\"name\": \"eps_v\", \"weight\": 2"), std::string::npos) << json;
  // The cube (its own load steps and Newton tolerance) follows the material point to 1 % of q.
  const double cube_vs_point = number_after(json, "\"max_q_cube_vs_point\"");
  EXPECT_LT(cube_vs_point, 1e-2) << json;
  EXPECT_TRUE(fs::exists(out / "index.html"));
  EXPECT_NE(read(out / "index.html").find("Verification on the deal.II cube"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "parameters.tsv"));
  for (const auto &e : fs::directory_iterator(dir / "cal"))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path() << " left behind";

  // A case file takes the calibrated section with deal.II's `include` after its own
  // continuum section; the included values win.
  const std::string including = axial_case(dir / "inc", 1e9, 0.1, 40.0) + "include " + (out / "calibrated.prm").string() + "\n";
  std::ofstream(dir / "includes.prm") << including;
  EXPECT_EQ(run(exe + "check '" + (dir / "includes.prm").string() + "' > /dev/null 2>&1"), 0);
  const geocomp::CaseDescription c = geocomp::parse_case(including, (dir / "includes.prm").string());
  EXPECT_NEAR(c.continuum.youngs_modulus / 80e6, 1.0, 1e-6);
  EXPECT_NEAR(c.continuum.friction_angle.points[1].second / 32.0, 1.0, 1e-6);
  fs::remove_all(dir);
}
