#include "Mpi.h"

#include <deal.II/base/mpi.h>

#include <memory>

namespace geocomp::cli {

namespace {
int saved_argc = 1;
char default_name[] = "geocomp";
char *default_argv[] = {default_name, nullptr};
char **saved_argv = default_argv;
std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
} // namespace

void set_mpi_arguments(int argc, char **argv)
{
  saved_argc = argc;
  saved_argv = argv;
}

void ensure_mpi()
{
  int initialized = 0; // by a host program (a test's main, an embedding application)
  MPI_Initialized(&initialized);
  if (!mpi && !initialized)
    mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(saved_argc, saved_argv, 1);
}

void finalize_mpi() { mpi.reset(); }

int rank_in(MPI_Comm comm)
{
  int rank = 0, initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized)
    MPI_Comm_rank(comm, &rank);
  return rank;
}

} // namespace geocomp::cli
