#pragma once
// One run at a time in an output folder: a lock file holding the process id.
//
// Why it exists: two runs into the same folder both succeed and interleave their files -
// snapshots appended by one to the other's, a specimen cache replaced under a reader,
// results from different cases side by side. A run takes <folder>/.geocomp.lock before it
// writes anything: an flock() on the open file (released by the kernel when the process
// ends, however it ends) is the lock, and the file's text - process id, host, command
// line - names the holder in the message a second run gets. A lock file whose writer
// no longer holds it (the process was killed) is stale: it is taken over with a warning.
// The lock file is removed when the run ends; a folder the lock created and nothing was
// written to is removed too, so a refused run leaves nothing behind.
#include "common/case/CaseParameters.h"

#include <mpi.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace geocomp::cli {

class OutputFolderLock {
public:
  /// Creates `dir` when missing and locks it for this process. Throws CaseError(`file`,
  /// `parameter`, ...) - bad input, exit code 2 - naming `dir` when it exists and is not a
  /// folder, cannot be created or written, or is locked by a running process (named with
  /// its id, host and command line, which this process writes into the lock file in turn).
  /// `file` and `parameter` say where the folder was given: the case file and
  /// "output/directory", or the command line and "--output".
  OutputFolderLock(const std::filesystem::path &dir, const std::string &file, const std::string &parameter);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock &) = delete;
  OutputFolderLock &operator=(const OutputFolderLock &) = delete;

  /// The lock file's path inside a folder.
  static std::filesystem::path file_in(const std::filesystem::path &dir);
  /// The warning printed when a stale lock was taken over; empty otherwise.
  const std::string &warning() const { return warning_; }

private:
  std::filesystem::path dir_;
  int fd_ = -1;
  std::vector<std::filesystem::path> created_; ///< folders this lock made, innermost first
  std::string warning_;

  /// Removes the folders this lock made, those left empty.
  void remove_created() const;
};

/// The lock of `dir` for a run on `comm` (MPI started): taken by rank 0, the other ranks
/// hold none; when rank 0 cannot take it every rank throws rank 0's CaseError.
std::unique_ptr<OutputFolderLock> lock_for_run(const std::filesystem::path &dir, const std::string &file,
                                               const std::string &parameter, MPI_Comm comm);

} // namespace geocomp::cli
