#pragma once
// @sect3{One triaxial test, two boundaries: the curve of a wall specimen and of a periodic cell}
//
// Why it exists: the comparison of issue 35 puts the RVE's triaxial curve beside the wall
// specimen's, so both must be measured alike. The test: the lateral stresses held at -p (the
// walls' servo, dem/program/ServoControl.h; the cell's, dem/periodic/MixedControl.h), the
// axial direction z shortened at `strain_rate`, until the axial (logarithmic) strain reaches
// `axial_strain`; a point every `record_strain` of axial strain:
//  - axial strain $\varepsilon_a = -\ln(L_z/L_{z,0})$, compression positive;
//  - volumetric strain $\varepsilon_v = \ln(V/V_0)$, tension positive (contraction < 0);
//  - deviator $q = \tfrac12(\sigma_{xx} + \sigma_{yy}) - \sigma_{zz}$ and mean pressure
//    $p = -\mathrm{tr}\,\sigma/3$ (tension-positive stresses; both > 0 in compression), at the
//    point's instant: the walls' stress (force over current face area), the cell's Love-Weber stress;
//  - the largest lateral error $|\sigma_{bb} + p_0|/p_0$;
//  - the inertial number $I = \dot\gamma\,\bar d\sqrt{\rho/p}$ (GDR MiDi; DEM-NOTES section 6) with
//    $\dot\gamma = \dot\varepsilon_{lat} - \dot\varepsilon_{zz}$ from the logarithmic strains of the
//    point and the one before (mean lateral strain $(\varepsilon_v + \varepsilon_a)/2$), the same
//    formula for both.
// One difference is the engines': the wall box drives z at a constant engineering rate
// (dem/program: the edge $L_{z,0}(1 - \dot\varepsilon t)$), the cell at a constant logarithmic
// rate ($L_{zz} = -\dot\varepsilon$); at 10 % the walls' logarithmic rate is 1.105 times the cell's.
#include "dem/DemSystem.h"
#include "dem/periodic/PeriodicCell.h"

#include <vector>

namespace geocomp::coupled {

struct TriaxialTest {
  double pressure = 1e5;        ///< p_0 [Pa] of the lateral stresses, compression positive
  double strain_rate = 1.0;     ///< [1/s] axial shortening rate
  double axial_strain = 0.10;   ///< logarithmic, compression positive: the end
  double record_strain = 1e-3;  ///< axial strain between points
};

struct TriaxialPoint {
  double time = 0.0;               ///< [s] since the start of the test
  double axial_strain = 0.0;       ///< compression positive
  double volumetric_strain = 0.0;  ///< tension positive
  double deviator = 0.0;           ///< q [Pa]
  double pressure = 0.0;           ///< p [Pa]
  double lateral_error = 0.0;
  double inertial_number = 0.0;
  double stress_ratio() const { return pressure > 0.0 ? deviator / pressure : 0.0; }
};

using TriaxialCurve = std::vector<TriaxialPoint>;

/// The test on a wall specimen (walls 0..5 the box faces; its box at the call is the
/// reference) with the wall box's own servo (the case-file defaults) and the specimen's local damping.
TriaxialCurve triaxial_on_walls(dem::DemSystem specimen, const TriaxialTest &test);

/// The test on a periodic cell (PeriodicProgram.h shear_triaxial, axis z), with the cell's
/// own servo and damping as they are set.
TriaxialCurve triaxial_on_cell(dem::PeriodicCell &cell, const TriaxialTest &test);

} // namespace geocomp::coupled
