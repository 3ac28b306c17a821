// cube_benchmark: times the FE cube on one loading program and prints the Response and the
// solver statistics. Not a test; used for the numbers in docs/continuum-fe.md.
//
//   mpirun -np N cube_benchmark [key=value ...]
//     n=8 degree=1 program=plane-strain|triaxial|isochoric strain=0.02 samples=20
//     solver=gmres|cg|direct regularization=crack-band|none integration=full|b-bar radius=0.2 factor=0.8
//     nullspace=rigid-body|translations steps=2 output=DIR verbose=0 localization=200 kpeak=0.002 kres=0.02 phi=30 psi=5
//     kinematics=finite|small reuse=1.5 (amg_rebuild_growth; 0: rebuild ML for every solve)
#include "common/ProgramRunner.h"
#include "continuum/fe/CubeEngine.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

using namespace geocomp;
using namespace geocomp::continuum;

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::map<std::string, std::string> arg;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    if (eq != std::string::npos)
      arg[a.substr(0, eq)] = a.substr(eq + 1);
  }
  auto get = [&](const std::string &k, const std::string &d) { return arg.count(k) ? arg[k] : d; };
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  const double p = 1e5, E = 1e8, nu = 0.3;
  MaterialParameters material;
  material.model = "mohr-coulomb";
  auto &m = material.mohr_coulomb;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  const double k_peak = std::stod(get("kpeak", "0.002")), k_res = std::stod(get("kres", "0.02"));
  m.cohesion = k_peak > 0.0 ? PiecewiseLinear({0.0, k_peak, k_res}, {20e3, 20e3, 4e3})
                            : PiecewiseLinear({0.0, k_res}, {20e3, 4e3});
  m.friction_angle = PiecewiseLinear(std::stod(get("phi", "30")) * M_PI / 180.0);
  m.dilatancy_angle = PiecewiseLinear(std::stod(get("psi", "5")) * M_PI / 180.0);

  CubeParameters cp;
  cp.cells_per_side = std::stoi(get("n", "8"));
  cp.degree = std::stoi(get("degree", "1"));
  cp.linear_solver = get("solver", "gmres");
  cp.near_null_space = get("nullspace", "rigid-body");
  cp.regularization = get("regularization", "crack-band");
  cp.volumetric_integration = get("integration", "full");
  cp.kinematics = parse_kinematics(get("kinematics", "finite") + " strain");
  cp.amg_rebuild_growth = std::stod(get("reuse", "1.5"));
  cp.imperfection_radius = std::stod(get("radius", "0.2"));
  cp.imperfection_cohesion_factor = std::stod(get("factor", "0.8"));
  cp.imperfection_centre = Vector3(std::stod(get("cx", "0.5")), std::stod(get("cy", "0.5")), std::stod(get("cz", "0.5")));
  cp.band_reference_width = std::stod(get("lref", "0"));
  cp.steps_per_advance = std::stoi(get("steps", "2"));
  cp.output_directory = get("output", "");
  cp.verbose = get("verbose", "0") == "1";
  cp.localization_directions = std::stoi(get("localization", "200"));
  cp.newton_tolerance = std::stod(get("tol", "1e-8"));
  cp.linear_tolerance = std::stod(get("ltol", "1e-10"));

  const double strain = std::stod(get("strain", "0.02"));
  const int samples = std::stoi(get("samples", "20"));
  const std::string kind = get("program", "plane-strain");
  LoadingProgram program;
  Stage iso;
  iso.name = "consolidation";
  for (auto &a : iso.axes)
    a = AxisDrive::stress(-p);
  Stage shear;
  shear.name = kind;
  const double rate = 1e-3;
  // The consolidation lasts one sampling interval (at least 1 time unit).
  const double consolidation = std::max(1.0, strain / rate / samples);
  iso.stop_any = {parse_condition("stage_time >= " + std::to_string(consolidation), "bench")};
  iso.max_duration = 2.0 * consolidation;
  if (kind == "isochoric") {
    shear.isochoric = true;
    shear.lambda = 0.0;
    shear.isochoric_rate = rate;
    shear.stop_any = {parse_condition("gamma_max >= " + std::to_string(strain), "bench")};
  } else {
    shear.axes[0] = AxisDrive::stress(-p);
    shear.axes[1] = kind == "triaxial" ? AxisDrive::stress(-p) : AxisDrive::rate(0.0);
    shear.axes[2] = AxisDrive::rate(-rate);
    shear.stop_any = {parse_condition("eps_zz <= " + std::to_string(-strain), "bench")};
  }
  shear.max_duration = 4.0 * strain / rate;
  program.stages = {iso, shear};
  program.sample_interval = strain / rate / samples;
  program.validate();

  const auto t0 = std::chrono::steady_clock::now();
  CubeEngine engine(cp, material, MPI_COMM_WORLD);
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ProgramRunner runner(program, engine);
  // A run that stops mid-way (Newton beyond its cut-backs) still prints what it computed,
  // its statistics and why it stopped, and exits 1.
  Response r;
  std::string failure;
  try {
    r = runner.run();
  } catch (const ProgramFailed &e) {
    r = e.partial;
    failure = e.what();
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const CubeStatistics &st = engine.statistics();
  if (root) {
    std::printf("# n=%u degree=%u dofs=%u ranks=%u h_e=%g kinematics=%s\n", cp.cells_per_side, cp.degree,
                engine.n_dofs(), dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD), engine.element_size(),
                to_string(cp.kinematics));
    std::printf("# time eps_xx eps_yy eps_zz sig_xx sig_yy sig_zz tau_max");
    for (const auto &c : r.extras)
      std::printf(" %s", c.name.c_str());
    std::printf("\n");
    for (const auto &s : r.samples) {
      std::printf("%.4g %.6e %.6e %.6e %.6e %.6e %.6e %.6e", s.time, s.strain(0, 0), s.strain(1, 1), s.strain(2, 2),
                  s.stress(0, 0), s.stress(1, 1), s.stress(2, 2), tau_max(s.stress));
      for (double x : s.extras)
        std::printf(" %.4g", x);
      std::printf("\n");
    }
    std::printf("# steps %u newton %u (%.2f/step) cutbacks %u linear its %u (%.1f/solve) preconditioner builds %u\n",
                st.steps, st.newton_iterations, double(st.newton_iterations) / st.steps, st.cutbacks,
                st.linear_iterations, double(st.linear_iterations) / st.newton_iterations, st.preconditioner_builds);
    std::printf("# seconds: setup %.2f assembly %.2f solve %.2f advance %.2f total %.2f\n", setup,
                st.assembly_seconds, st.solve_seconds, st.total_seconds, total);
    if (!failure.empty())
      std::printf("# FAILED: %s\n", failure.c_str());
  }
  return failure.empty() ? 0 : 1;
}
