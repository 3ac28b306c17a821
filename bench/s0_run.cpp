// @sect3{geocomp-bench-s0: S0's isochoric program on a packing-tool specimen, without deal.II}
//
// Why it exists: issue 36 item 3 asks for the wall time, memory and thread count of an S0
// isochoric run on a million spheres. The machine with many cores has none of the project's
// libraries, so only statically linked programs run there, and `geocomp` links deal.II (its
// case reader). This program runs the same thing as `geocomp dem cases/s0_isochoric_lambda0.prm`
// with only the DEM's libraries (geocomp_dem_program and below; bench/build-static-bench.sh
// links it statically): the case's specimen, contact law and program are filled in code
// with the values of that case, of cases/store/s0_reference.prm (how its specimen is made)
// and the defaults of dem/case/DemParameters.h, and run through the same functions:
//  1. the specimen (dem::prepare_specimen): N spheres grown to eta = 0.69 (R = 11.8 mm,
//     L0 from N, eta and R; FIRE for the frictionless rest), at rest with mu_s = 0.4 on,
//     consolidated by the servo walls to sigma_0 = 8.093 MPa; or, with --packing, the
//     spheres of an xyzr file at rest and consolidated the same way;
//  2. S0's isochoric stage, eq. (3), lambda = 0, 2 v0 / L0 = 0.5 1/s, sampled every
//     0.002 s, with the case's five unloading branches (those reached), to gamma_max >=
//     GAMMA_MAX (the case's 0.30 by default), through DemEngine and ProgramRunner.
// It prints lines to grep: `phase`, `response` (every fifth sample: gamma_max, the interval
// means of the stresses, the box volume), `shear`, `memory`, `total`. Same seed (2022) and
// N as a case file with these values: the same specimen and response bit for bit.
// With --locate TOL the stage also locates the elastic limit (`locate elastic limit`,
// tolerance TOL, docs/metrics.md): `branch` lines give each branch's start strain and
// residual, `bracket` the located bracket and the wall time of the bisection branches.
// Usage: geocomp-bench-s0 N THREADS [GAMMA_MAX] [--packing FILE.xyzr] [--locate TOL]. Bad
// arguments exit 2 before anything runs; a run that stops mid-way exits 1 and says why.
// Writes no files.
#include "bench/PeakResident.h"
#include "common/ElasticLimitBracket.h"
#include "common/ProgramRunner.h"
#include "common/Tensor.h"
#include "dem/program/DemEngine.h"
#include "dem/program/SpecimenExchange.h"
#include "dem/program/SpecimenPreparation.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace geocomp;
using namespace geocomp::dem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }


struct Arguments
{
  unsigned int particles = 0;
  int threads = 1;
  double gamma_max = 0.30;  ///< cases/s0_isochoric_lambda0.prm: stop when gamma_max >= 0.30
  std::string packing;      ///< xyzr file; empty: the packing tools make the specimen
  double locate = 0.0;      ///< elastic limit tolerance; 0: not located
};

/// The arguments, or none with the reason in `why`.
std::optional<Arguments> parse_arguments(int argc, char **argv, std::string &why)
{
  Arguments a;
  std::vector<std::string> positional;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--packing") {
      if (k + 1 == argc || !a.packing.empty()) {
        why = "--packing needs one FILE.xyzr";
        return std::nullopt;
      }
      a.packing = argv[++k];
    } else if (arg == "--locate") {
      char *end = nullptr;
      a.locate = k + 1 < argc ? std::strtod(argv[++k], &end) : 0.0;
      if (!end || *end != '\0' || !(a.locate > 0.0 && a.locate < 0.1)) {
        why = "--locate needs a tolerance in (0, 0.1) (a strain)";
        return std::nullopt;
      }
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() < 2 || positional.size() > 3) {
    why = "expected N THREADS [GAMMA_MAX]";
    return std::nullopt;
  }
  char *end = nullptr;
  const long n = std::strtol(positional[0].c_str(), &end, 10);
  if (*end != '\0' || n < 8 || n > 100000000) {
    why = "N: expected an integer in [8, 1e8], got '" + positional[0] + "'";
    return std::nullopt;
  }
  a.particles = static_cast<unsigned int>(n);
  const long threads = std::strtol(positional[1].c_str(), &end, 10);
  if (*end != '\0' || threads < 1 || threads > 1024) {
    why = "THREADS: expected an integer in [1, 1024], got '" + positional[1] + "'";
    return std::nullopt;
  }
  a.threads = int(threads);
  if (positional.size() == 3) {
    a.gamma_max = std::strtod(positional[2].c_str(), &end);
    if (*end != '\0' || !(a.gamma_max > 0.0 && a.gamma_max <= 0.5)) {
      why = "GAMMA_MAX: expected a shear strain in (0, 0.5], got '" + positional[2] + "'";
      return std::nullopt;
    }
  }
  return a;
}

