#include "common/ProgramCheckpoint.h"

#include "common/BinaryState.h"

#include <istream>
#include <ostream>
#include <string>

namespace geocomp {

namespace {

void put_string(std::ostream &out, const std::string &s)
{
  binary::put_vector(out, std::vector<char>(s.begin(), s.end()));
}

std::string get_string(std::istream &in)
{
  std::vector<char> v;
  binary::get_vector(in, v);
  return std::string(v.begin(), v.end());
}

void put_strings(std::ostream &out, const std::vector<std::string> &v)
{
  binary::put<std::uint64_t>(out, v.size());
  for (const std::string &s : v)
    put_string(out, s);
}

std::vector<std::string> get_strings(std::istream &in)
{
  std::uint64_t n = 0;
  binary::get(in, n);
  if (n > (1u << 24))
    throw binary::StateError("checkpoint: implausible string count");
  std::vector<std::string> v(n);
  for (std::string &s : v)
    s = get_string(in);
  return v;
}

void put_response(std::ostream &out, const Response &r)
{
  put_string(out, r.engine);
  binary::put(out, r.interval_means);
  binary::put<std::uint64_t>(out, r.extras.size());
  for (const ExtraColumn &c : r.extras) {
    put_string(out, c.name);
    put_string(out, c.units);
    put_string(out, c.description);
  }
  binary::put<std::uint64_t>(out, r.samples.size());
  for (const ResponseSample &s : r.samples) {
    binary::put(out, s.time);
    binary::put(out, s.strain);
    binary::put(out, s.stress);
    binary::put(out, s.stress_mean);
    binary::put(out, s.stage);
    binary::put(out, s.branch);
    binary::put_vector(out, s.extras);
  }
  binary::put<std::uint64_t>(out, r.branches.size());
  for (const BranchRecord &b : r.branches) {
    binary::put(out, b.id);
    binary::put(out, b.stage);
    put_string(out, b.trigger);
    binary::put<std::uint64_t>(out, b.first_sample);
    binary::put<std::uint64_t>(out, b.last_sample);
    binary::put(out, b.tau_start);
    binary::put(out, b.tau_target);
    binary::put(out, b.gamma_start);
    binary::put(out, b.residual_gamma);
    binary::put(out, b.reached_target);
  }
  put_strings(out, r.stage_names);
  put_strings(out, r.stage_end_reasons);
}

std::uint64_t get_count(std::istream &in)
{
  std::uint64_t n = 0;
  binary::get(in, n);
  if (n > (std::uint64_t(1) << 32))
    throw binary::StateError("checkpoint: implausible record count");
  return n;
}

Response get_response(std::istream &in)
{
  Response r;
  r.engine = get_string(in);
  binary::get(in, r.interval_means);
  r.extras.resize(get_count(in));
  for (ExtraColumn &c : r.extras) {
    c.name = get_string(in);
    c.units = get_string(in);
    c.description = get_string(in);
  }
  r.samples.resize(get_count(in));
  for (ResponseSample &s : r.samples) {
    binary::get(in, s.time);
    binary::get(in, s.strain);
    binary::get(in, s.stress);
    binary::get(in, s.stress_mean);
    binary::get(in, s.stage);
    binary::get(in, s.branch);
    binary::get_vector(in, s.extras);
  }
  r.branches.resize(get_count(in));
  for (BranchRecord &b : r.branches) {
    std::uint64_t first = 0, last = 0;
    binary::get(in, b.id);
    binary::get(in, b.stage);
    b.trigger = get_string(in);
    binary::get(in, first);
    binary::get(in, last);
    b.first_sample = first;
    b.last_sample = last;
    binary::get(in, b.tau_start);
    binary::get(in, b.tau_target);
    binary::get(in, b.gamma_start);
    binary::get(in, b.residual_gamma);
    binary::get(in, b.reached_target);
  }
  r.stage_names = get_strings(in);
  r.stage_end_reasons = get_strings(in);
  return r;
}

} // namespace

void write_runner_state(std::ostream &out, const RunnerState &s)
{
  binary::put_tag(out, "GCRUNNER", 3);
  put_response(out, s.response);
  binary::put_vector(out, s.stage_start_sample);
  binary::put(out, s.stage);
  binary::put(out, s.time);
  binary::put(out, s.tau_peak);
  binary::put(out, s.peak_sample);
  binary::put_vector(out, s.fired);
  binary::put(out, s.has_peak_state);
  binary::put_vector(out, s.kept_samples);
  binary::put_tag(out, "GCRUNEND", 1);
}

RunnerState read_runner_state(std::istream &in)
{
  RunnerState s;
  binary::expect_tag(in, "GCRUNNER", 3);
  s.response = get_response(in);
  binary::get_vector(in, s.stage_start_sample);
  binary::get(in, s.stage);
  binary::get(in, s.time);
  binary::get(in, s.tau_peak);
  binary::get(in, s.peak_sample);
  binary::get_vector(in, s.fired);
  binary::get(in, s.has_peak_state);
  binary::get_vector(in, s.kept_samples);
  binary::expect_tag(in, "GCRUNEND", 1);
  return s;
}

} // namespace geocomp

