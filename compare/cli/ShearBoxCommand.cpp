// `geocomp shear-box`: S4's direct shear box test of clumped rubble (Yan & Ji 2009).
//
// Why it exists: one command per seed scenario with its own parameter file, like
// `rate-sweep`. The case file and its reader live with the engine
// (dem/program/ShearBoxCase.h: every input declared once, bad input reported as file +
// parameter + expectation, exit 2). Outputs go to temporary names and are renamed when complete:
// <DIR>/<case>.tsv (one row per output step, compression positive) and
// <DIR>/<case>-summary.txt (peak mu_b, max contraction, final dilation, costs).
#include "Commands.h"
#include "Log.h"
#include "OutputFolderLock.h"

#include "common/AtomicFile.h"
#include "compare/ShearBoxReport.h"
#include "dem/program/ShearBoxCase.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace geocomp::cli {

using namespace dealii;

namespace {

// <dir>/report from every run in `dir` (S4's Fig. 5 and 7); false with a message on failure.
bool refresh_report(const std::string& dir)
{
  try {
    const auto runs = compare::read_shear_box_runs(dir);
    if (runs.empty()) {
      log::error("shear-box report: no <case>.tsv with its <case>-summary.txt in " + dir);
      return false;
    }
    const compare::ShearBoxReportOutcome o =
      compare::write_shear_box_report(runs, std::filesystem::path(dir) / "report");
    if (!o.message.empty()) log::warning("shear-box report: " + o.message);
    std::cout << "wrote " << o.dir.string() << "/index.html (" << runs.size() << " runs"
              << (o.plots_made ? ", fig5.png, fig7.png" : "") << ")\n";
    return true;
  } catch (const std::exception& e) {
    log::error(std::string("shear-box report: ") + e.what());
    return false;
  }
}

}  // namespace

