// pair_over_ranks() and the exit-code guard every run command shares (PairOverRanks.h).
#include "PairOverRanks.h"

#include "Commands.h"
#include "Log.h"
#include "OutputFolderLock.h"
#include "Pair.h"

#include "common/case/CaseError.h"

#include <mpi.h>

namespace geocomp::cli {

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

std::vector<int> pair_over_ranks(const std::vector<CaseDescription> &cases, const RunSettings &settings,
                                 const std::string &command, const CaseProgress &progress)
{
  int world_rank = 0, world_size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world_size);
  std::vector<int> codes(cases.size(), ok);
  for (std::size_t k = world_rank; k < cases.size(); k += world_size) {
    RunSettings s = settings;
    s.comm = MPI_COMM_SELF;
    if (progress)
      s.progress = [&progress, k](const std::string &engine, const RunProgress &p) { progress(k, engine, p); };
    codes[k] = guarded([&] {
      const OutputFolderLock lock(cases[k].output.directory, cases[k].file, "output/directory");
      return pair_case(cases[k], cases[k].output.directory, s).complete ? ok : run_failure;
    });
    log::info(command + ": rank " + std::to_string(world_rank) + " case " + cases[k].file + ": " +
              (codes[k] == ok ? "done" : "FAILED") + " -> " + cases[k].output.directory);
  }
  std::vector<int> all(cases.size(), ok);
  MPI_Allreduce(codes.data(), all.data(), static_cast<int>(codes.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return all;
}

} // namespace geocomp::cli
