// `geocomp material-point|continuum|dem <case>` run one engine; `geocomp pair <case>` runs
// every engine the case names (reusing up-to-date results), compares and reports;
// `geocomp compare <dir>` and `geocomp report <dir>` work on existing results.
#include "CaseValidation.h"
#include "Log.h"
#include "Commands.h"
#include "Engines.h"
#include "OutputFolderLock.h"
#include "Progress.h"

#include "common/ProgramCheckpoint.h"
#include "common/ProgramRunner.h"
#include "common/AtomicFile.h"
#include "common/Hdf5.h"
#include "common/ResponseFile.h"
#include "common/Version.h"
#include "compare/LocalizationOnsets.h"
#include "compare/Metrics.h"
#include "compare/Report.h"
#include "compare/calibrate/FitReport.h"
#include "continuum/fe/CubeEngine.h"
#include "dem/case/SpecimenRecord.h"
#include "dem/program/DemEngine.h"
#include "dem/program/Fields.h"
#include "dem/program/SpecimenPreparation.h"

#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <iostream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
/// The communicator engines run on: the world for `continuum`/`pair`, one rank each in a sweep.
MPI_Comm engine_comm = MPI_COMM_WORLD;

int rank()
{
  int r = 0, initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized)
    MPI_Comm_rank(engine_comm, &r);
  return r;
}

std::string command_line;

/// DEM particle snapshots of a run, inside the output folder.
const char *const dem_fields_file = "dem-fields.h5";
/// The FE cube's mid-plane fields at the end of the main path.
const char *const continuum_plane_file = "continuum-midplane.h5";
const char *const plane_columns[5] = {"x", "z", "u_x", "u_z", "kappa"};

/// Writes the cube's mid-plane (collective; rank 0 writes, atomically).
void write_mid_plane(const continuum::CubeEngine &cube, const fs::path &dir)
{
  const continuum::MidPlaneSample plane = cube.mid_plane();
  if (rank() != 0)
    return;
  fs::create_directories(dir);
  write_atomically(dir / continuum_plane_file, [&plane](const fs::path &tmp) {
    const h5::Handle f = h5::create_file(tmp);
    const std::vector<double> *columns[5] = {&plane.x, &plane.z, &plane.ux, &plane.uz, &plane.kappa};
    for (int k = 0; k < 5; ++k)
      h5::write(f.id(), plane_columns[k], *columns[k], {hsize_t(columns[k]->size())}, k == 4 ? "1" : "m");
  });
}

/// FE maps beside the DEM ones: u_x and the equivalent plastic strain kappa on y = L0/2.
/// The cube's bottom faces are rollers, so its displacements are measured from the x = 0
/// face; the DEM's platens move symmetrically about the box centre. The FE u_x is shifted
/// to the box centre, which moves by half the edge change, eps_xx L0 / 2 at the end of the
/// main path, so both maps share one reference.
void add_continuum_plane(compare::ReportInput &in, const fs::path &dir, const Response &response, double side)
{
  const fs::path file = dir / continuum_plane_file;
  if (!fs::exists(file))
    return;
  const h5::Handle f = h5::open_file(file);
  std::vector<std::vector<double>> c;
  for (const char *name : plane_columns)
    c.push_back(h5::read_doubles(f.id(), name));
  const std::vector<const ResponseSample *> main = response.path(0);
  const double centre = main.empty() ? 0.0 : 0.5 * main.back()->strain(0, 0) * side;
  for (double &u : c[2])
    u -= centre;
  compare::DisplacementMap ux{"FE cube, y = L0/2, end of the main path, from the box centre", "u_x", c[0], c[1],
                              c[2]};
  compare::DisplacementMap kappa{"FE cube, y = L0/2, end of the main path", "kappa", c[0], c[1], c[4], 100.0, "%"};
  in.maps.push_back(ux);
  in.maps.push_back(kappa);
}

/// The strain measure onsets are reported in (compare::onset_strain): the log strain from
/// the program start, on the program's axial axis or gamma_max on isochoric programs.
double onset_label(const ResponseSample &s, compare::CurveKind kind, const compare::AxialAxis &axial)
{
  return compare::onset_strain(s.strain, Tensor3::Zero(), kind, axial);
}

