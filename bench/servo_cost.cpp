// @sect3{geocomp-bench-servo-cost: what the wall servo and the interval means add to a step}
//
// Why it exists: issue 30 bounds the cost of the stress servo and of the interval-mean
// stresses by 2 % of the DEM step at 100 000 spheres. Both are O(1) per step (six walls:
// the servo's stiffness-based PI law per stress axis; the wall stress tensor added to the
// interval's sum, its deviation from the goals, the box and stress guards), so they are
// measured where the step itself costs least, and then set against the step of a real
// packing:
//  1. on 8 spheres (a 2 x 2 x 2 array, 1 % overlaps, the shared benchmark's law) the same
//     STEPS steps are driven three ways, ROUNDS times interleaved, fastest of each:
//       system    DemSystem::step() with the walls at fixed speeds (no engine);
//       kinematic DemEngine, every axis kinematic (the engine's wall drive, the interval
//                 means and the guards);
//       servo     DemEngine, x and y on stress goals (the same plus two servos);
//     kinematic - system is the engine's per-step bookkeeping with the means, servo -
//     kinematic the servo's;
//  2. the step of FILE.xyzr (DemSystem::step, the shared benchmark's law, walls moving in at
//     0.01 m/s, as geocomp-dem-bench) at THREADS threads;
//  3. both per-step costs as fractions of that step.
// The particles-in-the-box guard runs at samples only (N comparisons per sample), outside
// these figures. Usage: geocomp-bench-servo-cost FILE.xyzr THREADS [STEPS ROUNDS]; bad
// arguments exit 2.
#include "bench/BenchLaw.h"
#include "dem/program/DemEngine.h"
#include "dem/specimen/Packing.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace geocomp;
using namespace geocomp::dem;

namespace {
double seconds_of(const std::chrono::steady_clock::time_point &t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// 8 spheres of the benchmark's radius, 1 % overlaps with each other and the walls.
DemSystem tiny_system(const bench::BenchParameters &b)
{
  DemSystem sys;
  bench::set_bench_law(sys, b);
  const double R = b.radius, h = 2.0 * R * 0.99;
  for (int k = 0; k < 8; ++k)
    sys.add_sphere(Vec3(0.99 * R + h * (k & 1), 0.99 * R + h * ((k >> 1) & 1), 0.99 * R + h * ((k >> 2) & 1)), R,
                   b.rho);
  sys.add_box(Vec3::Zero(), Vec3::Constant(h + 1.98 * R), 0.0);
  sys.set_time_step(0.2 * sys.critical_time_step());
  sys.set_num_threads(1);
  return sys;
}

/// The engine's parameters for the 2-sphere-wide box: the box guard at half a diameter
/// (still checked every step, as in a run).
DemEngineParameters tiny_parameters()
{
  DemEngineParameters p;
  p.guards.min_edge_diameters = 0.5;
  return p;
}

/// Seconds per step of `steps` steps of a DemEngine following `stage` from `start`.
double engine_step(const DemSystem &start, const Stage &stage, long steps)
{
  DemEngine engine(start, tiny_parameters());
  StageControl control;
  control.stage = &stage;
  engine.begin_control(control);
  const double t_end = engine.time() + double(steps) * start.time_step();
  const auto t0 = std::chrono::steady_clock::now();
  engine.advance_to(t_end);
  return seconds_of(t0) / double(steps);
}

double system_step(DemSystem sys, long steps)
{
  for (std::size_t w = 0; w < 6; ++w)
    sys.set_wall_velocity(w, 1e-4 * sys.wall(w).normal);
  const auto t0 = std::chrono::steady_clock::now();
  sys.run(std::size_t(steps));
  return seconds_of(t0) / double(steps);
}
} // namespace

int main(int argc, char **argv)
{
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: %s FILE.xyzr THREADS [STEPS ROUNDS]\n", argv[0]);
    return 2;
  }
  const int threads = std::atoi(argv[2]);
  const long steps = argc == 5 ? std::atol(argv[3]) : 200000;
  const int rounds = argc == 5 ? std::atoi(argv[4]) : 5;
  if (threads < 1 || steps < 1 || rounds < 1) {
    std::fprintf(stderr, "%s: THREADS, STEPS and ROUNDS must be positive\n", argv[0]);
    return 2;
  }
  Packing packing;
  try {
    packing = read_xyzr(argv[1]);
  } catch (const PackingFileError &e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  const bench::BenchParameters b;

  // 1. The per-step costs, on 8 spheres.
  const DemSystem tiny = tiny_system(b);
  Stage kinematic;
  kinematic.axes = {{AxisDrive::rate(-1e-3), AxisDrive::rate(-1e-3), AxisDrive::rate(-1e-3)}};
  Stage servo = kinematic;
  {
    DemEngine probe(tiny, tiny_parameters());
    const Tensor3 s0 = probe.wall_stress();
    servo.axes[0] = AxisDrive::stress(s0(0, 0));
    servo.axes[1] = AxisDrive::stress(s0(1, 1));
  }
  double t_system = 1e300, t_kinematic = 1e300, t_servo = 1e300;
  for (int r = 0; r < rounds; ++r) {
    t_system = std::min(t_system, system_step(tiny, steps));
    t_kinematic = std::min(t_kinematic, engine_step(tiny, kinematic, steps));
    t_servo = std::min(t_servo, engine_step(tiny, servo, steps));
  }
  const double bookkeeping = t_kinematic - t_system, servos = t_servo - t_kinematic;
  std::printf("8 spheres, %ld steps, fastest of %d: system %.1f ns/step, engine (kinematic) %.1f, "
              "engine (2 servos) %.1f\n",
              steps, rounds, 1e9 * t_system, 1e9 * t_kinematic, 1e9 * t_servo);
  std::printf("per step: engine bookkeeping with the interval means and guards %.1f ns, two servos %.1f ns\n",
              1e9 * bookkeeping, 1e9 * servos);

  // 2. The step of the packing.
  DemSystem sys;
  bench::set_bench_law(sys, b);
  sys.reserve(packing.size());
  for (std::size_t k = 0; k < packing.size(); ++k)
    sys.add_sphere(packing.position[k], packing.radius[k], b.rho);
  sys.add_box(packing.box_min, packing.box_max, 0.0);
  for (std::size_t w = 0; w < 6; ++w)
    sys.set_wall_velocity(w, b.v_wall * sys.wall(w).normal);
  sys.set_time_step(b.dt);
  sys.set_skin(b.skin);
  sys.set_num_threads(threads);
  sys.set_contact_force_recording(DemSystem::ContactForceRecording::on_request);
  sys.run(100);
  const long timed = 500;
  const auto t0 = std::chrono::steady_clock::now();
  sys.run(std::size_t(timed));
  const double step = seconds_of(t0) / double(timed);
  std::printf("%zu spheres, %d threads: %.3f ms/step (%.1f ns/particle-step)\n", sys.n_particles(), threads,
              1e3 * step, 1e9 * step / double(sys.n_particles()));

  // 3. The fractions.
  std::printf("fraction of the step: bookkeeping with the means %.4f %%, servos %.4f %%, together %.4f %%\n",
              100.0 * bookkeeping / step, 100.0 * servos / step, 100.0 * (bookkeeping + servos) / step);
  return 0;
}
