#include "compare/calibrate/FitTarget.h"

#include "common/ProgramRunner.h"
#include "common/ResponseFile.h"
#include "common/Tensor.h"
#include "compare/case/CaseDescription.h"
#include "compare/calibrate/FreeParameters.h"
#include "continuum/driver/MaterialPointEngine.h"

#include <algorithm>
#include <cmath>

namespace geocomp::calibration {

double deviator(const Tensor3 &stress)
{
  const Tensor3 s = stress - mean_stress(stress) * Tensor3::Identity();
  return std::sqrt(1.5 * (s.array() * s.array()).sum());
}

FitTarget make_target(std::string name, Response response, LoadingProgram program, double initial_stress,
                      unsigned substeps, double weight)
{
  FitTarget t;
  t.name = std::move(name);
  t.response = std::move(response);
  t.program = std::move(program);
  for (auto &s : t.program.stages) { // the fit replays the main path only
    s.unload_at.clear();
    s.locate_elastic_limit = false; // (its bisection needs branches)
  }
  t.initial_stress = initial_stress;
  t.substeps = substeps;
  t.weight = weight;
  double q_max = 0.0, v_min = 0.0, v_max = 0.0;
  const auto &samples = t.response.samples;
  for (std::size_t k = 1; k < samples.size(); ++k)
    if (samples[k].branch == 0) {
      t.samples.push_back(k);
      q_max = std::max(q_max, deviator(samples[k].stress));
      const double v = volumetric_strain(samples[k].strain);
      v_min = std::min(v_min, v);
      v_max = std::max(v_max, v);
    }
  if (t.samples.size() < 3)
    throw CalibrationError(t.name, t.name + ": fewer than 3 main-path samples to fit");
  t.q_scale = q_max > 0.0 ? q_max : 1.0;
  t.volume_scale = std::max(v_max - v_min, 1e-3);
  return t;
}

FitTarget load_target(const std::filesystem::path &file, double weight)
{
  RunMeta meta;
  Response r;
  try {
    r = read_response(file, &meta);
  } catch (const std::exception &e) {
    throw CalibrationError(file.string(), file.string() + ": not a readable results file: " + e.what());
  }
  CaseDescription c;
  try {
    c = parse_case(meta.case_text, meta.case_file.empty() ? file.string() : meta.case_file);
  } catch (const std::exception &e) {
    throw CalibrationError(file.string(), file.string() + ": the case stored in it does not parse: " + e.what());
  }
  return make_target(file.string(), std::move(r), c.program, -c.specimen.isotropic_pressure,
                     c.continuum.point_substeps, weight);
}

Response simulate(const FitTarget &target, const continuum::MaterialParameters &material)
{
  continuum::MaterialPointParameters p;
  p.initial_stress = target.initial_stress;
  p.substeps_per_advance = target.substeps;
  p.localization_directions = 10; // the least: the indicator is not fitted
  continuum::MaterialPointEngine engine(material, p);
  return ProgramRunner(target.program, engine).run();
}

std::vector<ResidualQuantity> fitted_quantities(const CalibrationParameters &c)
{
  std::vector<ResidualQuantity> out;
  for (const FittedQuantity &f : c.quantities) {
    ResidualQuantity q;
    q.name = f.name;
    q.weight = f.weight;
    if (f.name == "q")
      q.kind = ResidualQuantity::Kind::Deviator;
    else if (f.name == "p")
      q.kind = ResidualQuantity::Kind::MeanStress;
    else if (f.name == "eps_v")
      q.kind = ResidualQuantity::Kind::Volumetric;
    else
      throw CalibrationError("calibration/quantities", "'" + f.name + "' is not a fitted quantity (q, p, eps_v)");
    out.push_back(q);
  }
  if (out.empty())
    throw CalibrationError("calibration/quantities", "no quantity to fit (q, p, eps_v)");
  return out;
}

std::vector<ResidualQuantity> all_quantities()
{
  return {{ResidualQuantity::Kind::Deviator, 1.0, "q"}, {ResidualQuantity::Kind::MeanStress, 1.0, "p"},
          {ResidualQuantity::Kind::Volumetric, 1.0, "eps_v"}};
}

std::size_t residual_count(const FitTarget &target, std::size_t quantities)
{
  return quantities * target.samples.size();
}

namespace {
double value_of(ResidualQuantity::Kind kind, const ResponseSample &s)
{
  switch (kind) {
  case ResidualQuantity::Kind::Deviator: return deviator(s.stress);
  case ResidualQuantity::Kind::MeanStress: return mean_stress(s.stress);
  case ResidualQuantity::Kind::Volumetric: return volumetric_strain(s.strain);
  }
  return 0.0;
}
} // namespace

void residuals(const FitTarget &target, const Response &model, const std::vector<ResidualQuantity> &quantities,
               double *out)
{
  const auto &m = model.samples;
  std::size_t j = 0;
  for (std::size_t k : target.samples) {
    const ResponseSample &s = target.response.samples[k];
    while (j + 1 < m.size() && m[j + 1].time < s.time)
      ++j;
    // Linear in time between the model's samples j and j + 1; held at its last sample.
    const bool inside = j + 1 < m.size() && m[j].time <= s.time;
    const double a = inside ? (s.time - m[j].time) / (m[j + 1].time - m[j].time) : 0.0;
    for (const ResidualQuantity &q : quantities) {
      const double model_value =
        inside ? (1 - a) * value_of(q.kind, m[j]) + a * value_of(q.kind, m[j + 1]) : value_of(q.kind, m.back());
      const double scale = q.kind == ResidualQuantity::Kind::Volumetric ? target.volume_scale : target.q_scale;
      *out++ = target.weight * q.weight * (model_value - value_of(q.kind, s)) / scale;
    }
  }
}

} // namespace geocomp::calibration
