#include "dem/liggghts/LiggghtsSamples.h"

#include "common/ProgramRunner.h"

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

} // namespace

Response read_liggghts_samples(const fs::path &dir, const LoadingProgram &program)
{
  const Table t = read_table(dir / "samples.txt");
  Response r;
  r.engine = "liggghts";
  r.interval_means = false;
  r.extras = {{"translational_kinetic_energy", "J", "sum of m v^2 / 2 over the spheres (LIGGGHTS ke)"},
              {"rotational_kinetic_energy", "J", "sum of I w^2 / 2 over the spheres (compute erotate/sphere)"}};
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    r.samples.push_back(sample_of(t, k));
  const std::vector<std::string> ends = stage_ends(dir / "stages.txt");
  for (std::size_t k = 0; k < ends.size() && k < program.stages.size(); ++k) {
    const Stage &stage = program.stages[k];
    r.stage_names.push_back(stage.name);
    const ResponseSample *last = nullptr;
    double start = 0.0; // the stage starts at the last sample of the stage before it
    for (const ResponseSample &s : r.samples) {
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
