// @sect3{Stand-alone RVE programs: isotropic compression, then triaxial shear}
//
// Why it exists: before an RVE is trusted at a quadrature point it must answer the
// element tests by itself, under mixed control (MixedControl.h), as Yade's
// PeriTriaxController runs them:
//  - compress_isotropic(): the three normal stresses follow $\sigma^* = -p$ (tension
//    positive), the shear stresses follow zero through the upper triangle of L (the
//    lower one held at zero, so H stays upper triangular); done when every normal
//    stress is within the tolerance of $-p$, the shear stresses below tolerance times p,
//    and the unbalanced-force ratio below its threshold, all at one check;
//  - shear_triaxial(): $L_{aa} = -\dot\varepsilon$ along the axial axis a (compression),
//    the two lateral normal stresses held at $-p$ and the shear stresses at zero by the
//    servo, until the axial (logarithmic) strain $\varepsilon_a = -\ln(|h_a|/|h_{a,0}|)$
//    reaches its end (refused when the servo's largest rate is below the axial rate: the
//    lateral stresses could not follow). Recorded every `record_interval` steps: $\varepsilon_a$, the
//    volumetric strain $\ln(V/V_0)$ (tension positive), the deviator
//    $q = \tfrac12(\sigma_{bb} + \sigma_{cc}) - \sigma_{aa}$ (positive when the axial
//    stress is the more compressive), the mean pressure and the largest lateral error.
#pragma once

#include "dem/periodic/PeriodicCell.h"

#include <cstdint>
#include <vector>

namespace geocomp::dem {

struct IsotropicCompression
{
  double pressure = 0.0;              ///< p [Pa], compression positive
  double tolerance = 0.01;            ///< relative stress error
  double unbalanced = 0.01;           ///< largest unbalanced-force ratio
  std::uint64_t check_interval = 100; ///< steps between checks
  std::uint64_t max_steps = 200000;
};

struct CompressionResult
{
  bool converged = false;
  std::uint64_t steps = 0;
  Mat3 stress = Mat3::Zero();         ///< [Pa] at the end
  double unbalanced = 0.0;
  double packing_fraction = 0.0;
};

CompressionResult compress_isotropic(PeriodicCell& cell, const IsotropicCompression& c);

struct TriaxialShear
{
  int axis = 2;                        ///< the axial direction a
  double lateral_pressure = 0.0;       ///< p [Pa], compression positive
  double strain_rate = 0.0;            ///< [1/s] axial compression rate (> 0)
  double axial_strain = 0.0;           ///< end of the test (> 0, compression)
  std::uint64_t record_interval = 100;
};

struct TriaxialRecord
{
  double axial_strain = 0.0;       ///< compression positive
  double volumetric_strain = 0.0;  ///< ln(V / V0), tension positive
  double deviator = 0.0;           ///< q [Pa]
  double pressure = 0.0;           ///< [Pa], compression positive
  double lateral_error = 0.0;      ///< max |sigma_bb + p| / p over the lateral axes
};

std::vector<TriaxialRecord> shear_triaxial(PeriodicCell& cell, const TriaxialShear& t);

}  // namespace geocomp::dem
