// The elastic limit located by bisection on a material point (issue 32 item 2): a hardening
// Mohr-Coulomb point (constant E, nu, phi, psi; cohesion rising linearly with the plastic
// strain, so the residual after unloading grows continuously past yield) in S0's isochoric
// shear. The residual as a function of the branch's start strain is measured independently
// by a second run with planned branches on a fine grid; the located bracket must hold the
// grid's crossing of 1 %, be narrower than the tolerance, and the metrics and the report
// must give it as the elastic limit.
#include "common/ProgramRunner.h"
#include "compare/Metrics.h"
#include "compare/Report.h"
#include "continuum/driver/MaterialPointEngine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace geocomp;
using namespace geocomp::compare;
namespace fs = std::filesystem;

namespace {

const double p0 = 1e5, c0 = 20e3;

continuum::MaterialParameters hardening_point()
{
  continuum::MaterialParameters m;
  m.mohr_coulomb.youngs_modulus = 100e6;
  m.mohr_coulomb.poisson_ratio = 0.25;
  m.mohr_coulomb.cohesion = continuum::PiecewiseLinear({0.0, 0.2}, {c0, 5.0 * c0});
  m.mohr_coulomb.friction_angle = continuum::PiecewiseLinear(30.0 * M_PI / 180.0);
  m.mohr_coulomb.dilatancy_angle = continuum::PiecewiseLinear(0.0);
  return m;
}

/// S0's isochoric shear (lambda = 0) to gamma_max = `stop`, sampled every `interval` seconds
/// (gamma_max grows by about 0.1 `interval`), with branches at `triggers`.
LoadingProgram isochoric(double interval, const std::vector<std::string> &triggers, double stop = 0.045)
{
  LoadingProgram p;
  p.sample_interval = interval;
  Stage s;
  s.name = "isochoric";
  s.isochoric = true;
  s.isochoric_rate = 0.05;
  s.stop_any = {parse_condition("gamma_max >= " + std::to_string(stop), "test")};
  s.max_duration = 100.0;
  for (const std::string &t : triggers)
    s.unload_at.push_back(parse_trigger(t, "test"));
  p.stages = {s};
  p.validate();
  return p;
}

Response run(const LoadingProgram &program)
{
  continuum::MaterialPointParameters mp;
  mp.initial_stress = -p0;
  continuum::MaterialPointEngine engine(hardening_point(), mp);
  return ProgramRunner(program, engine).run();
}

MetricOptions shear()
{
  MetricOptions o;
  o.kind = CurveKind::ShearIsochoric;
  return o;
}

std::string read(const fs::path &p)
{
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

// Samples 0.002 apart in gamma_max and a tolerance of 0.001: the last steps leave the main
// path between samples.
TEST(ElasticLimitBisection, MaterialPointBracketHoldsTheCrossingOfAFineGridOfBranches)
{
  const double tolerance = 1e-3;
  LoadingProgram program = isochoric(0.02, {"gamma_max >= 0.002", "gamma_max >= 0.04"});
  program.stages[0].locate_elastic_limit = true;
  program.stages[0].elastic_limit_tolerance = tolerance;
  const Response located = run(program);
  const MetricSet m = compute_metrics(located, shear());
  ASSERT_EQ(m.elastic_limit_method, "located by bisection");
  const double lo = m.elastic_limit_lower, hi = m.elastic_limit_upper;
  EXPECT_GT(hi - lo, 0.0);
  EXPECT_LE(hi - lo, tolerance);
  EXPECT_DOUBLE_EQ(m.elastic_limit_strain, 0.5 * (lo + hi));
  EXPECT_GT(lo, 0.002); // a real bracket, well inside the planned one
  EXPECT_LT(hi, 0.04);

  // The independent measurement: branches every 2e-4 of gamma_max over the bracket +- 0.002,
  // on a main path sampled ten times finer.
  std::vector<std::string> grid;
  for (double g = lo - 0.002; g < hi + 0.002; g += 2e-4)
    grid.push_back("gamma_max >= " + std::to_string(g));
  const MetricSet fine = compute_metrics(run(isochoric(0.002, grid, hi + 0.0025)), shear());
  ASSERT_EQ(fine.branches.size(), grid.size());
  double crossing = NAN;
  for (std::size_t k = 1; k < fine.branches.size(); ++k) {
    const BranchResidual &a = fine.branches[k - 1], &b = fine.branches[k];
    EXPECT_GT(b.residual, a.residual) << "the residual grows with the start strain";
    if (std::isnan(crossing) && a.residual < 0.01 && b.residual >= 0.01)
      crossing = a.x_start + (0.01 - a.residual) * (b.x_start - a.x_start) / (b.residual - a.residual);
  }
  ASSERT_TRUE(std::isfinite(crossing)) << "the grid does not cross 1 %";
  // Within the grid's own resolution (its path is sampled and sub-stepped differently).
  EXPECT_GE(crossing, lo - 2e-5);
  EXPECT_LE(crossing, hi + 2e-5);
  std::printf("[located] bracket [%.5f, %.5f] %%, grid crossing %.5f %%, %zu branches\n", lo * 100, hi * 100,
              crossing * 100, located.branches.size());

  // The report: the bracket and one row per branch, bisection or planned, also in metrics.json.
  const fs::path dir = fs::temp_directory_path() / ("geocomp-bisection-" + std::to_string(::getpid())) / "report";
  ReportInput in;
  in.responses = {{"material point", located}};
  in.metrics = {{"material point", m}};
  ReportOptions no_plots;
  no_plots.gnuplot = "";
  write_report(in, dir, no_plots);
  const std::string html = read(dir / "index.html"), json = read(dir / "metrics.json");
  EXPECT_NE(html.find("elastic limit bracket gamma_max in [" + format_number(lo * 100) + ", " +
                      format_number(hi * 100) + "] %"),
            std::string::npos);
  std::size_t bisection_rows = 0, planned_rows = 0;
  for (std::size_t at = 0; (at = html.find("<td>bisection</td>", at)) != std::string::npos; ++at)
    ++bisection_rows;
  for (std::size_t at = 0; (at = html.find("<td>planned</td>", at)) != std::string::npos; ++at)
    ++planned_rows;
  EXPECT_EQ(planned_rows, 2u);
  EXPECT_EQ(bisection_rows + planned_rows, located.branches.size());
  EXPECT_NE(json.find("\"elastic_limit_lower_pct\": " + format_number(lo * 100)), std::string::npos);
  EXPECT_NE(json.find("\"placed\": \"bisection\""), std::string::npos);
  fs::remove_all(dir.parent_path());
}

// Branches only in the elastic range: no bracket, no bisection branch, and the metric says
// the limit lies beyond the last branch instead of inventing one.
TEST(ElasticLimitBisection, MaterialPointWithoutACrossingGetsNoBracketAndSaysSo)
{
  LoadingProgram program = isochoric(0.005, {"gamma_max >= 0.0005", "gamma_max >= 0.001"}, 0.01);
  program.stages[0].locate_elastic_limit = true;
  const Response r = run(program);
  EXPECT_EQ(r.branches.size(), 2u);
  const MetricSet m = compute_metrics(r, shear());
  EXPECT_EQ(m.elastic_limit_method, "unloading residual");
  EXPECT_TRUE(std::isnan(m.elastic_limit_strain));
  EXPECT_TRUE(std::isnan(m.elastic_limit_lower));
  EXPECT_TRUE(std::isnan(m.elastic_limit_upper));
  bool said = false;
  for (const std::string &n : m.notes)
    said = said || n.find("beyond the last branch") != std::string::npos;
  EXPECT_TRUE(said);
}
