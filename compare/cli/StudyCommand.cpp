// `geocomp study <study.prm>`: the cases of a study file (compare/case/StudyFile.h) run as one
// job - each through `pair`, spread over the MPI ranks as `sweep` spreads them, up-to-date
// results reused - then one report overlaying their curves and plotting their summary
// against the study's entry (compare/StudyReport.h). The run itself is run_study()
// (StudyRun.h), which Python's geocomp.study calls too.
#include "Commands.h"
#include "Log.h"
#include "StudyRun.h"

#include "common/case/CaseError.h"

#include <iostream>

namespace geocomp::cli {

Command study_command()
{
  Command c;
  c.name = "study";
  c.summary = "run a study's cases as one job (mpirun -np N) and report them against one entry";
  c.usage = "usage: [mpirun -np N] geocomp study <study.prm> [--force] [--check] [--print-parameters]\n\n"
            "Reads the study file (a list of cases, or one case with an entry swept over values;\n"
            "docs/studies.md), checks every case it makes (any bad input: exit 2, nothing written),\n"
            "writes each as <output>/cases/<name>/<name>.prm, runs `pair` on each (reusing up-to-date\n"
            "results unless --force; case k on rank k mod N, as `sweep`), then writes\n"
            "<output>/report/index.html and study.json: every case's curves overlaid, and the peak\n"
            "stress, secant modulus, elastic limit, dilatancy angle and V_r against the study's\n"
            "'against' entry. Exit 1 if a case failed (the report says which). --check only reads\n"
            "and checks the study and its cases; --print-parameters prints the study file's entries.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {}, {"force", "check", "print-parameters"});
    if (a.has("print-parameters")) {
      std::cout << describe_study_parameters();
      return static_cast<int>(ok);
    }
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one study file");
    Study s;
    try {
      s = read_valid_study(a.positional[0]);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
    if (a.has("check")) {
      std::cout << s.file << ": ok (" << s.cases.size() << " case(s), against " << s.parameters.against << ")\n";
      for (const StudyCase &c : s.cases)
        std::cout << "  " << c.name << ": " << s.parameters.against << " = " << c.x << ", engines "
                  << c.description.engines.size() << " -> " << c.folder << "\n";
      return static_cast<int>(ok);
    }
    try {
      return static_cast<int>(run_study(s, command_run_settings(!a.has("force"))).complete() ? ok : run_failure);
    } catch (const CaseError &e) {
      log::error(e.what());
      return static_cast<int>(bad_input);
    }
  };
  return c;
}

} // namespace geocomp::cli
