// `geocomp study` end to end on material-point cases (under a second each): a swept continuum
// entry run over two MPI ranks, the report and its figures, study.json against the metrics
// recomputed here from each case's own results file, reuse on a second run, and refusals
// that write nothing.
#include "common/ResponseFile.h"
#include "compare/Metrics.h"
#include "compare/StudyReport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace geocomp;

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

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("geocomp-study-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

const std::vector<std::string> moduli = {"100e6", "200e6", "400e6"};

/// A material-point case (a second): axial compression to eps_z = -2 % under 2 MPa lateral
/// stress (the default isotropic pressure), the default Mohr-Coulomb continuum.
fs::path write_point_case(const fs::path &dir)
{
  fs::create_directories(dir);
  const fs::path file = dir / "point.prm";
  std::ofstream(file) << "set engines = material-point\n"
                      << "subsection program\n  set sampling interval = 0.002\n  subsection stage 1\n"
                      << "    set x = stress -2e6\n    set y = stress -2e6\n    set z = rate -1\n"
                      << "    set stop when = eps_zz <= -0.02\n    set max duration = 1\n  end\nend\n"
                      << "subsection output\n  set directory = " << (dir / "unused").string()
                      << "\n  set fields = false\nend\n";
  return file;
}

/// A study sweeping the point case's continuum Young's modulus; `entry` is the swept entry.
fs::path write_study(const fs::path &dir, const std::string &entry, const std::string &values)
{
  write_point_case(dir / "cases");
  const fs::path file = dir / "study.prm";
  std::ofstream(file) << "set title = stiffness series\nsubsection study\n  set base case = cases/point.prm\n"
                      << "  set swept entry = " << entry << "\n  set values = " << values << "\n"
                      << "  set output directory = " << (dir / "out").string() << "\nend\n";
  return file;
}

std::string study(const fs::path &file, const fs::path &log, const std::string &mpirun = "")
{
  return mpirun + "'" + std::string(GEOCOMP_EXE) + "' study '" + file.string() + "' > '" + log.string() + "' 2>&1";
}

/// The metrics of a case's results, computed here from its file: the axial curve of z, shortened.
compare::StudySummary recomputed(const fs::path &h5)
{
  compare::MetricOptions options;
  options.kind = compare::CurveKind::AxialLateral;
  options.axial = compare::AxialAxis{2, -1.0};
  const Response r = with_interval_means(read_response(h5));
  compare::StudySummary s;
  s.metrics = compare::compute_metrics(r, options);
  const compare::Curve curve = compare::extract_curve(r, options.kind, -1, options.axial);
  double v_min = 0.0;
  for (double e : curve.eps_v)
    v_min = std::min(v_min, std::exp(e) - 1.0);
  s.v_r_min = v_min;
  s.v_r_final = std::exp(curve.eps_v.back()) - 1.0;
  return s;
}

void expect_same(const nlohmann::json &v, double expected, const std::string &what)
{
  if (!std::isfinite(expected)) {
    EXPECT_TRUE(v.is_null()) << what << ": " << v;
    return;
  }
  ASSERT_TRUE(v.is_number()) << what << ": " << v;
  EXPECT_NEAR(v.get<double>(), expected, 1e-12 * std::abs(expected)) << what;
}
} // namespace

TEST(StudyCommand, RunsEverySweptCaseOverTwoRanksAndItsSummaryEqualsEachCaseOwnMetrics)
{
  Scratch s;
  const fs::path file = write_study(s.dir, "continuum/youngs modulus", "100e6, 200e6, 400e6");
  const std::string mpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -np 2 --oversubscribe ";
  ASSERT_EQ(run(study(file, s.dir / "log1", mpirun)), 0) << read(s.dir / "log1");
  EXPECT_NE(read(s.dir / "log1").find("study: rank 1 case"), std::string::npos) << read(s.dir / "log1");
  const fs::path report = s.dir / "out/report";
  for (const char *f : {"index.html", "study.json", "report.gp", "curves.png", "summary.png"})
    EXPECT_TRUE(fs::exists(report / f)) << f;
  const std::string html = read(report / "index.html"), gp = read(report / "report.gp");
  const nlohmann::json j = nlohmann::json::parse(read(report / "study.json"));
  ASSERT_EQ(j["cases"].size(), moduli.size());
  double previous_secant = 0.0;
  for (std::size_t k = 0; k < moduli.size(); ++k) {
    const std::string name = "point_" + moduli[k], label = "continuum/youngs modulus = " + moduli[k];
    const fs::path folder = s.dir / "out/cases" / name;
    EXPECT_TRUE(fs::exists(folder / (name + ".prm"))) << name;
    EXPECT_NE(html.find("<td>" + name + "</td>"), std::string::npos) << name;
    EXPECT_NE(gp.find("'" + label + "'"), std::string::npos) << label;
    const nlohmann::json &c = j["cases"][k];
    EXPECT_EQ(c["name"], name);
    EXPECT_EQ(c["status"], "complete");
    EXPECT_DOUBLE_EQ(c["x"].get<double>(), std::stod(moduli[k]));
    ASSERT_EQ(c["engines"].size(), 1u);
    const nlohmann::json &e = c["engines"][0];
    EXPECT_EQ(e["engine"], "material point");
    const compare::StudySummary m = recomputed(folder / "material-point.h5");
    expect_same(e["peak_stress_Pa"], m.metrics.peak_stress, name + " peak");
    expect_same(e["secant_modulus_Pa"], m.metrics.secant_modulus, name + " secant");
    expect_same(e["elastic_limit_stress_Pa"], m.metrics.elastic_limit_stress, name + " elastic limit");
    expect_same(e["dilatancy_angle_deg"], m.metrics.dilatancy_angle_deg, name + " dilatancy");
    expect_same(e["V_r_min"], m.v_r_min, name + " V_r min");
    expect_same(e["V_r_final"], m.v_r_final, name + " V_r final");
    // The stiffer the continuum, the stiffer its secant: the sweep changed what it says.
    EXPECT_GT(m.metrics.secant_modulus, previous_secant) << name;
    previous_secant = m.metrics.secant_modulus;
  }
  // Each case file the study wrote runs alone with `geocomp pair`, and finds its results up to date.
  const fs::path first = s.dir / "out/cases/point_100e6/point_100e6.prm";
  ASSERT_EQ(run("'" + std::string(GEOCOMP_EXE) + "' pair '" + first.string() + "' > '" + (s.dir / "log2").string() +
                "' 2>&1"), 0) << read(s.dir / "log2");
  EXPECT_NE(read(s.dir / "log2").find("up-to-date results reused"), std::string::npos) << read(s.dir / "log2");
  // A second run of the study reuses every result.
  const auto before = fs::last_write_time(s.dir / "out/cases/point_400e6/material-point.h5");
  ASSERT_EQ(run(study(file, s.dir / "log3")), 0) << read(s.dir / "log3");
  const std::string log3 = read(s.dir / "log3");
  std::size_t reused = 0;
  for (std::size_t at = log3.find("up-to-date results reused"); at != std::string::npos;
       at = log3.find("up-to-date results reused", at + 1))
    ++reused;
  EXPECT_EQ(reused, moduli.size()) << log3;
  EXPECT_EQ(fs::last_write_time(s.dir / "out/cases/point_400e6/material-point.h5"), before);
}

