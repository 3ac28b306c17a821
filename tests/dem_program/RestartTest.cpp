// Checkpoint/restart across processes: a child run (this test binary, started again)
// writes periodic checkpoints and dies by SIGKILL, or gets SIGTERM and writes a checkpoint
// before it exits; the run restarted from the file equals the uninterrupted run bit for
// bit at the same thread count (2 threads here).
#include "Specimen.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;

namespace {
constexpr double kEnd = 0.012;  ///< program time of the whole run [s]
constexpr double kKill = 0.007; ///< the child dies here [s]
constexpr int kChildInterrupted = 3;
constexpr double kSample = 0.0005; ///< sample interval [s]: samples at k kSample

/// Advances through the sample times k kSample up to `t_end` (those already passed are
/// skipped), as a run recording samples would; calls `after` at each.
template <class F>
void play(DemEngine &engine, double t_end, F &&after)
{
  for (int k = 1; k * kSample <= t_end + 1e-12; ++k) {
    if (k * kSample <= engine.time())
      continue;
    engine.advance_to(k * kSample);
    after();
  }
}

DemEngineParameters run_parameters(const std::filesystem::path &checkpoint)
{
  DemEngineParameters p = engine_parameters();
  p.checkpoint_file = checkpoint;
  p.checkpoint_every_steps = 97;
  return p;
}

/// Start state of the run: the specimen on 2 threads, in an isochoric stage with lambda = 0.5.
void write_start(const std::filesystem::path &file)
{
  DemSystem system = consolidated().system;
  system.set_num_threads(2);
  DemEngine engine(std::move(system), engine_parameters());
  static Stage stage;
  stage.isochoric = true;
  stage.lambda = 0.5;
  stage.isochoric_rate = 1.0;
  StageControl control;
  control.stage = &stage;
  engine.begin_control(control);
  engine.write_checkpoint(file);
}

int run_child(const std::filesystem::path &dir, const char *mode)
{
  setenv("GEOCOMP_DEMPROG_CHILD_DIR", dir.c_str(), 1);
  setenv("GEOCOMP_DEMPROG_CHILD_MODE", mode, 1);
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string filter = "--gtest_filter=DemEngineChild.Run";
  char *argv[] = {const_cast<char *>(self.c_str()), filter.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, self.c_str(), nullptr, nullptr, argv, environ);
  unsetenv("GEOCOMP_DEMPROG_CHILD_DIR");
  unsetenv("GEOCOMP_DEMPROG_CHILD_MODE");
  if (rc != 0)
    return -1;
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

struct Final
{
  ResponseSample sample;
  ParticleFields fields;
};

Final finish(DemEngine &engine)
{
  play(engine, kEnd, [] {});
  return {engine.measure(), engine.snapshot()};
}

void expect_bitwise_equal(const Final &a, const Final &b)
{
  EXPECT_EQ(a.sample.time, b.sample.time);
  EXPECT_EQ(a.sample.strain, b.sample.strain);
  EXPECT_EQ(a.sample.stress, b.sample.stress);
  EXPECT_EQ(a.sample.extras, b.sample.extras);
  EXPECT_EQ(a.fields.positions, b.fields.positions);
  EXPECT_EQ(a.fields.velocities, b.fields.velocities);
  EXPECT_EQ(a.fields.angular_velocities, b.fields.angular_velocities);
  EXPECT_EQ(a.fields.contact_pairs, b.fields.contact_pairs);
  EXPECT_EQ(a.fields.contact_forces, b.fields.contact_forces);
  EXPECT_EQ(a.fields.wall_contact_forces, b.fields.wall_contact_forces);
}

class Restart : public ::testing::Test
{
protected:
  void SetUp() override
  {
    dir = std::filesystem::temp_directory_path() / ("geocomp_dem_restart_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    write_start(dir / "start.bin");
    // The uninterrupted run (it writes checkpoints too, elsewhere: they change nothing).
    auto engine = DemEngine::from_checkpoint(dir / "start.bin", run_parameters(dir / "reference.ckpt"));
    reference = finish(*engine);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::filesystem::path dir;
  Final reference;
};
} // namespace

// The child side: runs only when started by the tests below.
TEST(DemEngineChild, Run)
{
  const char *dir_env = std::getenv("GEOCOMP_DEMPROG_CHILD_DIR");
  const char *mode_env = std::getenv("GEOCOMP_DEMPROG_CHILD_MODE");
  if (!dir_env || !mode_env)
    GTEST_SKIP() << "only run as the child of the restart tests";
  const std::filesystem::path dir = dir_env;
  const std::string mode = mode_env;
  install_interrupt_handlers();
  auto engine = DemEngine::from_checkpoint(dir / "start.bin", run_parameters(dir / "run.ckpt"));
  try {
    play(*engine, kEnd, [&] {
      if (engine->time() >= kKill - 1e-12) {
        if (mode == "kill")
          ::kill(::getpid(), SIGKILL); // dies here: no cleanup, no final checkpoint
        else
          ::kill(::getpid(), SIGTERM); // the handler raises the flag; the next step stops
      }
    });
  } catch (const Interrupted &e) {
    std::_Exit(e.signal == SIGTERM ? kChildInterrupted : 4);
  }
  std::_Exit(5); // never finish normally
}

TEST_F(Restart, SigkilledRunRestartsFromItsLastCheckpointBitForBit)
{
  const int status = run_child(dir, "kill");
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  ASSERT_TRUE(std::filesystem::exists(dir / "run.ckpt"));
  auto engine = DemEngine::from_checkpoint(dir / "run.ckpt", engine_parameters());
  EXPECT_GT(engine->time(), 0.0);
  EXPECT_LE(engine->time(), kKill + 1e-12); // the child died at the sample kKill
  EXPECT_EQ(engine->system().n_steps() % 97, 0u); // a periodic checkpoint
  EXPECT_EQ(engine->system().num_threads(), 2);
  std::printf("[restart] SIGKILL at t = %.4f s; restarting from the checkpoint at t = %.5f s (step %llu)\n", kKill,
              engine->time(), (unsigned long long)engine->system().n_steps());
  expect_bitwise_equal(finish(*engine), reference);
}

TEST_F(Restart, SigtermWritesACheckpointAndTheRestartIsBitForBit)
{
  const int status = run_child(dir, "term");
  ASSERT_TRUE(WIFEXITED(status)) << "status " << status;
  EXPECT_EQ(WEXITSTATUS(status), kChildInterrupted);
  auto engine = DemEngine::from_checkpoint(dir / "run.ckpt", engine_parameters());
  EXPECT_NEAR(engine->time(), kKill, 1e-12); // written at the interrupt, after the last periodic one
  std::printf("[restart] SIGTERM handled: checkpoint at t = %.5f s (step %llu)\n", engine->time(),
              (unsigned long long)engine->system().n_steps());
  expect_bitwise_equal(finish(*engine), reference);
}

TEST(DemEngineInterrupt, RequestStopsTheRunWithACheckpoint)
{
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "geocomp_dem_interrupt.ckpt";
  DemEngineParameters p = engine_parameters();
  p.checkpoint_file = file;
  DemEngine engine(consolidated().system, p);
  Stage stage;
  stage.axes = {{AxisDrive::rate(-0.5), AxisDrive::stress(-kPressure), AxisDrive::stress(-kPressure)}};
  StageControl control;
  control.stage = &stage;
  engine.begin_control(control);
  engine.advance_to(0.0005);
  request_interrupt();
  try {
    engine.advance_to(0.001);
    ADD_FAILURE() << "no Interrupted";
  } catch (const Interrupted &e) {
    EXPECT_EQ(e.checkpoint, file);
    EXPECT_NEAR(e.time, engine.time(), 1e-15);
  }
  clear_interrupt();
  auto back = DemEngine::from_checkpoint(file, engine_parameters());
  EXPECT_EQ(back->time(), engine.time());
  EXPECT_EQ(back->measure().stress, engine.measure().stress);
  std::filesystem::remove(file);
}

// A command that runs the DEM and then something else (a pair's fit, its continuum runs) must
// stop on Ctrl-C after the DEM as before it: the handlers that turn the signal into a
// checkpoint are taken down again. In a child: with the handlers, SIGTERM only raises the
// flag; after restore_default_interrupt_handlers() it terminates the process.
TEST(InterruptHandlers, SigtermRaisesTheFlagWhileInstalledAndKillsOnceRestored)
{
  for (const bool restored : {false, true}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      install_interrupt_handlers();
      if (restored)
        restore_default_interrupt_handlers();
      ::raise(SIGTERM);
      std::_Exit(interrupt_requested() == SIGTERM ? 3 : 4);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    if (restored) {
      ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
      EXPECT_EQ(WTERMSIG(status), SIGTERM);
    } else {
      ASSERT_TRUE(WIFEXITED(status)) << "status " << status;
      EXPECT_EQ(WEXITSTATUS(status), 3);
    }
  }
}
