#include "compare/CrushRuns.h"

#include "compare/RunFiles.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace geocomp::compare {

namespace {

const std::string summary_suffix = "_summary.tsv";

std::map<std::string, std::string> read_summary(const fs::path& path) { return read_run_summary(path); }

/// A table with a header line of tab-separated names and numeric rows; empty when the
/// file is missing and not `required`.
CrushTable read_table(const fs::path& path, bool required)
{
  CrushTable t;
  std::ifstream in(path);
  if (!in) {
    if (required) throw std::runtime_error(path.string() + ": cannot read the table");
    return t;
  }
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path.string() + ": no header line");
  std::istringstream h(line);
  for (std::string name; std::getline(h, name, '\t');) t.columns.push_back(name);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream r(line);
    std::vector<double> row(t.columns.size());
    for (double& x : row)
      if (!(r >> x)) throw std::runtime_error(path.string() + ": short row '" + line + "'");
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace

std::size_t CrushTable::column(const std::string& name, const fs::path& file) const
{
  const auto at = std::find(columns.begin(), columns.end(), name);
  if (at == columns.end()) throw std::runtime_error(file.string() + ": no column '" + name + "'");
  return std::size_t(at - columns.begin());
}

double CrushRun::number(const std::string& key, double fallback) const
{
  const auto it = summary.find(key);
  if (it == summary.end()) return fallback;
  try {
    return std::stod(it->second);
  } catch (const std::exception&) {
    return fallback;
  }
}

CrushRun read_crush_run(const fs::path& summary)
{
  const std::string file = summary.filename().string();
  if (file.size() <= summary_suffix.size() || file.compare(file.size() - summary_suffix.size(), summary_suffix.size(),
                                                           summary_suffix) != 0)
    throw std::runtime_error(summary.string() + ": not a <case>" + summary_suffix);
  CrushRun r;
  r.name = file.substr(0, file.size() - summary_suffix.size());
  r.summary = read_summary(summary);
  auto text = [&](const std::string& key) {
    const auto it = r.summary.find(key);
    if (it == r.summary.end()) throw std::runtime_error(summary.string() + ": no '" + key + "' in the run summary");
    return it->second;
  };
  r.title = text("title");
  r.program = text("program");
  r.breakage_mode = text("breakage_mode");
  r.cut_point = text("cut_point");
  const fs::path base = summary.parent_path() / r.name;
  r.curve = read_table(base.string() + "_curve.tsv", true);
  r.gradation = read_table(base.string() + "_gradation.tsv", true);
  r.fragments = read_table(base.string() + "_fragments.tsv", false);
  for (const char* state : {"seated", "peak", "final"}) {
    const fs::path svg = base.string() + "_polar_" + state + ".svg";
    if (fs::exists(svg)) r.roses.push_back(svg);
  }
  return r;
}

std::vector<CrushRun> read_crush_runs(const fs::path& dir)
{
  std::vector<fs::path> summaries;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (e.is_regular_file() && f.size() > summary_suffix.size() &&
        f.compare(f.size() - summary_suffix.size(), summary_suffix.size(), summary_suffix) == 0 &&
        f.find("_polar_summary.tsv") == std::string::npos)
      summaries.push_back(e.path());
  }
  std::sort(summaries.begin(), summaries.end());
  std::vector<CrushRun> runs;
  for (const fs::path& s : summaries)
    if (read_summary(s).count("program")) runs.push_back(read_crush_run(s));
  return runs;
}

std::vector<SeedFragments> fragments_by_seed(const CrushRun& run, double bin_mm)
{
  std::vector<SeedFragments> out;
  if (!run.single() || run.fragments.rows.empty()) return out;
  const fs::path file = run.name + "_fragments.tsv";
  const std::size_t cd = run.fragments.column("child_diameter_mm", file);
  const std::size_t cr = run.fragments.column("relative_size", file);
  const auto at = std::find(run.fragments.columns.begin(), run.fragments.columns.end(), "run");
  const std::size_t crun = at == run.fragments.columns.end() ? run.fragments.columns.size() : std::size_t(at - run.fragments.columns.begin());
  double d_max = 0.0;
  int runs = 1;
  for (const auto& row : run.fragments.rows) {
    d_max = std::max(d_max, row[cd]);
    if (crun < row.size()) runs = std::max(runs, int(row[crun]) + 1);
  }
  const std::size_t bins = std::size_t(std::floor(d_max / bin_mm)) + 1;
  out.resize(std::size_t(runs));
  for (int k = 0; k < runs; ++k) {
    out[std::size_t(k)].run = k;
    out[std::size_t(k)].percent.assign(bins, 0.0);
  }
  for (const auto& row : run.fragments.rows) {
    SeedFragments& s = out[crun < row.size() ? std::size_t(row[crun]) : 0];
    ++s.fragments;
    s.mean_relative_size += row[cr];
    s.percent[std::min(bins - 1, std::size_t(std::floor(row[cd] / bin_mm)))] += 1.0;
  }
  for (SeedFragments& s : out) {
    if (s.fragments == 0) continue;
    s.mean_relative_size /= double(s.fragments);
    for (double& p : s.percent) p *= 100.0 / double(s.fragments);
  }
  return out;
}

double expected_mean_relative_size(int p)
{
  if (p < 1 || p > 3) throw std::invalid_argument("expected_mean_relative_size: cut power 1, 2 or 3");
  const double q = 1.0 / 3.0, P = double(p);
  const double e_x = 1.0 / (1.0 + P * q);                                                          // E[x^q]
  const double e_1mx = std::tgamma(1.0 / P) * std::tgamma(q + 1.0) / std::tgamma(1.0 / P + q + 1.0) / P;  // E[(1-x)^q]
  return std::pow(0.5 * (e_x + e_1mx), 3);
}

}  // namespace geocomp::compare
