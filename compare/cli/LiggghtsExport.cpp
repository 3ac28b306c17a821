#include "LiggghtsExport.h"

#include "CaseValidation.h"
#include "Commands.h"
#include "Engines.h"
#include "LiggghtsEngine.h"

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
         "branches (`unload at`): the main run writes branch_S_K.restart at each trigger and a\n"
         "`start` line in branches.txt; then run each started branch's deck in DIR, in the order\n"
         "of branches.txt: `liggghts -in in.branch_S_K` (S stage, K trigger, 1-based).\n";
}

int export_liggghts(const std::vector<std::string> &args)
{
  const Arguments a = Arguments::parse(args, {"output"}, {});
  if (a.positional.size() != 1 || !a.has("output"))
    throw UsageError("expected `geocomp export liggghts <case> --output DIR`");
  const fs::path out = a.get("output");
  if (fs::exists(out) && !fs::is_directory(out))
    throw CaseError(out.string(), "output", "exists and is not a folder");
  const CaseDescription c = read_valid_case(a.positional[0], {"dem"});
  const LiggghtsExportSummary s = export_liggghts_case(c, out, c.output.directory);
  for (const std::string &note : s.deck.notes)
    std::cerr << "export liggghts: note: " << note << "\n";
  std::cout << "export liggghts: " << c.file << " (" << s.spheres << " spheres, dt = " << s.deck.time_step << " s, "
            << s.deck.steps_per_sample << " steps per sample, " << s.model << ") -> " << s.deck.deck.string() << "\n";
  return static_cast<int>(ok);
}

} // namespace geocomp::cli
