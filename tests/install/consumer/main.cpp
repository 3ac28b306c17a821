// geocomp_consumer: a program outside the project, built against the installed package
// (headers under include/geocomp, imported targets geocomp::*). It uses three libraries as a
// user's program would: it reads a case (geocomp_case, deal.II's ParameterHandler), runs
// its material point through the program (geocomp_cli_engines, ProgramRunner), computes the
// metrics (geocomp_compare), and checks the run against a results file the `geocomp`
// command wrote for the same case: every sample's time, strain and stress must be the same
// bits, since both are the same code. It also steps two touching spheres (geocomp_dem) and
// checks that their momentum is conserved (Newton's third law in the contact pass).
// Usage: geocomp_consumer CASE.prm CLI_RESULTS.h5; exit 0 when every check holds, 1 if not.
#include "common/ProgramRunner.h"
#include "common/ResponseFile.h"
#include "compare/Metrics.h"
#include "compare/case/CaseDescription.h"
#include "compare/cli/Engines.h"
#include "dem/DemSystem.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iostream>

using namespace geocomp;

namespace {

int failures = 0;

void expect(bool ok, const std::string &what)
{
  std::cout << (ok ? "ok: " : "FAILED: ") << what << "\n";
  if (!ok)
    ++failures;
}

void check_material_point(const std::string &case_path, const std::string &cli_results)
{
  const CaseDescription c = read_case(case_path);
  const auto dir = std::filesystem::current_path() / "consumer-fields"; // the test's scratch folder
  std::unique_ptr<LoadingEngine> engine = cli::make_engine("material-point", c, dir.string());
  ProgramRunner runner(c.program, *engine);
  const Response here = runner.run();
  const Response cli = read_response(cli_results);
  expect(here.samples.size() == cli.samples.size() && !here.samples.empty(),
         "as many samples as the CLI's run (" + std::to_string(here.samples.size()) + ")");
  bool same = here.samples.size() == cli.samples.size();
  for (std::size_t k = 0; same && k < here.samples.size(); ++k)
    same = here.samples[k].time == cli.samples[k].time && here.samples[k].strain == cli.samples[k].strain &&
           here.samples[k].stress == cli.samples[k].stress;
  expect(same, "every sample's time, strain and stress equal the CLI's bit for bit");
  const double p0 = -here.samples.front().stress.trace() / 3.0;
  expect(std::abs(p0 - c.specimen.isotropic_pressure) <= 1e-9 * c.specimen.isotropic_pressure,
         "the first sample's mean stress is the case's isotropic pressure");
  const compare::MetricSet m = compare::compute_metrics(here);
  expect(!compare::metric_table(m).empty(), "the metrics of the run are computed");
}

void check_two_spheres()
{
  using dem::Vec3;
  dem::DemSystem system;
  system.set_contact_model(
      dem::LinearSpringDashpot(dem::LinearNormal::with_stiffness(1e5, 0.5), dem::LinearTangential::with_ratio(2.0 / 7.0)));
  system.set_friction(0.3);
  const dem::ParticleId a = system.add_sphere(Vec3(0.0, 0.0, 0.0), 0.01, 2650.0, Vec3(0.1, 0.02, 0.0));
  const dem::ParticleId b = system.add_sphere(Vec3(0.0199, 0.0, 0.0), 0.01, 2650.0, Vec3(-0.1, 0.0, 0.0));
  system.set_time_step(1e-6);
  const auto momentum = [&] {
    const dem::ParticleStore &p = system.particles();
    return Vec3(p.mass[system.index_of(a)] * system.velocity(a) + p.mass[system.index_of(b)] * system.velocity(b));
  };
  const Vec3 p0 = momentum();
  for (int n = 0; n < 5000; ++n)
    system.step();
  expect(system.velocity(a).x() < 0.0, "the spheres bounced off each other");
  expect((momentum() - p0).norm() <= 1e-12 * p0.norm(), "two colliding spheres keep their total momentum");
}

} // namespace

int main(int argc, char **argv)
{
  if (argc != 3) {
    std::cerr << "usage: geocomp_consumer CASE.prm CLI_RESULTS.h5\n";
    return 2;
  }
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try {
    check_material_point(argv[1], argv[2]);
    check_two_spheres();
  } catch (const std::exception &e) {
    std::cerr << "geocomp_consumer: " << e.what() << "\n";
    return 1;
  }
  return failures == 0 ? 0 : 1;
}
