#pragma once
// @sect3{LIGGGHTS as an engine of a case (issue 34 item 2)}
//
// Why it exists: `pair` plays a case in every engine it names; LIGGGHTS is an engine that
// runs outside this process. Its run is three steps, each one already a part of its own:
//   1. the case exported as a LIGGGHTS deck (dem/liggghts/, `geocomp export liggghts`) into
//      <output>/liggghts/, from the consolidated specimen `geocomp dem` starts from;
//   2. the deck run by the `liggghts` program of Debian's package `liggghts`, in that folder,
//      without a shell (common/Subprocess.h), under `mpirun -np N` when N ranks are asked for
//      (`--allow-run-as-root` when this process is root), its screen output kept in
//      <output>/liggghts/liggghts.out and its log in log.liggghts;
//   2b. the unloading branches the main run started (branches.txt), each its own LIGGGHTS
//      run of in.branch_<stage>_<trigger> from the restart file written at its trigger, in
//      the order of their ids, screen output in liggghts.branch_<stage>_<trigger>.out;
//   3. its samples read back as the Response of engine "liggghts" (dem/liggghts/LiggghtsSamples.h).
// EngineRun.h writes the Response as <output>/liggghts.h5 with /meta, like every engine, and
// reuses it while it is up to date. A missing program is bad input (CaseError, exit 2, the
// package named); a deck LIGGGHTS refuses (an "ERROR" line on its screen, or a non-zero exit)
// is a failed run (exit 1) whose message quotes LIGGGHTS' ERROR line.
#include "compare/case/CaseDescription.h"
#include "common/Response.h"
#include "dem/liggghts/LiggghtsDeck.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace geocomp::cli {

/// How LIGGGHTS is started: `liggghts -in in.geocomp`, or under `mpirun -np ranks`.
struct LiggghtsLaunch {
  int ranks = 1;                    ///< >= 1; 1: no mpirun
  std::string program = "liggghts"; ///< searched in PATH
  std::string mpirun = "mpirun";    ///< searched in PATH, for ranks > 1
};

/// The screen output and log of a run in a deck folder.
inline constexpr const char *kLiggghtsScreenFile = "liggghts.out";
inline constexpr const char *kLiggghtsLogFile = "log.liggghts";
/// The deck folder of the `liggghts` engine inside a case's output folder.
inline constexpr const char *kLiggghtsDeckFolder = "liggghts";

/// Every case entry the deck cannot carry, refused as `export liggghts` refuses it (CaseError
/// naming the entry): the contact law's mapping, the program's stop conditions and branch
/// triggers ("peak", `locate elastic limit`: LiggghtsDeck.h).
void check_liggghts_case(const CaseDescription &c);

/// CaseError (exit 2) naming the Debian package when `launch`'s programs are not installed.
void require_liggghts(const CaseDescription &c, const LiggghtsLaunch &launch);

/// What an export wrote, for the messages.
struct LiggghtsExportSummary {
  dem::LiggghtsDeckSummary deck;
  std::size_t spheres = 0;
  std::string model; ///< LIGGGHTS' contact model
};

/// Writes the case's deck into `out` from the specimen cached in (or prepared into) `cache`
/// (Engines.h, make_dem_engine); returns what was written.
LiggghtsExportSummary export_liggghts_case(const CaseDescription &c, const std::filesystem::path &out,
                                              const std::filesystem::path &cache);

/// LIGGGHTS refused the deck or failed: what() says which folder and quotes its ERROR line.
struct LiggghtsRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs the deck `deck` of `dir` (in.geocomp, or a branch's in.branch_S_K) to its end, its
/// screen output into `screen_file`; throws LiggghtsRefused when LIGGGHTS prints an ERROR
/// line, exits non-zero or cannot be started.
void run_liggghts_deck(const std::filesystem::path &dir, const LiggghtsLaunch &launch,
                       const std::string &deck = "in.geocomp", const std::string &screen_file = kLiggghtsScreenFile);

/// The first line of `file` that LIGGGHTS starts with "ERROR" (empty: none).
std::string liggghts_error_line(const std::filesystem::path &file);

/// The whole engine: export into <dir>/liggghts, run, read back. Throws CaseError for a
/// case it refuses, LiggghtsRefused (after reading back any samples LIGGGHTS wrote into
/// `partial`) for a failed run.
Response run_liggghts(const CaseDescription &c, const std::filesystem::path &dir, const LiggghtsLaunch &launch,
                      Response *partial);

} // namespace geocomp::cli