/// DEM particle snapshots along the main path of the last stage, for the localization
/// analysis and the mid-section maps: at its first sample and each time its progress
/// passes k/n (n = dem/snapshots), appended to <dir>/dem-fields.h5 (XDMF sidecar beside).
class SnapshotRecorder {
public:
  SnapshotRecorder(dem::DemEngine &engine, const CaseDescription &c, const fs::path &dir)
    : engine_(engine), file_(dir / dem_fields_file), n_(std::max(1u, c.dem.snapshots)),
      kind_(compare::curve_kind_for(c.program)),
      axial_(compare::axial_axis_for(c.program).value_or(compare::AxialAxis{})),
      sample_interval_(c.program.sample_interval)
  {
    fs::create_directories(dir);
  }
  /// A run from the start: no snapshots yet.
  void start()
  {
    fs::remove(file_);
    fs::remove(dem::xdmf_path(file_));
  }
  /// Going on from a program checkpoint at program time `time`, where `next` snapshots
  /// had been counted: the file keeps the snapshots taken up to then (a killed run may
  /// have written later ones).
  void resume(double time, unsigned int next)
  {
    next_ = next;
    if (!fs::exists(file_))
      return;
    std::vector<dem::ParticleFields> kept = dem::read_snapshots(file_);
    // Snapshots are taken at samples, a sample interval apart; the engine's clock and the
    // runner's may differ in the last bits (0.035000000000000031 against 0.035), so "later"
    // means more than half an interval later: the snapshot at the checkpoint's own sample stays.
    const double tolerance = 0.5 * sample_interval_;
    const auto later = std::find_if(kept.begin(), kept.end(),
                                    [&](const auto &f) { return f.time > time + tolerance; });
    if (later == kept.end())
      return;
    kept.erase(later, kept.end());
    fs::remove(file_);
    fs::remove(dem::xdmf_path(file_));
    for (const auto &f : kept)
      dem::append_snapshot(file_, f);
  }
  unsigned int next() const { return next_; }
  void operator()(const RunProgress &p)
  {
    if (p.branch != 0 || p.stage != p.stage_count - 1 || next_ > n_)
      return;
    if (next_ > 0 && p.stage_fraction < double(next_) / double(n_) - 1e-12)
      return;
    dem::append_snapshot(file_, engine_.snapshot(onset_label(*p.sample, kind_, axial_)));
    while (next_ <= n_ && p.stage_fraction >= double(next_) / double(n_) - 1e-12)
      ++next_;
  }

private:
  dem::DemEngine &engine_;
  fs::path file_;
  unsigned int n_, next_ = 0;
  compare::CurveKind kind_;
  compare::AxialAxis axial_;
  double sample_interval_;
};

/// The DEM side of the report from the particle snapshots: localization onset and band
/// (compare::detect_localization, local-strain radius 3 mean radii, docs/metrics.md) as
/// the DEM entry of the verdict, and the mid-section maps of u_x and u_z in the slab
/// |y - L0/2| <= 2 R between the first and the last snapshot (S0 Fig. 3, 5).
void add_dem_fields(compare::ReportInput &in, const fs::path &dir, std::vector<compare::OnsetEstimate> &onsets)
{
  const fs::path file = dir / dem_fields_file;
  if (!fs::exists(file)) {
    in.notes.push_back("DEM: no particle snapshots in " + file.string() + "; no DEM onset or maps.");
    return;
  }
  const std::vector<dem::ParticleFields> fields = dem::read_snapshots(file);
  if (fields.size() < 2) {
    in.notes.push_back("DEM: fewer than two particle snapshots; no DEM onset or maps.");
    return;
  }
  std::vector<compare::ParticleSnapshot> snapshots;
  for (const auto &f : fields)
    snapshots.push_back({f.ids, f.positions, f.label});
  double mean_radius = 0.0;
  for (double r : fields.front().radii)
    mean_radius += r / double(fields.front().radii.size());
  compare::LocalizationOptions options;
  options.strain.radius = 3.0 * mean_radius;
  const compare::LocalizationResult loc = compare::detect_localization(snapshots, options);
  compare::OnsetEstimate dem_onset;
  dem_onset.source = "DEM (particle local strain)";
  dem_onset.found = loc.onset_found;
  dem_onset.strain = loc.onset_label;
  dem_onset.has_angle = loc.band.found;
  dem_onset.angle_deg = loc.band.angle_to_compressive_deg;
  std::ostringstream note;
  note << fields.size() << " snapshots; heterogeneity index (CV of the incremental local shear strain) up to "
       << (loc.index.empty() ? 0.0 : *std::max_element(loc.index.begin(), loc.index.end())) << ", threshold "
       << options.threshold;
  if (loc.band.found)
    note << "; band of " << loc.band.band_particles << " particles, planarity " << loc.band.planarity;
  dem_onset.note = note.str();
  onsets.push_back(dem_onset);
  const dem::ParticleFields &first = fields.front(), &last = fields.back();
  const double y_mid = 0.5 * (first.box_min.y() + first.box_max.y());
  std::ostringstream title;
  title << "DEM, y = L0/2, from strain " << first.label << " to " << last.label << ", from the box centre";
  for (int component : {0, 2})
    in.maps.push_back(compare::midsection_map(snapshots.front(), snapshots.back(), y_mid, 2.0 * mean_radius,
                                              component, title.str()));
}

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

