#include "compare/ShearBoxRuns.h"

#include "compare/RunFiles.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace geocomp::compare {

namespace {

const std::string summary_suffix = "-summary.txt";

fs::path summary_of(const fs::path& tsv)
{
  return tsv.parent_path() / (tsv.stem().string() + summary_suffix);
}

std::map<std::string, std::string> read_summary(const fs::path& path) { return read_run_summary(path); }

double number(const std::map<std::string, std::string>& kv, const std::string& key, const fs::path& file,
              bool required = true)
{
  const auto it = kv.find(key);
  if (it == kv.end()) {
    if (required) throw std::runtime_error(file.string() + ": no '" + key + "' in the run summary");
    return 0.0;
  }
  try {
    return std::stod(it->second);
  } catch (const std::exception&) {
    throw std::runtime_error(file.string() + ": '" + key + "' is not a number: " + it->second);
  }
}

// The curve's columns by their header names (U_m, lid_rise_m, tau_x_Pa, mu_b).
std::vector<ShearBoxCurvePoint> read_curve(const fs::path& tsv)
{
  std::ifstream in(tsv);
  if (!in) throw std::runtime_error(tsv.string() + ": cannot read the shear curve");
  std::string line;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream h(line);
    for (std::string name; h >> name;) header.push_back(name);
  }
  auto column = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    if (at == header.end()) throw std::runtime_error(tsv.string() + ": no column '" + name + "'");
    return std::size_t(at - header.begin());
  };
  const std::size_t cu = column("U_m"), cl = column("lid_rise_m"), ct = column("tau_x_Pa"), cm = column("mu_b");
  std::vector<ShearBoxCurvePoint> curve;
  std::vector<double> v(header.size());
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream r(line);
    for (double& x : v)
      if (!(r >> x)) throw std::runtime_error(tsv.string() + ": short row '" + line + "'");
    curve.push_back({v[cu], v[cl], v[ct], v[cm]});
  }
  if (curve.empty()) throw std::runtime_error(tsv.string() + ": no rows");
  return curve;
}

}  // namespace

double residual_mu_b(const std::vector<ShearBoxCurvePoint>& curve, double fraction)
{
  if (curve.empty()) return 0.0;
  const double from = (1.0 - fraction) * curve.back().shear;
  double sum = 0.0;
  std::size_t n = 0;
  for (const ShearBoxCurvePoint& p : curve)
    if (p.shear >= from) {
      sum += p.mu_b;
      ++n;
    }
  return sum / double(n);
}

ShearBoxRun read_shear_box_run(const fs::path& tsv)
{
  const fs::path sp = summary_of(tsv);
  const auto kv = read_summary(sp);
  ShearBoxRun r;
  r.name = tsv.stem().string();
  r.normal_stress = 1e3 * number(kv, "normal_stress_kPa", sp);
  r.contact_friction = number(kv, "contact_friction", sp);
  r.seed = std::uint64_t(number(kv, "seed", sp, false));
  r.box_length = number(kv, "box_length_m", sp, false);
  r.shear_speed = number(kv, "shear_speed_m_s", sp, false);
  r.clumps = std::size_t(number(kv, "clumps", sp));
  r.void_ratio = number(kv, "void_ratio_at_shear_start", sp);
  r.inertial_number = number(kv, "inertial_number", sp);
  r.peak_mu_b = number(kv, "peak_mu_b", sp);
  r.shear_at_peak = 1e-3 * number(kv, "shear_at_peak_mm", sp);
  r.max_contraction = 1e-3 * number(kv, "max_contraction_mm", sp);
  r.final_dilation = 1e-3 * number(kv, "final_dilation_mm", sp);
  r.seconds = number(kv, "prepare_seconds", sp) + number(kv, "shear_seconds", sp);
  r.curve = read_curve(tsv);
  r.residual_mu_b = residual_mu_b(r.curve);
  return r;
}

std::vector<ShearBoxRun> read_shear_box_runs(const fs::path& dir)
{
  std::vector<fs::path> tsvs;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".tsv" && fs::exists(summary_of(e.path())))
      tsvs.push_back(e.path());
  std::sort(tsvs.begin(), tsvs.end());
  std::vector<ShearBoxRun> runs;
  for (const fs::path& p : tsvs) runs.push_back(read_shear_box_run(p));
  return runs;
}

}  // namespace geocomp::compare
