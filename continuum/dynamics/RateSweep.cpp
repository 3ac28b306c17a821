#include "continuum/dynamics/RateSweep.h"

namespace geocomp::dynamics {

double s1_strength_factor(LoadingMode mode, double strain_rate)
{
  return mode == LoadingMode::compression ? kinetic::compressive_strength_factor(strain_rate)  // S1 eq. (14)
                                          : kinetic::tensile_strength_factor(strain_rate);     // S1 eq. (15)
}

std::vector<RateSweepRow> run_rate_sweep(const RateSweepSetup &setup,
                                         const std::function<void(const RateSweepRow &)> &progress)
{
  std::vector<RateSweepRow> rows;
  const double strength = setup.mode == LoadingMode::compression ? setup.material.compressive_strength
                                                                 : setup.material.tensile_strength;
  for (const bool kinetic : setup.kinetic_modes) {
    const KineticNikolaevsky model(setup.material, kinetic);
    const ExplicitSpecimen specimen(model, setup.geometry, setup.controls);
    for (const double rate : setup.strain_rates) {
      RateSweepRow row;
      row.kinetic = kinetic;
      row.strain_rate = rate;
      row.run = specimen.run(setup.mode, rate);
      row.normalized_strength = row.run.peak_stress / strength;
      row.s1_fit = s1_strength_factor(setup.mode, rate);
      row.point_normalized_strength = kinetic::run_uniaxial_point(model, setup.mode, rate).peak_stress / strength;
      rows.push_back(row);
      if (progress)
        progress(row);
    }
  }
  return rows;
}

} // namespace geocomp::dynamics