/// Runs one engine through the program and writes <dir>/<engine>.h5 (rank 0).
Response run_engine(const std::string &engine, const CaseDescription &c, const fs::path &dir, bool reuse)
{
  ensure_mpi();
  const fs::path file = dir / results_file(engine);
  if (reuse && up_to_date(file, c)) {
    if (rank() == 0)
      log::info(engine + ": up-to-date results reused: " + file.string());
    return read_response(file);
  }
  if (engine == "dem" && rank() == 0)
    for (const std::string &unused : dem::ignored_specimen_entries(c))
      log::warning(unused);
  std::unique_ptr<LoadingEngine> e = make_engine(engine, c, dir.string(), engine_comm);
  ProgramRunner runner(c.program, *e);
  ProgressPrinter progress(engine);
  std::unique_ptr<SnapshotRecorder> snapshots;
  if (auto *d = dynamic_cast<dem::DemEngine *>(e.get()))
    snapshots = std::make_unique<SnapshotRecorder>(*d, c, dir);
  runner.on_progress([&](const RunProgress &p) {
    if (snapshots)
      (*snapshots)(p);
    if (rank() == 0)
      progress(p);
  });
  // Program checkpoints (DEM): periodic and on SIGINT/SIGTERM, at main-path samples;
  // the same command resumes from one written for the same case text by the same build.
  const fs::path checkpoint = dir / (engine + "-program.ckpt");
  const std::string key = std::string(GEOCOMP_GIT_HASH) + "\n" + c.text;
  std::optional<ProgramCheckpoint> resumed;
  int ranks = 1;
  MPI_Comm_size(engine_comm, &ranks);
  if (e->can_write_states() && ranks == 1) {
    dem::install_interrupt_handlers();
    CheckpointPolicy policy;
    policy.every_seconds = c.dem.checkpoint_interval;
    policy.stop_requested = [] { return dem::interrupt_requested() != 0; };
    policy.write = [&](const RunnerState &state, const EngineState &current, const EngineState *peak) {
      write_program_checkpoint(checkpoint, key, state, *e, current, peak, snapshots ? snapshots->next() : 0);
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
      e->restore(*resumed->current);
      r = runner.resume(std::move(resumed->runner), std::move(resumed->peak));
    } else {
      if (snapshots)
        snapshots->start();
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
  const auto *cube = dynamic_cast<const continuum::CubeEngine *>(e.get());
  if (cube && !failed)
    write_mid_plane(*cube, dir);
  if (rank() == 0) {
    RunMeta meta;
    meta.case_file = c.file;
    meta.case_text = c.text;
    meta.command = command_line;
    meta.seed = c.seed;
    meta.kinematics = engine == "dem" ? "finite strain (particle positions; box strain ln(L/L0), wall force over "
                                        "current wall area)"
                                      : c.continuum.kinematics;
    meta.status = status;
    meta.parameters = parameters_text(c);
    if (engine == "dem")
      meta.specimen_record = dem::specimen_record(c, GEOCOMP_GIT_HASH);
    log::debug(engine + ": writing " + file.string() + " (status " + status + ")");
    write_response(file, r, meta);
    log::info(engine + ": " + std::to_string(r.samples.size()) + " samples, " + std::to_string(r.branches.size()) +
              " unloading branches -> " + file.string());
    if (!failed && status != "complete")
      log::warning(engine + ": " + status);
  }
  if (failed)
    throw std::runtime_error(engine + " " + status + "; the samples recorded so far are in " + file.string());
  return r;
}

std::string label_of(const std::string &engine)
{
  if (engine == "dem")
    return "DEM";
  if (engine == "continuum")
    return "FE cube";
  return "material point";
}

compare::ReportInput report_input(const CaseDescription &c, const std::vector<std::pair<std::string, Response>> &runs,
                                  const fs::path &dir)
{
  compare::ReportInput in;
  in.title = c.title.empty() ? "geocomp: " + c.file : c.title;
  in.case_name = c.file;
  in.kind = compare::curve_kind_for(c.program);
  in.axial = compare::axial_axis_for(c.program);
  compare::MetricOptions options;
  options.kind = in.kind;
  options.axial = in.axial;
  for (const auto &[engine, instantaneous] : runs) {
    // Metrics, curves and tables read each engine's interval-mean stresses (the DEM's; the
    // continuum's samples are its states), and the report says so.
    const Response response = with_interval_means(instantaneous);
    if (instantaneous.interval_means)
      in.notes.push_back(label_of(engine) + ": stresses in the curves, tables and metrics are means over each "
                         "sampling interval (the instantaneous samples are /response/stress of " +
                         results_file(engine) + ").");
    in.responses.push_back({label_of(engine), response});
    try {
      in.metrics.push_back({label_of(engine), compare::compute_metrics(response, options)});
    } catch (const std::exception &e) {
      in.notes.push_back(label_of(engine) + ": metrics not computed: " + e.what());
    }
  }
  // Rudnicki-Rice: the theory along the material-point path against each engine's onset.
  const Response *point = nullptr;
  std::vector<compare::OnsetEstimate> onsets;
  for (const auto &[engine, response] : runs) {
    if (engine == "material-point")
      point = &response;
    if (engine != "dem")
      onsets.push_back(
        compare::acoustic_tensor_onset(response, label_of(engine) + " (acoustic tensor)", in.kind, -1, in.axial));
    else
      add_dem_fields(in, dir, onsets);
    if (engine == "continuum")
      add_continuum_plane(in, dir, response, cube_parameters(c, dir.string()).side);
  }
  in.calibrated_parameters = calibration::read_parameter_table(dir / "calibration");
  // DEM and FE maps side by side: DEM u_x | FE u_x, DEM u_z | FE kappa.
  std::vector<compare::DisplacementMap> dem_maps, fe_maps;
  for (auto &m : in.maps)
    (m.title.rfind("DEM", 0) == 0 ? dem_maps : fe_maps).push_back(std::move(m));
  in.maps.clear();
  for (std::size_t k = 0; k < std::max(dem_maps.size(), fe_maps.size()); ++k) {
    if (k < dem_maps.size())
      in.maps.push_back(std::move(dem_maps[k]));
    if (k < fe_maps.size())
      in.maps.push_back(std::move(fe_maps[k]));
  }
  if (point && c.continuum.model == "nikolaevsky") {
    in.notes.push_back("No Rudnicki-Rice prediction: it is computed from the Mohr-Coulomb parameters, and the "
                       "case's model is nikolaevsky.");
  } else if (point) {
    const continuum::MaterialParameters m = continuum_material(c);
    const compare::KappaMeasure measure = c.continuum.model == "drucker-prager" ? compare::KappaMeasure::shear_strain
                                                                                : compare::KappaMeasure::mohr_coulomb;
    in.verdict = compare::rudnicki_rice_verdict(
      compare::rudnicki_rice_onset(*point, m.mohr_coulomb, m.drucker_prager_matching, measure, in.kind, -1, in.axial),
      onsets);
  } else {
    in.notes.push_back("No Rudnicki-Rice prediction: add 'material-point' to the case's engines.");
  }
  in.notes.push_back("Measures, the same for every engine: logarithmic strain ln(L/L0) of the box edges and "
                     "Cauchy stress (force over current area); continuum kinematics: " + c.continuum.kinematics + ". " +
                     (in.kind == compare::CurveKind::AxialLateral
                        ? "Axial curve on axis " + in.axial.value_or(compare::AxialAxis{}).describe() + "."
                        : std::string("tau_max and gamma_max are sign-free.")));
  return in;
}

int write_and_say(const compare::ReportInput &in, const fs::path &dir)
{
  if (rank() != 0)
    return ok;
  const compare::ReportOutcome out = compare::write_report(in, dir / "report");
  log::info("report: " + (out.dir / "index.html").string());
  if (!out.plots_made)
    log::info("  (" + out.message + ")");
  return ok;
}

struct RunOptions {
  CaseDescription c;
  fs::path dir;
  std::string dir_given_as; ///< "output/directory" or "--output", for messages
  bool reuse = true;
};

/// The case, validated for its engines and `engine` (the one a command runs) before
/// anything runs, and where its results go.
RunOptions parse_run(const std::vector<std::string> &args, const std::vector<std::string> &engine = {})
{
  const Arguments a = Arguments::parse(args, {"output"}, {"force"});
  if (a.positional.size() != 1)
    throw UsageError("expected exactly one case file");
  RunOptions o;
  o.c = read_valid_case(a.positional[0], engine);
  o.dir = a.has("output") ? fs::path(a.get("output")) : fs::path(o.c.output.directory);
  o.dir_given_as = a.has("output") ? "--output" : "output/directory";
  o.reuse = !a.has("force");
  return o;
}

/// The output folder of a run, locked for as long as the result lives (OutputFolderLock).
std::unique_ptr<OutputFolderLock> lock_output(const RunOptions &o)
{
  ensure_mpi();
  return lock_for_run(o.dir, o.c.file, o.dir_given_as, engine_comm);
}

/// Runs `body`, mapping failures onto exit codes: bad input 2, run failure 1.
int guarded(const std::function<int()> &body)
{
  try {
    return body();
  } catch (const CaseError &e) {
    log::error(e.what());
    return bad_input;
  } catch (const UsageError &) {
    throw;
  } catch (const std::exception &e) {
    log::error(std::string("run failed: ") + e.what());
    return run_failure;
  }
}

Command engine_command(const std::string &engine, const std::string &summary, const std::string &details)
{
  Command c;
  c.name = engine;
  c.summary = summary;
  c.usage = "usage: geocomp " + engine + " <case> [--output DIR] [--force]\n\n" + details +
            "\nWrites <output directory>/" + results_file(engine) +
            " (docs/results-format.md); --output overrides the case's\n"
            "output directory; results made from the same case text by the same build are reused\n"
            "unless --force.\n";
  c.run = [engine](const std::vector<std::string> &args) {
    RunOptions o = parse_run(args, {engine});
    return guarded([&] {
      const auto lock = lock_output(o);
      const Response r = run_engine(engine, o.c, o.dir, o.reuse);
      return static_cast<int>(completion_status(r, o.c.program) == "complete" ? ok : run_failure);
    });
  };
  return c;
}
} // namespace

void set_command_line(const std::string &line) { command_line = line; }

Command dem_command()
{
  return engine_command("dem", "run the DEM specimen in its wall box through the program",
                        "Prepares (or reuses, <output>/dem-specimen.bin) the case's consolidated specimen,\n"
                        "then plays the loading program with kinematic and servo walls (S0 eq. (3) as\n"
                        "wall positions), measuring wall and Love-Weber stress, coordination, fabric,\n"
                        "inertial number and unbalanced force; particle snapshots go to\n"
                        "<output>/dem-fields.h5 with an XDMF sidecar for ParaView.\n");
}

Command material_point_command()
{
  return engine_command("material-point", "run the continuum model at one material point through the program",
                        "Plays the case's loading program on one material point of the continuum model\n"
                        "(mixed control: strain on kinematic axes, stress on servo axes, S0 eq. (3)).\n");
}

Command continuum_command()
{
  return engine_command("continuum", "run the deal.II Mohr-Coulomb cube through the program (mpirun -np N)",
                        "Runs the case's loading program on the finite-element cube (deal.II, PETSc, MPI:\n"
                        "`mpirun -np N geocomp continuum <case>`), with VTU field output per sample.\n");
}

int pair_case(const CaseDescription &c, const fs::path &dir, bool reuse);

Command pair_command()
{
  Command c;
  c.name = "pair";
  c.summary = "run every engine of a case (reusing up-to-date results), compare, write the report";
  c.usage = "usage: geocomp pair <case> [--output DIR] [--force]\n\n"
            "Runs (or reuses) each engine the case names on the same loading program, computes\n"
            "the metrics of every Response (elastic limit, peak, softening, residual, dilatancy),\n"
            "and writes <output directory>/report/index.html with plots and metrics.json.\n";
  c.run = [](const std::vector<std::string> &args) {
    RunOptions o = parse_run(args);
    return guarded([&] {
      const auto lock = lock_output(o);
      return pair_case(o.c, o.dir, o.reuse);
    });
  };
  return c;
}

/// Runs every engine of a case, then the report (the body of `pair` and of each sweep item).
int pair_case(const CaseDescription &c, const fs::path &dir, bool reuse)
{
  std::vector<std::pair<std::string, Response>> runs;
  for (const auto &engine : engine_names())
    if (std::find(c.engines.begin(), c.engines.end(), engine) != c.engines.end())
      runs.emplace_back(engine, run_engine(engine, c, dir, reuse));
  const int code = write_and_say(report_input(c, runs, dir), dir);
  for (const auto &[engine, response] : runs)
    if (completion_status(response, c.program) != "complete")
      return run_failure; // the warning was printed with the run
  return code;
}

Command sweep_command()
{
  Command c;
  c.name = "sweep";
  c.summary = "run many independent cases, spread over MPI ranks (mpirun -np N geocomp sweep ...)";
  c.usage = "usage: [mpirun -np N] geocomp sweep <case> [<case> ...] [--force]\n\n"
            "Validates every case first (any bad case: exit 2, nothing run), then runs `pair` on\n"
            "each, case k on rank k mod N (each case's engines on that one rank), and prints one\n"
            "summary line per case. Exit 1 if any case failed.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {}, {"force"});
    if (a.positional.empty())
      throw UsageError("expected at least one case file");
    std::vector<CaseDescription> cases;
    try {
      for (const auto &f : a.positional)
        cases.push_back(read_valid_case(f));
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    ensure_mpi();
    int world_rank = 0, world_size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &world_size);
    engine_comm = MPI_COMM_SELF;
    int failures = 0;
    for (std::size_t k = world_rank; k < cases.size(); k += world_size) {
      const int code = guarded([&] {
        const OutputFolderLock lock(cases[k].output.directory, cases[k].file, "output/directory");
        return pair_case(cases[k], cases[k].output.directory, !a.has("force"));
      });
      log::info("sweep: rank " + std::to_string(world_rank) + " case " + cases[k].file + ": " +
                (code == ok ? "done" : "FAILED") + " -> " + cases[k].output.directory);
      failures += code != ok;
    }
    engine_comm = MPI_COMM_WORLD;
    int total = 0;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    return total == 0 ? static_cast<int>(ok) : static_cast<int>(run_failure);
  };
  return c;
}

