// The shear-box report (compare/ShearBoxReport.h): runs read back from a results folder
// as `geocomp shear-box` writes them, S4's Fig. 7 series grouped by what differs, and the
// report folder with Fig. 5 and Fig. 7 drawn by gnuplot.
#include "common/Subprocess.h"
#include "compare/ShearBoxReport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace geocomp::compare;

namespace {

// A run as the command writes it: a curve whose mu_b rises to `peak` at U = 2 mm, then
// falls to `residual` (held over the last 3 mm), and its summary.
void write_run(const fs::path& dir, const std::string& name, double sigma_kpa, double mu, int seed, double peak,
               double residual)
{
  std::ofstream t(dir / (name + ".tsv"));
  t << "# S4 direct shear test\nU_m\tlid_rise_m\tF_N_N\tF_S_N\tarea_m2\tsigma_z_Pa\ttau_x_Pa\tmu_b\tinertial_number\n";
  for (int k = 0; k <= 9; ++k) {
    const double U = 1e-3 * k;
    const double m = k <= 2 ? peak * k / 2.0 : (k >= 6 ? residual : peak + (residual - peak) * (k - 2) / 4.0);
    t << U << '\t' << -1e-5 * k + 2e-5 * k * k / 9.0 << "\t1\t1\t1\t" << sigma_kpa * 1e3 << '\t' << m * sigma_kpa * 1e3
      << '\t' << m << "\t8e-4\n";
  }
  std::ofstream s(dir / (name + "-summary.txt"));
  s << "case\tcases/" << name << ".prm\nnormal_stress_kPa\t" << sigma_kpa << "\ncontact_friction\t" << mu << "\nseed\t"
    << seed << "\nbox_length_m\t0.06\nshear_speed_m_s\t0.05\nclumps\t300\nvoid_ratio_at_shear_start\t0.66\n"
    << "inertial_number\t8e-4\npeak_mu_b\t" << peak << "\nshear_at_peak_mm\t2\nmax_contraction_mm\t0.03\n"
    << "final_dilation_mm\t0.1\nprepare_seconds\t30\nshear_seconds\t14\n";
}

fs::path fresh_dir(const std::string& name)
{
  const fs::path d = fs::temp_directory_path() / ("geocomp-shear-box-report-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(ShearBoxReport, RunsAreReadBackWithTheirCurveAndSummary)
{
  const fs::path d = fresh_dir("read");
  write_run(d, "b", 200, 0.7, 1, 1.5, 1.1);
  write_run(d, "a", 100, 0.7, 1, 1.7, 1.2);
  std::ofstream(d / "lonely.tsv") << "U_m\n0\n";  // no summary: not a run
  const auto runs = read_shear_box_runs(d);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].name, "a");
  EXPECT_DOUBLE_EQ(runs[0].normal_stress, 100e3);
  EXPECT_DOUBLE_EQ(runs[0].box_length, 0.06);
  EXPECT_EQ(runs[0].curve.size(), 10u);
  EXPECT_NEAR(runs[0].residual_mu_b, 1.2, 1e-12);  // the rows with U >= 0.9 U_max
  EXPECT_NEAR(runs[0].max_contraction, 3e-5, 1e-15);
  EXPECT_NEAR(runs[0].seconds, 44.0, 1e-12);
}

TEST(ShearBoxReport, FigureSevenGroupsRunsThatDifferOnlyByTheAbscissaAndAveragesSeeds)
{
  const fs::path d = fresh_dir("groups");
  write_run(d, "s100", 100, 0.7, 1, 1.7, 1.2);
  write_run(d, "s100b", 100, 0.7, 2, 1.5, 1.0);
  write_run(d, "s300", 300, 0.7, 1, 1.3, 1.1);
  write_run(d, "m03", 100, 0.3, 1, 1.2, 0.8);
  const auto runs = read_shear_box_runs(d);
  const auto a = mu_b_against_normal_stress(runs);
  ASSERT_EQ(a.size(), 2u);  // contact mu 0.3 and 0.7
  ASSERT_EQ(a[1].points.size(), 2u);
  EXPECT_DOUBLE_EQ(a[1].points[0].x, 100e3);
  EXPECT_NEAR(a[1].points[0].mean_peak(), 1.6, 1e-12);  // two seeds
  EXPECT_NEAR(a[1].points[0].mean_residual(), 1.1, 1e-12);
  const auto b = mu_b_against_contact_friction(runs);
  ASSERT_EQ(b.size(), 2u);  // 100 and 300 kPa
  ASSERT_EQ(b[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(b[0].points[0].x, 0.3);
  EXPECT_NE(b[0].label.find("100"), std::string::npos);
}

TEST(ShearBoxReport, ReportFolderHoldsTheTableAndBothFiguresDrawnByGnuplot)
{
  const fs::path d = fresh_dir("folder");
  write_run(d, "s100", 100, 0.7, 1, 1.7, 1.2);
  write_run(d, "s300", 300, 0.7, 1, 1.3, 1.1);
  const ShearBoxReportOutcome o = write_shear_box_report(read_shear_box_runs(d), d / "report");
  std::ifstream in(d / "report" / "index.html");
  const std::string html((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(html.find("s300"), std::string::npos);
  EXPECT_NE(html.find("8.00e-04"), std::string::npos);  // the inertial number in the table
  EXPECT_TRUE(fs::exists(d / "report" / "report.gp"));
  if (!geocomp::program_available("gnuplot")) GTEST_SKIP() << "gnuplot not installed";
  EXPECT_TRUE(o.plots_made) << o.message;
  EXPECT_GT(fs::file_size(d / "report" / "fig5.png"), 1000u);
  EXPECT_GT(fs::file_size(d / "report" / "fig7.png"), 1000u);
  const ShearBoxReportOutcome none = write_shear_box_report(read_shear_box_runs(d), d / "report2", "/nonexistent/gnuplot");
  EXPECT_FALSE(none.plots_made);
  EXPECT_NE(none.message.find("gnuplot not found"), std::string::npos);
}
