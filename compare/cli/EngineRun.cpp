#include "EngineRun.h"
#include "DemSection.h"
#include "DemSnapshots.h"
#include "Engines.h"
#include "Log.h"
#include "MidPlane.h"
#include "Mpi.h"
#include "Progress.h"

#include "common/ProgramCheckpoint.h"
#include "common/ResponseFile.h"
#include "common/Version.h"
#include "continuum/fe/CubeEngine.h"
#include "dem/case/SpecimenRecord.h"
#include "dem/program/DemEngine.h"
#include "dem/program/SpecimenPreparation.h"

#include <optional>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
/// Results of `engine` for case `c` in `dir` if they were made from the same case text and
/// the same parameters as parsed (an included file may have changed) by the same build and
/// the run completed; otherwise none.
bool up_to_date(const fs::path &file, const CaseDescription &c)
{
  if (!fs::exists(file))
    return false;
  try {
    RunMeta meta;
    read_response(file, &meta);
    return meta.case_text == c.text && meta.parameters == parameters_text(c) && meta.git_hash == GEOCOMP_GIT_HASH &&
           meta.status == "complete";
  } catch (const std::exception &) {
    return false;
  }
}

/// Writes `file`, the engine's results with their /meta provenance (called on rank 0).
void write_results(const std::string &engine, const CaseDescription &c, const fs::path &file, const Response &r,
                   const std::string &status, const std::string &command_line)
{
  RunMeta meta;
  meta.case_file = c.file;
  meta.case_text = c.text;
  meta.command = command_line;
  meta.seed = c.seed;
  meta.kinematics = engine == "dem" ? "finite strain (particle positions; box strain ln(L/L0), wall force over "
                                      "current wall area)"
                    : engine == "liggghts" ? "finite strain (LIGGGHTS particle positions; box strain from the wall "
                                             "positions, wall force over current wall area)"
                                           : c.continuum.kinematics;
  meta.status = status;
  meta.parameters = parameters_text(c);
  if (engine == "dem" || engine == "liggghts")
    meta.specimen_record = dem::specimen_record(c, GEOCOMP_GIT_HASH);
  log::debug(engine + ": writing " + file.string() + " (status " + status + ")");
  write_response(file, r, meta);
  log::info(engine + ": " + std::to_string(r.samples.size()) + " samples, " + std::to_string(r.branches.size()) +
            " unloading branches -> " + file.string());
}

/// The `liggghts` engine (LiggghtsEngine.h): its results written as every engine's, a
/// failed run's with the samples LIGGGHTS wrote and its message as /meta/status.
Response run_liggghts_engine(const CaseDescription &c, const fs::path &dir, const RunSettings &settings)
{
  const fs::path file = dir / results_file("liggghts");
  const bool root = rank_in(settings.comm) == 0;
  if (!root) // LIGGGHTS runs once, from rank 0; the others read what it wrote
    return Response{};
  Response partial;
  partial.engine = "liggghts";
  try {
    const Response r = run_liggghts(c, dir, settings.liggghts, &partial);
    const std::string status = completion_status(r, c.program);
    write_results("liggghts", c, file, r, status, settings.command_line);
    if (status != "complete")
      log::warning("liggghts: " + status);
    return r;
  } catch (const LiggghtsRefused &e) {
    write_results("liggghts", c, file, partial, std::string("failed: ") + e.what(), settings.command_line);
    throw std::runtime_error(std::string(e.what()) + "; the samples recorded so far are in " + file.string());
  }
}
} // namespace

bool results_up_to_date(const std::string &engine, const CaseDescription &c, const fs::path &dir)
{
  return up_to_date(dir / results_file(engine), c);
}

