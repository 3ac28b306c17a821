// `geocomp calibrate` end to end: a material-point target with known parameters, a case
// whose continuum section is off, the calibrated section written, verified on the deal.II
// cube, and pulled into another case file with deal.II's `include`; its model ladder's
// criteria recomputed from the written RSS, n and k, and an unknown rung refused.
#include "compare/ModelLadder.h"
#include "compare/case/CaseDescription.h"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(CalibrateCommand, TheLadderWritesEachRungsCriteriaAsTheFormulaGivesThemAndRefusesAnUnknownRung)
{
  const fs::path dir = fs::temp_directory_path() / ("geocomp-ladder-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string exe = std::string("'") + GEOCOMP_EXE + "' ";
  std::ofstream(dir / "target.prm") << axial_case(dir / "target", 80e6, 0.3, 32.0);
  ASSERT_EQ(run(exe + "material-point '" + (dir / "target.prm").string() + "' > '" + (dir / "o1").string() + "' 2>&1"), 0)
    << read(dir / "o1");
  const std::string calibration = "subsection calibration\n  set targets = " +
                                  (dir / "target/material-point.h5").string() +
                                  "\n  set free parameters = E, nu, friction[1]\n  set starting values = case\n";

  // Two rungs: the constant friction cannot follow the hardening and softening of the table.
  std::ofstream(dir / "ladder.prm") << axial_case(dir / "ladder", 110e6, 0.22, 27.0) << calibration
                                    << "  set ladder = mohr-coulomb constant, mohr-coulomb tables\nend\n";
  ASSERT_EQ(run(exe + "calibrate '" + (dir / "ladder.prm").string() + "' > '" + (dir / "o2").string() + "' 2>&1"), 0)
    << read(dir / "o2");
  EXPECT_NE(read(dir / "o2").find("model ladder"), std::string::npos) << read(dir / "o2");
  const std::vector<geocomp::compare::LadderRung> rungs =
    geocomp::compare::ladder_from_fit_json(read(dir / "ladder/calibration/fit.json"));
  ASSERT_EQ(rungs.size(), 2u);
  EXPECT_EQ(rungs[0].name, "mohr-coulomb constant");
  EXPECT_EQ(rungs[1].name, "mohr-coulomb tables");
  double best_aic = INFINITY, best_bic = INFINITY;
  for (const auto &r : rungs) {
    ASSERT_TRUE(r.failure.empty()) << r.failure;
    EXPECT_EQ(r.k, 3u) << r.name; // E, nu and one friction value (constant) or knot (tables)
    ASSERT_GT(r.rss, 0.0) << r.name;
    const double aic = double(r.n) * std::log(r.rss / double(r.n)) + 2.0 * double(r.k);
    const double bic = double(r.n) * std::log(r.rss / double(r.n)) + double(r.k) * std::log(double(r.n));
    EXPECT_NEAR(r.aic, aic, 1e-12 * std::abs(aic)) << r.name;
    EXPECT_NEAR(r.bic, bic, 1e-12 * std::abs(bic)) << r.name;
    best_aic = std::min(best_aic, aic);
    best_bic = std::min(best_bic, bic);
  }
  for (const auto &r : rungs) {
    EXPECT_NEAR(r.delta_aic, r.aic - best_aic, 1e-9 * std::abs(best_aic)) << r.name;
    EXPECT_NEAR(r.delta_bic, r.bic - best_bic, 1e-9 * std::abs(best_bic)) << r.name;
  }
  EXPECT_LT(rungs[1].rss, rungs[0].rss) << "the tables made the target";
  EXPECT_NE(read(dir / "ladder/calibration/index.html").find("Model ladder"), std::string::npos);

  // An unknown rung: exit 2 naming the entry, nothing written.
  std::ofstream(dir / "bad.prm") << axial_case(dir / "bad", 110e6, 0.22, 27.0) << calibration
                                 << "  set ladder = mohr-coulomb constant, cam-clay\nend\n";
  EXPECT_EQ(run(exe + "calibrate '" + (dir / "bad.prm").string() + "' > '" + (dir / "o3").string() + "' 2>&1"), 2);
  const std::string message = read(dir / "o3");
  EXPECT_NE(message.find("calibration/ladder"), std::string::npos) << message;
  EXPECT_NE(message.find("cam-clay"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "bad")) << "nothing written";
  fs::remove_all(dir);
}
