// See LiggghtsEngine.h: the case exported, run in LIGGGHTS, read back.
#include "LiggghtsEngine.h"
#include "Engines.h"
#include "LiggghtsExport.h"
#include "Log.h"

#include "common/Subprocess.h"
#include "dem/liggghts/LiggghtsContact.h"
#include "dem/liggghts/LiggghtsSamples.h"
#include "dem/program/SpecimenExchange.h"

#include <unistd.h>

extern char **environ;

#include <fstream>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

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

/// The sizes the specimen will have before it is prepared: its radius, or the extremes of
/// a uniform distribution (what decides whether one linear constant fits every pair).
dem::Packing probe_packing(const CaseDescription &c)
{
  dem::Packing probe;
  probe.density = c.specimen.density;
  probe.radius = {c.specimen.radius};
  if (c.specimen.source == "generate" && c.specimen.size_distribution == "uniform")
    probe.radius = {c.specimen.radius * (1.0 - c.specimen.radius_spread), c.specimen.radius * (1.0 + c.specimen.radius_spread)};
  probe.position.assign(probe.radius.size(), Eigen::Vector3d::Zero());
  return probe;
}
/// `env -u NAME ...` for every variable of Open MPI's and PMIx's run-time in our environment
/// (OMPI_*, PMIX_*, ORTE_*, OPAL_*, but OMPI_ALLOW_*): geocomp is itself an MPI process (a
/// singleton), and an `mpirun` started with its parent's PMIx server and rank variables
/// ends at once with exit 1 and no output (measured); LIGGGHTS must start as a job of its own.
std::vector<std::string> without_mpi_runtime()
{
  std::vector<std::string> argv = {"/usr/bin/env"};
  for (char **e = environ; e && *e; ++e) {
    const std::string var(*e);
    const std::string name = var.substr(0, var.find('='));
    const bool runtime = name.rfind("OMPI_", 0) == 0 || name.rfind("PMIX_", 0) == 0 || name.rfind("ORTE_", 0) == 0 ||
                         name.rfind("OPAL_", 0) == 0;
    if (runtime && name.rfind("OMPI_ALLOW_", 0) != 0)
      argv.insert(argv.end(), {"-u", name});
  }
  return argv;
}
} // namespace

void check_liggghts_case(const CaseDescription &c)
{
  const dem::Packing probe = probe_packing(c);
  dem::map_contact_to_liggghts(dem::LiggghtsContactInput{c.file, &c.contact, &c.dem, &probe});
  dem::check_liggghts_program(c.program, c.file);
}

void require_liggghts(const CaseDescription &c, const LiggghtsLaunch &launch)
{
  if (!program_available(launch.program))
    throw CaseError(c.file, "engines",
                    "names 'liggghts', but the program '" + launch.program +
                      "' is not installed: install the Debian package 'liggghts' (apt-get install liggghts)");
  if (launch.ranks > 1 && !program_available(launch.mpirun))
    throw CaseError(c.file, "engines",
                    "LIGGGHTS on " + std::to_string(launch.ranks) + " ranks needs '" + launch.mpirun +
                      "', which is not installed (Debian package openmpi-bin)");
}

LiggghtsExportSummary export_liggghts_case(const CaseDescription &c, const fs::path &out, const fs::path &cache)
{
  check_liggghts_case(c); // before the specimen is prepared
  const std::unique_ptr<dem::DemEngine> engine = make_dem_engine(c, cache);
  const dem::DemSystem &system = engine->system();
  const dem::Packing p = moving_packing(system, c.specimen.density);
  dem::LiggghtsDeckInput in;
  in.case_file = c.file;
  in.packing = &p;
  in.program = &c.program;
  in.contact = dem::map_contact_to_liggghts(dem::LiggghtsContactInput{c.file, &c.contact, &c.dem, &p});
  in.servo = dem::DemEngineParameters::from_case(c.dem).servo;
  in.time_step = system.time_step();
  double d_mean = 0.0; // the skin as make_system sets it: DemParameters::skin x the mean diameter
  for (double r : p.radius)
    d_mean += 2.0 * r / double(p.size());
  in.skin = c.dem.skin * d_mean;
  LiggghtsExportSummary s{dem::write_liggghts_case(out, in), p.size(), in.contact.model};
  std::ofstream(out / kExportCaseFile) << fs::absolute(c.file).string() << "\n";
  std::ofstream(out / kExportParametersFile) << parameters_text(c);
  return s;
}