/// cases/s0_isochoric_lambda0.prm's specimen, contact law and DEM settings for N spheres:
/// made as cases/store/s0_reference.prm makes the reference specimen (its seed, FIRE rest),
/// with L0 from N, eta and R (0.9991 m at N = 100 000, the store's 1 m), or read from
/// `packing`.
DemCase s0_case(const Arguments &a)
{
  DemCase c;
  c.file = "geocomp-bench-s0";
  c.title = "S0 isochoric shear, lambda = 0 (geocomp-bench-s0)";
  c.engines = {"dem"};
  c.seed = 2022;
  SpecimenParameters &s = c.specimen;
  s.source = a.packing.empty() ? "generate" : "text";
  s.text_file = a.packing;
  s.particles = a.particles;
  s.packing_fraction = 0.69;
  s.radius = 0.0118;
  s.density = 2650.0;
  s.isotropic_pressure = 8.093e6;
  s.frictionless_relaxation = "fire";
  ContactParameters &k = c.contact;
  k.model = "linear";
  k.youngs_modulus = 7e9;
  k.poisson_ratio = 0.25;
  k.impact_velocity = 1.0;
  k.restitution = 0.5;
  k.particle_friction = 0.4;
  k.wall_friction = 0.0;
  c.dem.threads = unsigned(a.threads);
  return c;
}

/// The case's program: one isochoric stage (S0 eq. (3)) to gamma_max >= `gamma_max`.
LoadingProgram s0_program(double gamma_max, double locate)
{
  Stage st;
  st.name = "isochoric shear (S0 eq. 3)";
  st.isochoric = true;
  st.lambda = 0.0;
  st.isochoric_rate = 0.5;
  char stop[64];
  std::snprintf(stop, sizeof stop, "gamma_max >= %g", gamma_max);
  st.stop_any = {parse_condition(stop, "program/stage 1/stop when")};
  st.max_duration = 2.0;
  for (const char *t : {"gamma_max >= 0.005", "gamma_max >= 0.01", "gamma_max >= 0.03", "peak", "peak_drop >= 0.1"})
    st.unload_at.push_back(parse_trigger(t, "program/stage 1/unload at"));
  st.locate_elastic_limit = locate > 0.0;
  st.elastic_limit_tolerance = locate > 0.0 ? locate : st.elastic_limit_tolerance;
  LoadingProgram p;
  p.stages = {st};
  p.sample_interval = 0.002;
  p.validate();
  return p;
}

/// Prints a line when the preparation enters a phase (the record times each at the end).
struct PhaseAnnouncer
{
  Clock::time_point start;
  std::string current;
  void operator()(const std::string &phase, double, double)
  {
    if (phase == current)
      return;
    current = phase;
    std::printf("phase started: %s at %.1f s wall\n", phase.c_str(), seconds_since(start));
    std::fflush(stdout);
  }
};

void print_preparation(const PreparationRecord &r, const DemSystem &s)
{
  const std::pair<const char *, const PhaseCost *> phases[] = {
    {"growth", &r.growth}, {"rest_frictionless", &r.frictionless}, {"rest_friction_on", &r.frictional},
    {"consolidation", &r.consolidation}};
  for (const auto &[name, cost] : phases)
    std::printf("phase %s: %.2f s wall, %llu steps, %.4f s DEM time\n", name, cost->wall_seconds,
                static_cast<unsigned long long>(cost->steps), cost->time);
  std::printf("phase preparation: %.2f s wall, %llu steps, %zu rebuilds, %d threads\n", r.wall_seconds,
              static_cast<unsigned long long>(r.steps), s.n_rebuilds(), s.num_threads());
  std::printf("specimen: %zu spheres, box %.4f m, packing fraction %.4f, Z %.3f, mean overlap %.2e d, "
              "stress error %.2e, dt %.3e s\n",
              s.n_particles(), r.box_size, r.final_packing_fraction, r.coordination, r.mean_overlap,
              r.consolidated.stress_error, s.time_step());
}

/// One `response` line: the sample's gamma_max and interval-mean stresses (MPa, tension
/// positive; p and tau_max as magnitudes) and the box volume.
void print_sample(const RunProgress &p, double reference_volume)
{
  const ResponseSample &s = *p.sample;
  const Tensor3 &m = s.stress_mean;
  std::printf("response branch=%d t=%.4f gamma_max=%.6f p_MPa=%.6f tau_max_MPa=%.6f sxx_MPa=%.6f syy_MPa=%.6f "
              "szz_MPa=%.6f volume_m3=%.9f\n",
              p.branch, s.time, gamma_max(s.strain), -1e-6 * mean_stress(m), 1e-6 * tau_max(m), 1e-6 * m(0, 0),
              1e-6 * m(1, 1), 1e-6 * m(2, 2), reference_volume * (1.0 + volumetric_strain(s.strain)));
  std::fflush(stdout);
}

struct ShearResult
{
  bool complete = false;
  std::string status;
  std::size_t samples = 0, branches = 0;
  double bisection_seconds = 0.0; ///< wall time after the last main-path sample
};

