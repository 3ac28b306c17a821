#include "dem/liggghts/LiggghtsSamples.h"

#include "common/ProgramRunner.h"
#include "common/UnloadingMeasure.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace geocomp::dem {

namespace fs = std::filesystem;

namespace {

const char *const kWall[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};

/// The rows of samples.txt by column name.
struct Table
{
  std::map<std::string, std::size_t> column;
  std::vector<std::vector<double>> rows;
  double at(std::size_t row, const std::string &name) const { return rows[row][column.at(name)]; }
};

Table read_table(const fs::path &file)
{
  std::ifstream in(file);
  if (!in)
    throw LiggghtsSamplesError(file.string() + ": not found: run LIGGGHTS on the deck in its folder first "
                                               "(liggghts -in in.geocomp)");
  Table t;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream l(line);
    if (line.rfind("# ", 0) == 0) {
      l.ignore(2);
      for (std::string name; l >> name;)
        t.column.emplace(name, t.column.size());
      continue;
    }
    std::vector<double> row;
    for (double v; l >> v;)
      row.push_back(v);
    if (row.empty())
      continue;
    if (t.column.empty() || row.size() != t.column.size() || !l.eof())
      throw LiggghtsSamplesError(file.string() + ":" + std::to_string(n) + ": expected " +
                                 std::to_string(t.column.size()) + " numbers after the '# t stage ...' header line");
    t.rows.push_back(std::move(row));
  }
  const char *needed[] = {"t", "stage", "Lx", "Ly", "Lz", "ke", "erot", "Fz_zhi"};
  for (const char *name : needed)
    if (!t.column.count(name))
      throw LiggghtsSamplesError(file.string() + ": no column '" + name + "': not written by geocomp's deck");
  if (t.rows.empty())
    throw LiggghtsSamplesError(file.string() + ": no sample: the run did not start");
  return t;
}

ResponseSample sample_of(const Table &t, std::size_t k)
{
  ResponseSample s;
  s.time = t.at(k, "t");
  s.stage = int(t.at(k, "stage"));
  s.branch = t.column.count("branch") ? int(t.at(k, "branch")) : 0;
  const char *edge[3] = {"Lx", "Ly", "Lz"};
  Vector3 L;
  for (int a = 0; a < 3; ++a) {
    L[a] = t.at(k, edge[a]);
    s.strain(a, a) = L[a] / t.at(0, edge[a]) - 1.0;
  }
  Tensor3 sigma = Tensor3::Zero();
  for (int a = 0; a < 3; ++a) {
    const double area = L[(a + 1) % 3] * L[(a + 2) % 3];
    for (int b = 0; b < 3; ++b) {
      const std::string f = std::string("F") + "xyz"[b] + "_";
      sigma(b, a) = -(t.at(k, f + kWall[2 * a + 1]) - t.at(k, f + kWall[2 * a])) / (2.0 * area);
    }
  }
  s.stress = 0.5 * (sigma + sigma.transpose());
  s.stress_mean = s.stress;
  s.extras = {t.at(k, "ke"), t.at(k, "erot")};
  return s;
}

/// Per stage, "stop" or "max-duration" from stages.txt.
std::vector<std::string> stage_ends(const fs::path &file)
{
  std::ifstream in(file);
  if (!in)
    throw LiggghtsSamplesError(file.string() + ": not found: the run did not end a stage");
  std::vector<std::string> ends;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream l(line);
    std::size_t stage = 0;
    std::string how;
    if (!(l >> stage >> how) || stage != ends.size() || (how != "stop" && how != "max-duration"))
      throw LiggghtsSamplesError(file.string() + ":" + std::to_string(n) + ": expected '" +
                                 std::to_string(ends.size()) + " stop' or '" + std::to_string(ends.size()) +
                                 " max-duration'");
    ends.push_back(how);
  }
  return ends;
}

/// branches.txt: where each branch left the main path and how it ended.
struct BranchLine
{
  int id = 0, stage = 0, trigger = 0;
  double time = 0.0;
  std::string end; ///< "target", "max-duration", or empty (the branch's run did not end)
};

std::map<int, BranchLine> branch_lines(const fs::path &file)
{
  std::map<int, BranchLine> lines;
  std::ifstream in(file);
  std::string line;
  for (int n = 1; in && std::getline(in, line); ++n) { // no file: a deck without branches
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream l(line);
    std::string what;
    BranchLine b;
    l >> what >> b.id;
    bool ok = bool(l) && b.id >= 1;
    if (ok && what == "start") {
      ok = bool(l >> b.stage >> b.trigger >> b.time) && !lines.count(b.id);
      if (ok)
        lines[b.id] = b;
    } else if (ok && what == "end") {
      std::string how;
      ok = bool(l >> how) && lines.count(b.id) && (how == "target" || how == "max-duration");
      if (ok)
        lines[b.id].end = how;
    } else
      ok = false;
    if (!ok)
      throw LiggghtsSamplesError(file.string() + ":" + std::to_string(n) +
                                 ": expected 'start ID STAGE TRIGGER TIME' or 'end ID target|max-duration'");
  }
  return lines;
}