TEST(StudyCommand, RefusesASweptEntryThatDoesNotExistAndWritesNothing)
{
  Scratch s;
  const fs::path file = write_study(s.dir, "continuum/stiffness", "1, 2");
  EXPECT_EQ(run(study(file, s.dir / "log")), 2);
  const std::string log = read(s.dir / "log");
  EXPECT_NE(log.find("study.prm: parameter 'study/swept entry'"), std::string::npos) << log;
  EXPECT_NE(log.find("continuum/stiffness"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(s.dir / "out"));
}

TEST(StudyCommand, RefusesASweptValueOutOfRangeAndWritesNothing)
{
  Scratch s;
  const fs::path file = write_study(s.dir, "continuum/youngs modulus", "200e6, 10");
  EXPECT_EQ(run(study(file, s.dir / "log")), 2);
  const std::string log = read(s.dir / "log");
  EXPECT_NE(log.find("study.prm: parameter 'study/values'"), std::string::npos) << log;
  EXPECT_NE(log.find("point_10"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(s.dir / "out"));
}

TEST(StudyCommand, RefusesAMissingCaseOfAListAndWritesNothing)
{
  Scratch s;
  write_point_case(s.dir / "cases");
  const fs::path file = s.dir / "list.prm";
  std::ofstream(file) << "subsection study\n  set cases = cases/point.prm, cases/absent.prm\n"
                      << "  set against = continuum/youngs modulus\n"
                      << "  set output directory = " << (s.dir / "out").string() << "\nend\n";
  EXPECT_EQ(run(study(file, s.dir / "log")), 2);
  const std::string log = read(s.dir / "log");
  EXPECT_NE(log.find("parameter 'study/cases'"), std::string::npos) << log;
  EXPECT_NE(log.find("cases/absent.prm"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(s.dir / "out"));
}

TEST(StudyReport, RelativeVolumeChangeIsTheVolumeRatioLessOne)
{
  // S0 Fig. 4b: V_r = V / V_start - 1; eps_v = ln(V / V_start).
  EXPECT_NEAR(compare::relative_volume_change(std::log(0.98)), -0.02, 1e-15);
  EXPECT_NEAR(compare::relative_volume_change(std::log(1.05)), 0.05, 1e-15);
  EXPECT_EQ(compare::relative_volume_change(0.0), 0.0);
}

TEST(StudyCommand, ShipsStudiesWhoseEveryCaseIsValid)
{
  const fs::path root = std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : ".";
  Scratch s;
  std::size_t studies = 0;
  for (const auto &e : fs::directory_iterator(root / "cases/studies")) {
    if (e.path().filename().string().rfind("s0_store_program", 0) == 0)
      continue; // a fragment the store studies include, not a study
    ++studies;
    const fs::path log = s.dir / (e.path().stem().string() + ".log");
    EXPECT_EQ(run("'" + std::string(GEOCOMP_EXE) + "' study --check '" + e.path().string() + "' > '" + log.string() +
                  "' 2>&1"), 0) << read(log);
  }
  EXPECT_GE(studies, 5u);
  // Fig. 4: the five friction cases, against mu_s = tan phi.
  const fs::path log = s.dir / "s0_fig4.log";
  for (const char *phi : {"0", "15", "30", "45", "60"})
    EXPECT_NE(read(log).find(std::string("s0_lateral_pressure_phi") + phi + "_n3000: contact/particle friction = "),
              std::string::npos) << read(log);
}
