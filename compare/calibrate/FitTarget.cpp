#include "compare/calibrate/FitTarget.h"

#include "common/ProgramRunner.h"
#include "common/ResponseFile.h"
#include "common/Tensor.h"
#include "common/case/CaseParameters.h"
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
  for (auto &s : t.program.stages)
    s.unload_at.clear();
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

std::size_t residual_count(const FitTarget &target) { return 2 * target.samples.size(); }

void residuals(const FitTarget &target, const Response &model, double volumetric_weight, double *out)
{
  const auto &m = model.samples;
  std::size_t j = 0;
  for (std::size_t k : target.samples) {
    const ResponseSample &s = target.response.samples[k];
    while (j + 1 < m.size() && m[j + 1].time < s.time)
      ++j;
    double q = deviator(m.back().stress), v = volumetric_strain(m.back().strain);
    if (j + 1 < m.size() && m[j].time <= s.time) {
      const double a = (s.time - m[j].time) / (m[j + 1].time - m[j].time);
      q = (1 - a) * deviator(m[j].stress) + a * deviator(m[j + 1].stress);
      v = (1 - a) * volumetric_strain(m[j].strain) + a * volumetric_strain(m[j + 1].strain);
    }
    *out++ = target.weight * (q - deviator(s.stress)) / target.q_scale;
    *out++ = target.weight * volumetric_weight * (v - volumetric_strain(s.strain)) / target.volume_scale;
  }
}

} // namespace geocomp::calibration