Command shear_box_command()
{
  Command c;
  c.name = "shear-box";
  c.summary = "S4 direct shear box of clumped rubble: mu_b, contraction and dilation (S4 eqs. (22)-(24))";
  c.usage = "usage: geocomp shear-box <case.prm> [--output DIR] [--check] [--print-parameters]\n"
            "       geocomp shear-box --report DIR\n\n"
            "Builds S4's split box (bounded walls), fills it with clumps from S4's four templates,\n"
            "grows them to full size, loads the lid to the normal stress (servo) and shears the lower\n"
            "box. Writes <DIR>/<case>.tsv (U, lid rise, F_N, F_S, area, sigma_z, tau_x, mu_b, I;\n"
            "compression positive) and <DIR>/<case>-summary.txt (docs/s4-direct-shear.md), then\n"
            "rewrites <DIR>/report/ (S4 Fig. 5 and Fig. 7, gnuplot) from every run in DIR;\n"
            "--report DIR only rewrites that report.\n"
            "--check only validates the case. Exit 0 ok, 1 run failure, 2 bad input.\n";
  c.run = [](const std::vector<std::string>& args) {
    const Arguments a = Arguments::parse(args, {"output", "report"}, {"check", "print-parameters"});
    if (a.has("report")) {
      if (!a.positional.empty()) throw UsageError("--report DIR takes no case file");
      const std::string dir = a.get("report");
      if (!std::filesystem::is_directory(dir)) {
        log::error("--report: '" + dir + "' is not a folder (expected the --output folder of shear-box runs)");
        return static_cast<int>(bad_input);
      }
      return static_cast<int>(refresh_report(dir) ? ok : run_failure);
    }
    if (a.has("print-parameters")) {
      ParameterHandler prm;
      dem::declare_shear_box_parameters(prm);
      prm.print_parameters(std::cout, ParameterHandler::Text);
      return static_cast<int>(ok);
    }
    if (a.positional.size() != 1) throw UsageError("expected exactly one case file");
    dem::ShearBoxCase sc;
    try {
      sc = dem::read_shear_box_case(a.positional[0]);
    } catch (const CaseError& e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    const double I = 0.1 * sc.p.shear_speed * std::sqrt(sc.p.clumps.density / sc.p.normal_stress);
    if (a.has("check")) {
      std::cout << sc.file << ": ok (sigma_n " << sc.p.normal_stress / 1e3 << " kPa, shear " << sc.p.max_shear * 1e3
                << " mm, I = " << I << ")\n";
      return static_cast<int>(ok);
    }
    const std::string dir = a.get("output", sc.output_directory);
    const std::string stem = std::filesystem::path(sc.file).stem().string();
    // Locked for this run; a path that cannot be a folder is bad input (CaseError: exit 2).
    const OutputFolderLock lock(dir, sc.file, a.has("output") ? "--output" : "output/directory");
    try {
      dem::DirectShearBox box(sc.p);
      std::string last;
      auto progress = [&](const std::string& phase, double) {
        if (phase != last) {
          std::printf("%s ...\n", phase.c_str());
          std::fflush(stdout);
          last = phase;
        }
      };
      box.prepare(progress);
      const auto curve = box.shear(progress);
      const dem::ShearSummary s = box.summary(curve);
      const std::string base = (std::filesystem::path(dir) / stem).string();
      write_atomically(base + ".tsv", [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        out << "# S4 direct shear " << sc.title << "; compression positive; lid_rise > 0 is dilation\n";
        out << "U_m\tlid_rise_m\tF_N_N\tF_S_N\tarea_m2\tsigma_z_Pa\ttau_x_Pa\tmu_b\tinertial_number\ttime_s"
               "\tframe_F_x_N\tbox_F_z_N\tbox_rise_m\tbox_stop_F_z_N\tW_P_N\n";
        char buf[512];
        for (const auto& r : curve) {
          std::snprintf(buf, sizeof buf,
                        "%.6e\t%.6e\t%.6e\t%.6e\t%.6e\t%.6e\t%.6e\t%.6f\t%.3e\t%.6e\t%.6e\t%.6e\t%.6e\t%.6e\t%.6e\n", r.shear,
                        r.lid_rise, r.normal_force, r.shear_force, r.area, r.sigma_z, r.tau_x, r.mu_b,
                        r.inertial_number, r.time, r.frame_force, r.box_vertical_force, r.box_rise, r.box_stop_force,
                        r.grain_weight);
          out << buf;
        }
        if (!out)
          throw std::runtime_error("cannot write " + tmp.string());
      });
      std::ostringstream sum;
      sum << "case\t" << sc.file << "\n"
          << "normal_stress_kPa\t" << sc.p.normal_stress / 1e3 << "\n"
          << "contact_friction\t" << sc.p.mu_contact << "\n"
          << "seed\t" << sc.p.seed << "\n"
          << "box_length_m\t" << sc.p.length << "\n"
          << "shear_speed_m_s\t" << sc.p.shear_speed << "\n"
          << "clumps\t" << s.n_clumps << "\nspheres\t" << s.n_spheres << "\n"
          << "gap_mm\t" << s.gap * 1e3 << "\n"
          << "time_step_s\t" << s.time_step << "\n"
          << "void_ratio_seated\t" << s.void_ratio_seated << "\n"
          << "void_ratio_at_shear_start\t" << s.void_ratio << "\n"
          << "kinetic_over_elastic_at_shear_start\t" << s.rest_kinetic_ratio << "\n"
          << "lid_speed_at_shear_start_m_s\t" << s.rest_lid_speed << "\n"
          << "load_error_at_shear_start\t" << s.load_error << "\n"
          << "inertial_number\t" << s.inertial_number << "\n"
          << "peak_mu_b\t" << s.peak_mu_b << "\n"
          << "shear_at_peak_mm\t" << s.shear_at_peak * 1e3 << "\n"
          << "frame_share_of_F_S_at_peak\t" << s.frame_share_at_peak << "\n"
          << "upper_box\t" << (sc.p.upper_box_free ? "free" : "fixed") << "\n"
          << "box_weight_N\t" << sc.p.box_weight << "\n"
          << "box_force_mean_N\t" << s.box_force_mean << "\n"
          << "box_force_max_row_N\t" << s.box_force_max << "\n"
          << "box_stop_mean_N\t" << s.box_stop_mean << "\n"
          << "box_seated_share\t" << s.box_seated_share << "\n"
          << "box_top_stop_share\t" << s.box_top_share << "\n"
          << "box_rise_max_mm\t" << s.box_rise_max * 1e3 << "\n"
          << "box_rise_final_mm\t" << s.box_rise_final * 1e3 << "\n"
          << "spheres_outside_box_at_end\t" << s.escaped << "\n"
          << "max_contraction_mm\t" << s.max_contraction * 1e3 << "\n"
          << "final_dilation_mm\t" << s.final_dilation * 1e3 << "\n"
          << "shear_steps\t" << s.steps << "\n"
          << "prepare_seconds\t" << s.prepare_seconds << "\nshear_seconds\t" << s.shear_seconds << "\n";
      write_atomically(base + "-summary.txt", [&](const std::filesystem::path& tmp) { std::ofstream(tmp) << sum.str(); });
      std::cout << sum.str() << "wrote " << base << ".tsv, " << base << "-summary.txt\n";
      refresh_report(dir);  // a report that cannot be drawn does not fail the run (its message is logged)
    } catch (const std::exception& e) {
      log::error(std::string("shear box failed: ") + e.what());
      return static_cast<int>(run_failure);
    }
    return static_cast<int>(ok);
  };
  return c;
}

}  // namespace geocomp::cli