Response run_engine(const std::string &engine, const CaseDescription &c, const fs::path &dir, const RunSettings &settings)
{
  ensure_mpi();
  const int rank = rank_in(settings.comm);
  const bool reuse = settings.reuse;
  const fs::path file = dir / results_file(engine);
  if (reuse && up_to_date(file, c)) {
    if (rank == 0)
      log::info(engine + ": up-to-date results reused: " + file.string());
    return read_response(file);
  }
  if (engine == "liggghts")
    return run_liggghts_engine(c, dir, settings);
  if (engine == "dem" && rank == 0)
    for (const std::string &unused : dem::ignored_specimen_entries(c))
      log::warning(unused);
  std::unique_ptr<LoadingEngine> e = make_engine(engine, c, dir.string(), settings.comm);
  ProgramRunner runner(c.program, *e);
  ProgressPrinter progress(engine);
  // Fields along the main path: the DEM's snapshots and mid-section, each FE engine's mid-plane.
  std::unique_ptr<SnapshotRecorder> snapshots;
  std::unique_ptr<DemSectionRecorder> dem_section;
  std::unique_ptr<CubeSectionRecorder> cube_section;
  if (auto *d = dynamic_cast<dem::DemEngine *>(e.get())) {
    snapshots = std::make_unique<SnapshotRecorder>(*d, c, dir);
    dem_section = std::make_unique<DemSectionRecorder>(*d, c, dir);
  }
  if (const auto *cube = dynamic_cast<const continuum::CubeEngine *>(e.get()))
    cube_section = std::make_unique<CubeSectionRecorder>(*cube, engine, settings.comm); // its maps and field onset
  runner.on_progress([&](const RunProgress &p) {
    if (snapshots)
      (*snapshots)(p);
    if (dem_section)
      (*dem_section)(p);
    if (cube_section)
      (*cube_section)(p);
    if (rank != 0)
      return;
    if (settings.progress)
      settings.progress(engine, p);
    else
      progress(p);
  });
  // Program checkpoints (DEM): periodic and on SIGINT/SIGTERM, at main-path samples;
  // the same command resumes from one written for the same case text by the same build.
  const fs::path checkpoint = dir / (engine + "-program.ckpt");
  const std::string key = std::string(GEOCOMP_GIT_HASH) + "\n" + c.text;
  std::optional<ProgramCheckpoint> resumed;
  int ranks = 1;
  MPI_Comm_size(settings.comm, &ranks);
  // After the program (its end or an exception) the signals kill again: a pair's fit and
  // continuum runs that follow the DEM are not left deaf to Ctrl-C.
  struct DefaultSignalsAfterwards {
    bool installed = false;
    ~DefaultSignalsAfterwards()
    {
      if (installed)
        dem::restore_default_interrupt_handlers();
    }
  } signals;
  if (e->can_write_states() && ranks == 1) {
    if (settings.signal_checkpoints) {
      dem::install_interrupt_handlers();
      signals.installed = true;
    }
    CheckpointPolicy policy;
    policy.every_seconds = c.dem.checkpoint_interval;
    policy.stop_requested = [] { return dem::interrupt_requested() != 0; };
    policy.write = [&](const RunnerState &state, const EngineState &current, const EngineState *peak,
                       const std::vector<const EngineState *> &kept) {
      write_program_checkpoint(checkpoint, key, state, *e, current, peak, kept, snapshots ? snapshots->next() : 0);
    };
    runner.set_checkpoints(policy);
    if (reuse)
      resumed = read_program_checkpoint(checkpoint, key, *e);
  }
  // A run that fails mid-way (ProgramFailed: an engine's exception, a DEM guard) still
  // writes what it recorded, with /meta/status saying where and why, and exits 1; a run
  // whose stage ended on its max duration writes all of it, says so and exits 1 too.
  Response r;
  std::string status;
  bool failed = false;
  try {
    if (resumed) {
      std::ostringstream what;
      what << engine << ": resuming from " << checkpoint.string() << " at t = " << resumed->runner.time << " s ("
           << resumed->runner.response.samples.size() << " samples)";
      log::info(what.str());
      if (snapshots)
        snapshots->resume(resumed->runner.time, static_cast<unsigned int>(resumed->counter));
      if (dem_section)
        dem_section->resume(resumed->runner.time);
      e->restore(*resumed->current);
      r = runner.resume(std::move(resumed->runner), std::move(resumed->peak), std::move(resumed->kept));
    } else {
      if (snapshots)
        snapshots->start();
      if (dem_section)
        dem_section->start();
      r = runner.run();
    }
    status = completion_status(r, c.program);
  } catch (const ProgramStopped &stopped) {
    progress.finish();
    throw std::runtime_error(engine + " stopped by a signal at t = " + std::to_string(stopped.time) +
                             " s; checkpoint " + checkpoint.string() + ": run the same command again to resume");
  } catch (ProgramFailed &failure) {
    r = std::move(failure.partial);
    status = failure.status;
    failed = true;
  }
  progress.finish();
  std::error_code ignored;
  fs::remove(checkpoint, ignored);
  if (cube_section && !failed)
    cube_section->write(dir);
  if (rank == 0) {
    write_results(engine, c, file, r, status, settings.command_line);
    if (!failed && status != "complete")
      log::warning(engine + ": " + status);
  }
  if (failed)
    throw std::runtime_error(engine + " " + status + "; the samples recorded so far are in " + file.string());
  return r;
}

} // namespace geocomp::cli