/// The main-path row of `stage` at `time` (where a branch left), or none.
std::size_t origin_row(const std::vector<ResponseSample> &main, int stage, double time)
{
  std::size_t best = main.size();
  for (std::size_t k = 0; k < main.size(); ++k)
    if (main[k].stage == stage && std::abs(main[k].time - time) <= 1e-9 * std::max(1.0, std::abs(time)))
      best = k;
  return best;
}

/// The samples in geocomp's order (each branch right after the main-path sample it leaves
/// from, as the ProgramRunner records it) and the branch records (ProgramRunner::run_branch's).
void place_branches(Response &r, const std::vector<ResponseSample> &rows, const std::map<int, BranchLine> &lines,
                    const LoadingProgram &program, const fs::path &file)
{
  std::vector<ResponseSample> main;
  for (const ResponseSample &s : rows)
    if (s.branch == 0)
      main.push_back(s);
  std::map<std::size_t, std::vector<int>> leaving; // main-path row -> branch ids, in id order
  for (const auto &[id, b] : lines) {
    const std::size_t at = origin_row(main, b.stage, b.time);
    if (at == main.size() || b.stage >= int(program.stages.size()) ||
        b.trigger >= int(program.stages[b.stage].unload_at.size()))
      throw LiggghtsSamplesError(file.string() + ": branch " + std::to_string(id) +
                                 " leaves from no main-path sample of its stage, or names no trigger of the case");
    leaving[at].push_back(id);
  }
  // Where each stage began in r.samples: the last main-path sample before it (sample 0 for
  // the first stage).
  std::vector<std::size_t> stage_start;
  std::size_t last_main = 0;
  for (std::size_t k = 0; k < main.size(); ++k) {
    if (stage_start.size() <= std::size_t(main[k].stage))
      stage_start.resize(main[k].stage + 1, last_main);
    r.samples.push_back(main[k]);
    const std::size_t origin = last_main = r.samples.size() - 1;
    for (int id : leaving[k]) {
      const BranchLine &line = lines.at(id);
      const Stage &stage = program.stages[line.stage];
      BranchRecord b;
      b.id = id;
      b.stage = line.stage;
      b.trigger = stage.unload_at[line.trigger].text;
      b.first_sample = origin;
      const ResponseSample o = r.samples[origin], start = r.samples[stage_start[line.stage]];
      b.tau_start = tau_max(o.stress);
      b.gamma_start = gamma_max(o.strain);
      b.tau_target = UnloadingMeasure(o.stress).target(stage, start.stress);
      for (const ResponseSample &s : rows)
        if (s.branch == id)
          r.samples.push_back(s);
      b.last_sample = r.samples.size() - 1;
      b.residual_gamma = gamma_max(r.samples.back().strain - start.strain);
      b.reached_target = line.end == "target";
      r.branches.push_back(b);
    }
  }
  std::sort(r.branches.begin(), r.branches.end(), [](const BranchRecord &a, const BranchRecord &b) { return a.id < b.id; });
}

} // namespace

std::vector<std::string> liggghts_branch_decks(const fs::path &dir)
{
  std::vector<std::string> decks;
  for (const auto &[id, b] : branch_lines(dir / "branches.txt"))
    decks.push_back("in.branch_" + std::to_string(b.stage + 1) + "_" + std::to_string(b.trigger + 1));
  return decks;
}

Response read_liggghts_samples(const fs::path &dir, const LoadingProgram &program)
{
  const Table t = read_table(dir / "samples.txt");
  Response r;
  r.engine = "liggghts";
  r.interval_means = false;
  r.extras = {{"translational_kinetic_energy", "J", "sum of m v^2 / 2 over the spheres (LIGGGHTS ke)"},
              {"rotational_kinetic_energy", "J", "sum of I w^2 / 2 over the spheres (compute erotate/sphere)"}};
  std::vector<ResponseSample> rows;
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    rows.push_back(sample_of(t, k));
  place_branches(r, rows, branch_lines(dir / "branches.txt"), program, dir / "branches.txt");
  const std::vector<std::string> ends = stage_ends(dir / "stages.txt");
  for (std::size_t k = 0; k < ends.size() && k < program.stages.size(); ++k) {
    const Stage &stage = program.stages[k];
    r.stage_names.push_back(stage.name);
    const ResponseSample *last = nullptr;
    double start = 0.0; // the stage starts at the last sample of the stage before it
    for (const ResponseSample &s : r.samples) {
      if (s.branch != 0)
        continue;
      if (s.stage < int(k))
        start = s.time;
      if (s.stage == int(k))
        last = &s;
    }
    std::string reason = "max duration";
    if (ends[k] == "stop" && last) {
      ConditionContext ctx;
      ctx.stage = &stage;
      ctx.stage_start_time = start;
      for (const Condition &c : stage.stop_any)
        if (holds(c, *last, ctx)) {
          reason = c.text;
          break;
        }
    }
    r.stage_end_reasons.push_back(reason);
  }
  return r;
}

} // namespace geocomp::dem