std::string liggghts_error_line(const fs::path &file)
{
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("ERROR", 0) == 0)
      return line;
  return "";
}

void run_liggghts_deck(const fs::path &dir, const LiggghtsLaunch &launch, const std::string &deck,
                       const std::string &screen_file)
{
  std::vector<std::string> argv = without_mpi_runtime();
  if (launch.ranks > 1) {
    argv.insert(argv.end(), {launch.mpirun, "-np", std::to_string(launch.ranks)});
    if (::geteuid() == 0)
      argv.push_back("--allow-run-as-root");
  }
  argv.push_back(launch.program);
  const std::string log = deck == "in.geocomp" ? std::string(kLiggghtsLogFile) : "log." + deck.substr(3);
  argv.insert(argv.end(), {"-in", deck, "-log", log});
  SubprocessOptions o;
  o.directory = dir;
  o.stdout_file = dir / screen_file;
  o.stderr_file = o.stdout_file;
  const SubprocessResult run = run_subprocess(argv, o);
  const fs::path screen = dir / screen_file;
  if (!run.started)
    throw LiggghtsRefused("LIGGGHTS did not start in " + dir.string() + ": " + run.error);
  const std::string error = liggghts_error_line(screen);
  if (!error.empty())
    throw LiggghtsRefused("LIGGGHTS refused the deck " + (dir / deck).string() + ": " + error + " (" +
                          screen.string() + ")");
  if (run.exit_code != 0)
    throw LiggghtsRefused("LIGGGHTS ended with " +
                          (run.signal ? "signal " + std::to_string(run.signal) : "exit " + std::to_string(run.exit_code)) +
                          " on " + (dir / deck).string() + "; its output: " + screen.string());
}

Response run_liggghts(const CaseDescription &c, const fs::path &dir, const LiggghtsLaunch &launch, Response *partial)
{
  require_liggghts(c, launch);
  const fs::path deck = dir / kLiggghtsDeckFolder;
  std::error_code ignored; // a previous run's samples and branches must not be read as this one's
  for (const char *file : {"samples.txt", "stages.txt", "branches.txt"})
    fs::remove(deck / file, ignored);
  if (fs::is_directory(deck, ignored))
    for (const fs::directory_entry &e : fs::directory_iterator(deck, ignored))
      if (e.path().filename().string().rfind("branch_", 0) == 0) // restart and state files
        fs::remove(e.path(), ignored);
  const dem::LiggghtsDeckSummary s = export_liggghts_case(c, deck, dir).deck;
  std::ostringstream what;
  what << "liggghts: " << s.steps_per_sample << " steps of " << s.time_step << " s per sample, "
       << launch.ranks << " rank(s), in " << deck.string();
  log::info(what.str());
  try {
    run_liggghts_deck(deck, launch, "in.geocomp", kLiggghtsScreenFile);
    // The unloading branches the main run started, each a run of its own from its restart.
    for (const std::string &branch : dem::liggghts_branch_decks(deck)) {
      log::info("liggghts: unloading branch " + branch.substr(3));
      run_liggghts_deck(deck, launch, branch, "liggghts." + branch.substr(3) + ".out");
    }
  } catch (const dem::LiggghtsSamplesError &e) {
    throw LiggghtsRefused(std::string("LIGGGHTS' branches cannot be read: ") + e.what());
  } catch (const LiggghtsRefused &) {
    try {
      if (partial)
        *partial = dem::read_liggghts_samples(deck, c.program);
    } catch (const dem::LiggghtsSamplesError &) {
      // No samples (LIGGGHTS stopped before its first): the results hold none.
    }
    throw;
  }
  try {
    return dem::read_liggghts_samples(deck, c.program);
  } catch (const dem::LiggghtsSamplesError &e) {
    throw LiggghtsRefused(std::string("LIGGGHTS ran, but its samples cannot be read: ") + e.what());
  }
}

} // namespace geocomp::cli
