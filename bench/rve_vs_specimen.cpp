// geocomp-bench-rve-vs-specimen: the RVE against the wall-bounded specimen of the same packing
// (issue 35; docs/coupled.md, "The RVE against the wall-bounded specimen"). One seed, one size,
// any of three families, each prepared and sheared in the same triaxial test:
//   rve   the periodic cell of the coupling, prepared by prepare_rve (coupled/RvePreparation.h);
//   wall  the same grains by the same protocol in the wall box (coupled/wall/WallSpecimen.h);
//   cell  that wall specimen's own particles as a periodic cell, compressed again
//         (coupled/wall/SpecimenCell.h); `wall,cell` prepares the wall specimen once for both.
// The grains, the pressure and the RVE's settings are the case file's (sections specimen,
// contact, dem, dem rve; the particle count and seed come from the command line).
//
// usage: geocomp-bench-rve-vs-specimen <case.prm> <families> <particles> <seed> <output dir>
//          [strain rate [axial strain [shear damping]]]
// Defaults: 1 /s, 0.10, the settings' local damping. Writes <output dir>/<family>-n<N>-s<seed>.csv:
// '#' lines of key=value (preparation, state before shear, figures, cost), then the curve.
// Exit 2 on bad arguments, 1 when a preparation does not converge.
#include "compare/case/CaseDescription.h"
#include "coupled/RvePreparation.h"
#include "coupled/case/RveSection.h"
#include "coupled/wall/CurveMetrics.h"
#include "coupled/wall/PackingState.h"
#include "coupled/wall/SpecimenCell.h"
#include "coupled/wall/TriaxialCurve.h"
#include "coupled/wall/WallSpecimen.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace geocomp;
using namespace geocomp::coupled;