/// The `branch` lines and the `bracket` line of a run that located its elastic limit.
void print_branches(const Response &r, const ShearResult &out)
{
  const std::vector<BranchPoint> points = branch_points(r, 0, r.samples.front());
  int bisections = 0;
  for (const BranchPoint &b : points) {
    bisections += b.bisection ? 1 : 0;
    std::printf("branch %d %s start_gamma_pct=%.4f residual_pct=%.4f\n", b.id, b.bisection ? "bisection" : "planned",
                100 * b.x, 100 * b.residual);
  }
  const LimitSearch s = search_limit(points, s0_residual_threshold);
  if (s.bracketed())
    std::printf("bracket gamma_max_pct=[%.4f, %.4f] width_pct=%.4f bisection_branches=%d bisection_wall_s=%.2f\n",
                100 * s.lower->x, 100 * s.upper->x, 100 * s.width(), bisections, out.bisection_seconds);
  else
    std::printf("bracket none: no two neighbouring branches straddle 1 %%\n");
}

/// Runs the program on the engine with the `response` lines; exceptions of the engine come
/// back as a failed status (ProgramFailed), not thrown.
ShearResult run_shear(DemEngine &engine, const LoadingProgram &program)
{
  ProgramRunner runner(program, engine);
  const double volume = engine.reference_lengths().prod();
  std::size_t count = 0;
  Clock::time_point last_main = Clock::now();
  runner.on_progress([&](const RunProgress &p) {
    if (p.branch == 0)
      last_main = Clock::now();
    if (count++ % 5 == 0)
      print_sample(p, volume);
  });
  ShearResult out;
  try {
    const Response r = runner.run();
    out.status = completion_status(r, program);
    out.complete = out.status == "complete";
    out.samples = r.samples.size();
    out.branches = r.branches.size();
    out.bisection_seconds = seconds_since(last_main);
    if (program.stages[0].locate_elastic_limit)
      print_branches(r, out);
  } catch (const ProgramFailed &f) {
    out.status = f.status;
    out.samples = f.partial.samples.size();
    out.branches = f.partial.branches.size();
  }
  return out;
}

int usage(const char *self, const std::string &why)
{
  std::fprintf(stderr, "%s: %s\nusage: %s N THREADS [GAMMA_MAX] [--packing FILE.xyzr] [--locate TOL]\n", self, why.c_str(), self);
  return 2;
}

/// The bad-input checks of the specimen (an unreadable packing, one of another N): exit 2.
std::optional<std::string> check_input(const DemCase &c)
{
  try {
    check_specimen(c);
    if (c.specimen.source == "text") {
      const std::size_t n = read_packing_file(c.specimen.text_file).size();
      if (n != c.specimen.particles)
        return "N = " + std::to_string(c.specimen.particles) + " but " + c.specimen.text_file + " holds " +
               std::to_string(n) + " spheres";
    }
  } catch (const std::exception &e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

} // namespace

int main(int argc, char **argv)
{
  std::string why;
  const std::optional<Arguments> a = parse_arguments(argc, argv, why);
  if (!a)
    return usage(argv[0], why);
  const DemCase c = s0_case(*a);
  if (const auto bad = check_input(c))
    return usage(argv[0], *bad);
  const LoadingProgram program = s0_program(a->gamma_max, a->locate);
  const auto start = Clock::now();
  std::printf("geocomp-bench-s0: N=%u threads=%d gamma_max=%g specimen=%s\n", a->particles, a->threads,
              a->gamma_max, a->packing.empty() ? "packing tools (seed 2022)" : a->packing.c_str());
  std::fflush(stdout);

  std::optional<PreparedSpecimen> prepared;
  try {
    prepared = prepare_specimen(c, {}, PhaseAnnouncer{start, {}});
  } catch (const std::exception &e) {
    std::printf("stopped: the specimen preparation failed: %s\n", e.what());
    return 1;
  }
  print_preparation(prepared->record, prepared->system);

  DemEngine engine(std::move(prepared->system), DemEngineParameters::from_case(c.dem));
  prepared.reset();
  const std::uint64_t steps0 = engine.system().n_steps();
  const std::size_t rebuilds0 = engine.system().n_rebuilds();
  const auto t_shear = Clock::now();
  const ShearResult r = run_shear(engine, program);
  const DemSystem &s = engine.system();
  std::printf("phase shear: %.2f s wall, %llu steps, %zu rebuilds (main path), %zu samples, %zu branches, "
              "%d threads\n",
              seconds_since(t_shear), static_cast<unsigned long long>(s.n_steps() - steps0),
              s.n_rebuilds() - rebuilds0, r.samples, r.branches, s.num_threads());
  std::printf("memory: %.0f bytes/particle (DemSystem::memory_bytes), peak_resident_MB %.0f\n",
              double(s.memory_bytes()) / double(s.n_particles()), bench::peak_resident_mb());
  std::printf("total: %.2f s wall, N=%zu threads=%d status=%s\n", seconds_since(start), s.n_particles(),
              s.num_threads(), r.status.c_str());
  if (!r.complete) {
    std::printf("stopped: %s\n", r.status.c_str());
    return 1;
  }
  return 0;
}
