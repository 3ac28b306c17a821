#include "LiggghtsExport.h"

#include "CaseValidation.h"
#include "Commands.h"
#include "Engines.h"

#include "dem/liggghts/LiggghtsDeck.h"
#include "dem/program/SpecimenExchange.h"

#include <filesystem>
#include <fstream>
#include <iostream>

namespace geocomp::cli {

namespace fs = std::filesystem;

std::string liggghts_export_usage()
{
  return "`export liggghts <case> --output DIR` writes the case as a LIGGGHTS 3.8 run into DIR:\n"
         "specimen.data (the consolidated specimen `geocomp dem <case>` starts from, with its\n"
         "velocities; taken from, or prepared into and cached in, the case's output directory as\n"
         "`geocomp dem` does), wall_*.stl (the six box faces) and in.geocomp, the deck that plays\n"
         "the loading program (kinematic walls, geocomp's stress servo, S0 eq. (3)) and writes\n"
         "samples.txt every sample interval. Run it in DIR: `liggghts -in in.geocomp`, or\n"
         "`mpirun -np N liggghts -in in.geocomp`. A contact or program entry that LIGGGHTS cannot\n"
         "play is refused (exit 2) naming it; docs/liggghts.md tabulates the mapping. Unloading\n"
         "branches are not played yet.\n";
}

namespace {
/// The engine's specimen with its velocities, in its box.
dem::Packing moving_packing(const dem::DemSystem &system, double density)
{
  dem::Packing p = dem::packing_of(system, density);
  const dem::ParticleStore &s = system.particles();
  for (dem::ParticleId id = 0; id < system.n_particles(); ++id) {
    const dem::Index i = system.index_of(id);
    p.velocity.push_back(s.v[i]);
    p.angular_velocity.push_back(s.omega[i]);
  }
  return p;
}
} // namespace

int export_liggghts(const std::vector<std::string> &args)
{
  const Arguments a = Arguments::parse(args, {"output"}, {});
  if (a.positional.size() != 1 || !a.has("output"))
    throw UsageError("expected `geocomp export liggghts <case> --output DIR`");
  const fs::path out = a.get("output");
  if (fs::exists(out) && !fs::is_directory(out))
    throw CaseError(out.string(), "output", "exists and is not a folder");
  const CaseDescription c = read_valid_case(a.positional[0], {"dem"});
  // Everything the deck cannot carry is refused before the specimen is prepared.
  dem::Packing probe;
  probe.density = c.specimen.density;
  probe.radius = {c.specimen.radius};
  if (c.specimen.source == "generate" && c.specimen.size_distribution == "uniform") // its extremes
    probe.radius = {c.specimen.radius * (1.0 - c.specimen.radius_spread), c.specimen.radius * (1.0 + c.specimen.radius_spread)};
  probe.position.assign(probe.radius.size(), Eigen::Vector3d::Zero());
  dem::LiggghtsContactInput law{c.file, &c.contact, &c.dem, &probe};
  dem::map_contact_to_liggghts(law);
  dem::check_liggghts_program(c.program, c.file);
  const std::unique_ptr<dem::DemEngine> engine = make_dem_engine(c, c.output.directory);
  const dem::DemSystem &system = engine->system();
  const dem::Packing p = moving_packing(system, c.specimen.density);
  law.packing = &p;
  dem::LiggghtsDeckInput in;
  in.case_file = c.file;
  in.packing = &p;
  in.program = &c.program;
  in.contact = dem::map_contact_to_liggghts(law);
  in.servo = dem::DemEngineParameters::from_case(c.dem).servo;
  in.time_step = system.time_step();
  double d_mean = 0.0; // the skin as make_system sets it: DemParameters::skin x the mean diameter
  for (double r : p.radius)
    d_mean += 2.0 * r / double(p.size());
  in.skin = c.dem.skin * d_mean;
  const dem::LiggghtsDeckSummary s = dem::write_liggghts_case(out, in);
  std::ofstream(out / kExportCaseFile) << fs::absolute(c.file).string() << "\n";
  std::ofstream(out / kExportParametersFile) << parameters_text(c);
  for (const std::string &note : s.notes)
    std::cerr << "export liggghts: note: " << note << "\n";
  std::cout << "export liggghts: " << c.file << " (" << p.size() << " spheres, dt = " << s.time_step << " s, "
            << s.steps_per_sample << " steps per sample, " << in.contact.model << ") -> " << s.deck.string() << "\n";
  return static_cast<int>(ok);
}

} // namespace geocomp::cli