namespace {

/// Inner box of the wall specimens: 3 mean diameters inside every wall (DEM-NOTES section 8).
constexpr double kInnerMargin = 3.0;

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string state_line(const PackingState &s)
{
  std::ostringstream o;
  o.precision(6);
  o << "# state particles=" << s.particles << " mean_diameter=" << s.mean_diameter << " edge_diameters=" << s.edge
    << " packing_fraction=" << s.packing_fraction << " coordination=" << s.coordination
    << " inner_particles=" << s.inner_particles << " inner_packing_fraction=" << s.inner_packing_fraction
    << " inner_coordination=" << s.inner_coordination << "\n";
  return o.str();
}

/// Writes one family's file and prints its summary line.
void write_run(const std::filesystem::path &file, const std::string &head, const std::string &preparation,
               const PackingState &state, const TriaxialCurve &curve, double prep_seconds, double shear_seconds)
{
  const CurveMetrics m = curve_metrics(curve);
  double inertial = 0.0, lateral = 0.0;
  for (std::size_t k = 1; k < curve.size(); ++k) {
    inertial += curve[k].inertial_number / double(curve.size() - 1);
    if (curve[k].axial_strain >= 0.005)
      lateral = std::max(lateral, curve[k].lateral_error);
  }
  std::ofstream out(file);
  out.precision(8);
  out << head << preparation << state_line(state);
  out << "# metrics peak_stress_ratio=" << m.peak_stress_ratio << " peak_strain=" << m.peak_strain
      << " stress_ratio_2=" << m.stress_ratio_2 << " stress_ratio_5=" << m.stress_ratio_5
      << " stress_ratio_10=" << m.stress_ratio_10 << " volumetric_5=" << m.volumetric_5
      << " volumetric_10=" << m.volumetric_10 << " mean_inertial_number=" << inertial
      << " largest_lateral_error=" << lateral << "\n";
  out << "# cost preparation_seconds=" << prep_seconds << " shear_seconds=" << shear_seconds << "\n";
  out << "axial_strain,volumetric_strain,stress_ratio,deviator,pressure,lateral_error,inertial_number,time\n";
  for (const TriaxialPoint &p : curve)
    out << p.axial_strain << ',' << p.volumetric_strain << ',' << p.stress_ratio() << ',' << p.deviator << ','
        << p.pressure << ',' << p.lateral_error << ',' << p.inertial_number << ',' << p.time << '\n';
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
  std::printf("%s: phi %.4f (inner %.4f), Z %.3f (inner %.3f); peak q/p %.3f at %.3f, q/p %.3f %.3f %.3f, eps_v "
              "%.4f %.4f; I %.2e, lateral error %.2e; %.0f s + %.0f s\n",
              file.filename().c_str(), state.packing_fraction, state.inner_packing_fraction, state.coordination,
              state.inner_coordination, m.peak_stress_ratio, m.peak_strain, m.stress_ratio_2, m.stress_ratio_5,
              m.stress_ratio_10, m.volumetric_5, m.volumetric_10, inertial, lateral, prep_seconds, shear_seconds);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char **argv)
{
  if (argc < 6 || argc > 9) {
    std::fprintf(stderr,
                 "usage: %s <case.prm> <families: rve,wall,cell> <particles> <seed> <output dir> "
                 "[strain rate [axial strain [shear damping]]]\n",
                 argv[0]);
    return 2;
  }
  CaseDescription c;
  RveGrains grains;
  RvePreparationSettings settings;
  const std::string families = argv[2];
  const bool rve = families.find("rve") != std::string::npos, wall = families.find("wall") != std::string::npos,
             cell = families.find("cell") != std::string::npos;
  TriaxialTest test;
  double shear_damping = 0.0;
  try {
    c = read_case(argv[1]);
    grains = rve_grains(c);
    settings = rve_settings(c, c.rve);
    settings.particles = std::size_t(std::stoul(argv[3]));
    settings.seed = std::stoull(argv[4]);
    test.pressure = settings.pressure;
    test.strain_rate = argc > 6 ? std::stod(argv[6]) : 1.0;
    test.axial_strain = argc > 7 ? std::stod(argv[7]) : 0.10;
    shear_damping = argc > 8 ? std::stod(argv[8]) : settings.local_damping;
    if (!(rve || wall || cell) || settings.particles < 10 || !(test.strain_rate > 0.0) || !(test.axial_strain > 0.0))
      throw std::invalid_argument("families must name rve, wall or cell; at least 10 particles; positive rate and strain");
  } catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  const std::filesystem::path dir = argv[5];
  std::filesystem::create_directories(dir);
  const std::string tag = "-n" + std::string(argv[3]) + "-s" + std::string(argv[4]) + ".csv";
  std::ostringstream head;
  head << "# run case=" << argv[1] << " particles=" << settings.particles << " seed=" << settings.seed
       << " pressure=" << test.pressure << " strain_rate=" << test.strain_rate << " axial_strain=" << test.axial_strain
       << " local_damping=" << settings.local_damping << " shear_damping=" << shear_damping << "\n";
  try {
    if (rve) {
      auto t0 = std::chrono::steady_clock::now();
      dem::PeriodicCell r = prepare_rve(grains, settings);
      const double prep = seconds_since(t0);
      const std::string preparation = "# preparation steps=" + std::to_string(r.steps()) + "\n";
      const PackingState state = packing_state(r);
      dem::PeriodicCell::Parameters cp = r.parameters();
      cp.local_damping = shear_damping;
      r.set_parameters(cp);
      t0 = std::chrono::steady_clock::now();
      const TriaxialCurve curve = triaxial_on_cell(r, test);
      write_run(dir / ("rve" + tag), head.str() + "# family rve\n", preparation, state, curve, prep, seconds_since(t0));
    }
    if (wall || cell) {
      auto t0 = std::chrono::steady_clock::now();
      WallSpecimen w = prepare_wall_specimen(grains, settings);
      const double prep = seconds_since(t0);
      std::ostringstream p;
      p << "# preparation growth_steps=" << w.record.growth_steps << " grown_packing_fraction=" << w.record.grown_packing_fraction
        << " grown_pressure=" << w.record.grown_pressure << " growth_factor=" << w.record.growth_factor
        << " compression_steps=" << w.record.compression_steps
        << " stress_error=" << w.record.stress_error << " unbalanced=" << w.record.unbalanced << "\n";
      if (cell) {
        t0 = std::chrono::steady_clock::now();
        SpecimenCell sc = cell_of_specimen(w.system, grains, settings);
        const double cell_prep = prep + seconds_since(t0);
        const PackingState state = packing_state(sc.cell);
        dem::PeriodicCell::Parameters cp = sc.cell.parameters();
        cp.local_damping = shear_damping;
        sc.cell.set_parameters(cp);
        t0 = std::chrono::steady_clock::now();
        const TriaxialCurve curve = triaxial_on_cell(sc.cell, test);
        write_run(dir / ("cell" + tag), head.str() + "# family cell\n",
                  p.str() + "# cell compression_steps=" + std::to_string(sc.compression_steps) +
                    " volume_change=" + std::to_string(sc.volume_change) + "\n",
                  state, curve, cell_prep, seconds_since(t0));
      }
      if (wall) {
        const PackingState state = packing_state(w.system, kInnerMargin);
        w.system.set_local_damping(shear_damping);
        t0 = std::chrono::steady_clock::now();
        const TriaxialCurve curve = triaxial_on_walls(std::move(w.system), test);
        write_run(dir / ("wall" + tag), head.str() + "# family wall\n", p.str(), state, curve, prep, seconds_since(t0));
      }
    }
  } catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
