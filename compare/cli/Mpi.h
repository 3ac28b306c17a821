#pragma once
// MPI (and PETSc) for whatever runs engines in this process - a command of the `geocomp`
// executable or a call from Python: deal.II's MPI_InitFinalize, started once, on first
// need (checking a case needs no MPI), with one thread per rank for deal.II's task
// parallelism (the DEM threads with OpenMP), and finished once.
#include <mpi.h>

namespace geocomp::cli {

/// The process's arguments, which MPI may read (mpirun passes its own); call before
/// ensure_mpi(). Without them MPI starts with the program name "geocomp" alone.
void set_mpi_arguments(int argc, char **argv);
/// Starts MPI and PETSc unless started.
void ensure_mpi();
/// Finishes them (PETSc, then MPI); nothing when they were not started.
void finalize_mpi();
/// This process's rank in `comm`; 0 while MPI is not started.
int rank_in(MPI_Comm comm);

} // namespace geocomp::cli