#include "common/AtomicFile.h"
#include "common/LoadingEngine.h"

#include <fstream>
#include <stdexcept>

namespace geocomp {

void LoadingEngine::write_state(std::ostream &, const EngineState &) const
{
  throw std::logic_error("the " + name() + " engine cannot write its state to a checkpoint");
}

std::unique_ptr<EngineState> LoadingEngine::read_state(std::istream &) const
{
  throw std::logic_error("the " + name() + " engine cannot read its state from a checkpoint");
}

} // namespace geocomp

namespace geocomp {

void write_program_checkpoint(const std::filesystem::path &file, const std::string &key, const RunnerState &runner,
                              const LoadingEngine &engine, const EngineState &current, const EngineState *peak,
                              const std::vector<const EngineState *> &kept, std::uint64_t counter)
{
  if (kept.size() != runner.kept_samples.size())
    throw std::invalid_argument("write_program_checkpoint: one kept state per RunnerState::kept_samples entry");
  write_atomically(file, [&](const std::filesystem::path &tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw std::runtime_error("cannot write checkpoint " + tmp.string());
    binary::put_tag(out, "GCPROGRM", 1);
    binary::put_vector(out, std::vector<char>(key.begin(), key.end()));
    write_runner_state(out, runner);
    engine.write_state(out, current);
    if (peak)
      engine.write_state(out, *peak);
    for (const EngineState *state : kept)
      engine.write_state(out, *state);
    binary::put(out, counter);
    binary::put_tag(out, "GCPRGEND", 1);
    out.flush();
    if (!out)
      throw std::runtime_error("writing checkpoint " + tmp.string() + " failed");
  });
}

std::optional<ProgramCheckpoint> read_program_checkpoint(const std::filesystem::path &file, const std::string &key,
                                                         const LoadingEngine &engine)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
    return std::nullopt;
  try {
    binary::expect_tag(in, "GCPROGRM", 1);
    std::vector<char> k;
    binary::get_vector(in, k);
    if (std::string(k.begin(), k.end()) != key)
      return std::nullopt;
    ProgramCheckpoint c;
    c.runner = read_runner_state(in);
    c.current = engine.read_state(in);
    if (c.runner.has_peak_state)
      c.peak = engine.read_state(in);
    for (std::size_t k = 0; k < c.runner.kept_samples.size(); ++k)
      c.kept.push_back(engine.read_state(in));
    binary::get(in, c.counter);
    binary::expect_tag(in, "GCPRGEND", 1);
    return c;
  } catch (const binary::StateError &) {
    return std::nullopt;
  }
}

} // namespace geocomp
