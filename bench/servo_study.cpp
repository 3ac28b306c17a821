// geocomp-servo-study: how closely the wall servo holds the stress-controlled axes of a
// case's program on a prepared specimen: a DemEngine checkpoint such as
// <output>/dem-specimen.bin, written by `geocomp dem <case>`, or prepared from the case and
// written to that path when the file does not exist.
//
// usage: geocomp-servo-study <case.prm> <specimen.bin> [gP gI vmax]
// Plays the whole program (ProgramRunner) with the case's servo, or with the proportional
// gain, integral gain and speed cap given, and prints dem::servo_report(): per stress axis
// the worst interval mean, instantaneous and per-step deviation from the goal after the first
// 0.5 % of axial strain, and the servo walls' speed reversals. Bad arguments exit 2.
#include "common/ProgramRunner.h"
#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"
#include "dem/program/ServoReport.h"
#include "dem/program/SpecimenPreparation.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

using namespace geocomp;

int main(int argc, char **argv)
{
  if (argc != 3 && argc != 6) {
    std::fprintf(stderr, "usage: %s <case.prm> <specimen.bin> [gP gI vmax]\n", argv[0]);
    return 2;
  }
  try {
    const CaseDescription c = read_case(argv[1]);
    dem::DemEngineParameters p = dem::DemEngineParameters::from_case(c.dem);
    p.check_interrupts = false;
    if (!std::filesystem::exists(argv[2])) {
      dem::PreparedSpecimen prepared = dem::prepare_specimen(c);
      dem::DemEngine(std::move(prepared.system), p).write_checkpoint(argv[2]);
    }
    if (argc == 6) {
      p.servo.proportional_gain = std::atof(argv[3]);
      p.servo.integral_gain = std::atof(argv[4]);
      p.servo.max_velocity = std::atof(argv[5]);
    }
    auto engine = dem::DemEngine::from_checkpoint(argv[2], p);
    const auto start = std::chrono::steady_clock::now();
    ProgramRunner runner(c.program, *engine);
    const Response r = runner.run();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s", dem::servo_report(r, c.program).describe().c_str());
    std::printf("gP %g, gI %g, cap %g m/s (ratio %g); %zu spheres, %zu samples, %.1f s\n",
                p.servo.proportional_gain, p.servo.integral_gain, p.servo.max_velocity,
                p.servo.kinematic_speed_ratio, engine->system().n_particles(), r.samples.size(), seconds);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