/// The results of the case's engines found in `dir` (nothing is run).
std::vector<std::pair<std::string, Response>> existing_results(const fs::path &dir)
{
  std::vector<std::pair<std::string, Response>> runs;
  for (const auto &engine : engine_names()) {
    const fs::path file = dir / results_file(engine);
    if (fs::exists(file))
      runs.emplace_back(engine, read_response(file));
  }
  if (runs.empty())
    throw std::runtime_error("no results in " + dir.string() + "; run `geocomp pair` first");
  return runs;
}

/// `report` and `compare`: existing results of a case, then `action` on the comparison;
/// a command that `writes` into the folder locks it first (OutputFolderLock).
Command existing_results_command(const std::string &name, const std::string &summary, const std::string &details,
                                 const std::function<int(const compare::ReportInput &, const fs::path &)> &action,
                                 bool writes = false)
{
  Command c;
  c.name = name;
  c.summary = summary;
  c.usage = "usage: geocomp " + name + " <case> [--output DIR]\n\n" + details;
  c.run = [action, writes](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"output"}, {});
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    return guarded([&] {
      const CaseDescription cd = read_case(a.positional[0]);
      validate_engines(cd, {}); // the same refusals as every other command, before anything is read
      const fs::path dir = a.has("output") ? fs::path(a.get("output")) : fs::path(cd.output.directory);
      std::unique_ptr<OutputFolderLock> lock;
      if (writes)
        lock = std::make_unique<OutputFolderLock>(dir, cd.file, a.has("output") ? "--output" : "output/directory");
      return action(report_input(cd, existing_results(dir), dir), dir);
    });
  };
  return c;
}

Command compare_command()
{
  return existing_results_command(
    "compare", "compare existing results of a case and print the metrics and verdict (JSON)",
    "Reads the results files of the case's engines from the output directory (nothing is\n"
    "run, nothing is written) and prints metrics.json's content: the metrics of every\n"
    "engine, their differences and the Rudnicki-Rice verdict.\n",
    [](const compare::ReportInput &in, const fs::path &) {
      std::cout << compare::metrics_json(in);
      return static_cast<int>(ok);
    });
}

Command report_command()
{
  return existing_results_command("report", "compare existing results of a case and write the report",
                                  "Reads the results files of the case's engines from the output directory (nothing is\n"
                                  "run) and writes the comparison report.\n",
                                  [](const compare::ReportInput &in, const fs::path &dir) { return write_and_say(in, dir); },
                                  true);
}

} // namespace geocomp::cli
