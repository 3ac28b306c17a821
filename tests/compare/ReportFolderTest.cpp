// The report folder and what comes from outside: a folder name with shell syntax reaches
// gnuplot untouched (no shell runs), and a title or case name that is not UTF-8 still
// gives a metrics.json that a strict JSON parser reads.
#include "compare/Report.h"
#include "common/Subprocess.h"
#include "Synthetic.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace geocomp::compare;

namespace {
ReportInput one_curve()
{
  geocomp::compare::testing::Backbone b;
  ReportInput in;
  in.case_name = "cases/demo.prm";
  in.responses.push_back({"DEM", geocomp::compare::testing::shear_response(b, 2e-4, 0.0, {0.01}, b.E)});
  MetricOptions o;
  o.kind = CurveKind::ShearIsochoric;
  in.metrics.push_back({"DEM", compute_metrics(in.responses[0].response, o)});
  return in;
}

std::string read(const fs::path &p)
{
  std::stringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

fs::path fresh(const std::string &name)
{
  const fs::path root = fs::temp_directory_path() / ("geocomp-report-folder-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  return root;
}
} // namespace

TEST(ReportFolder, AFolderNamedWithQuotesSpacesDollarParenAndSemicolonGetsItsPlotsAndRunsNothingElse)
{
  if (!geocomp::program_available("gnuplot"))
    GTEST_SKIP() << "gnuplot not installed";
  const fs::path root = fresh("shell");
  const fs::path dir = root / "it's a $(touch pwned1); touch pwned2 `touch pwned3` \"q\"" / "report";
  const ReportOutcome out = write_report(one_curve(), dir);
  EXPECT_TRUE(out.plots_made) << out.message << "\n" << read(dir / "gnuplot.log");
  EXPECT_EQ(out.plots.size(), 3u);
  for (const auto &e : fs::recursive_directory_iterator(root))
    EXPECT_NE(e.path().filename().string().rfind("pwned", 0), 0u) << e.path();
  for (const auto &e : fs::directory_iterator(fs::current_path()))
    EXPECT_NE(e.path().filename().string().rfind("pwned", 0), 0u) << e.path();
  fs::remove_all(root);
}

TEST(ReportFolder, ATitleAndCaseNameThatAreNotUtf8LeaveMetricsJsonValidUtf8)
{
  const fs::path root = fresh("utf8");
  ReportInput in = one_curve();
  in.title = "bad \xff\xfe title \"quoted\"\n";
  in.case_name = "case-\xc0\xaf.prm";
  write_report(in, root / "report", ReportOptions{""});
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(read(root / "report" / "metrics.json")));
  EXPECT_EQ(j["title"], "bad \xef\xbf\xbd\xef\xbf\xbd title \"quoted\"\n");
  EXPECT_EQ(j["case"].get<std::string>().find("\xc0"), std::string::npos);
  fs::remove_all(root);
}
