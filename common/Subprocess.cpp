// See Subprocess.h: posix_spawnp with file actions, no shell.
#include "common/Subprocess.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char **environ;

namespace geocomp {

namespace {
/// posix_spawn's file actions, released on every way out.
struct FileActions {
  posix_spawn_file_actions_t actions;
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
};

void redirect(FileActions &f, int fd, const std::filesystem::path &file)
{
  const char *path = file.empty() ? "/dev/null" : file.c_str();
  posix_spawn_file_actions_addopen(&f.actions, fd, path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
}

bool executable(const std::string &path)
{
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}
} // namespace

bool program_available(const std::string &program)
{
  if (program.empty())
    return false;
  if (program.find('/') != std::string::npos)
    return executable(program);
  const char *path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t colon = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = dirs.substr(start, colon - start);
    if (executable((dir.empty() ? std::string(".") : dir) + "/" + program))
      return true;
    start = colon + 1;
  }
  return false;
}

SubprocessResult run_subprocess(const std::vector<std::string> &argv, const SubprocessOptions &options)
{
  SubprocessResult r;
  if (argv.empty() || argv[0].empty()) {
    r.error = "no program to run";
    return r;
  }
  FileActions f;
  posix_spawn_file_actions_addopen(&f.actions, 0, "/dev/null", O_RDONLY, 0);
  redirect(f, 1, options.stdout_file);
  if (!options.stderr_file.empty() && options.stderr_file == options.stdout_file)
    posix_spawn_file_actions_adddup2(&f.actions, 1, 2);
  else
    redirect(f, 2, options.stderr_file);
  // After the opens: the output files are named relative to our working directory.
  if (!options.directory.empty())
    posix_spawn_file_actions_addchdir_np(&f.actions, options.directory.c_str());
  std::vector<char *> args;
  for (const auto &a : argv)
    args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &f.actions, nullptr, args.data(), environ);
  if (rc != 0) {
    r.error = std::strerror(rc);
    return r;
  }
  r.started = true;
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, options.timeout_seconds > 0.0 ? WNOHANG : 0);
    if (done == pid)
      break;
    if (done < 0 && errno != EINTR) {
      r.error = std::strerror(errno);
      return r;
    }
    if (done == 0) {
      const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (waited > options.timeout_seconds && !r.timed_out) {
        r.timed_out = true;
        ::kill(pid, SIGKILL);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  if (WIFEXITED(status))
    r.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status))
    r.signal = WTERMSIG(status);
  return r;
}

} // namespace geocomp
