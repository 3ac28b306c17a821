#pragma once
// @sect3{Dynamic uniaxial test of S1's 6 x 9 mm plane-stress specimen}
//
// Why: S1 verifies its kinetic model on rectangular plane-stress specimens loaded in
// uniaxial compression and tension at 1e-3 ... 1e3 1/s, with inertia, taking the peak end
// load over the end area as the strength. This engine does that with deal.II.
//
// Discretization (docs/s1-kinetic-model.md, "Why explicit dynamics"):
//   - serial Triangulation<2>, Q1 elements (FESystem(FE_Q(1), 2)), 2 x 2 Gauss points,
//     plane stress, unit thickness; small strain (strains stay below 1 %);
//   - lumped (row-sum) mass M, central differences (leapfrog):
//       v_{n+1/2} = v_{n-1/2} + dt M^{-1} (f_ext - f_int(u_n)),  u_{n+1} = u_n + dt v_{n+1/2},
//     with dt = safety * h_min / c, c = sqrt(E / (rho (1 - nu^2))) - explicit is what S1's
//     own model is built for (the Wilkins correction and the relaxation of eq. (13) are
//     per-step updates), and at 1e2-1e3 1/s the time to fracture is a few wave transits,
//     so the step the waves need is the step the physics needs anyway;
//   - the strain increment of each step goes through the kinetic point at every Gauss point
//     (KineticNikolaevsky via plane_stress_step); f_int = sum_q B^T sigma JxW with B and
//     JxW computed once (the geometry never changes);
//   - ends: smooth rigid platens, u_y prescribed on the bottom and top edges
//     (velocities -+ epsdot H / 2: compression brings them together), u_x pinned at the
//     middle node of each end (or, with bonded platens, at every end node: S1 does not say
//     which), lateral edges free; the specimen starts at rest and the
//     platen speed rises as a half cosine over half of t_st (see below): an impulsive start
//     sends a front of amplitude rho c V from each platen, the two fronts meet mid-height
//     and double, and the specimen breaks there before the end load reaches its strength
//     (-8 % at 1e2 1/s for the concrete without the kinetic extension) - the smooth start
//     plays the part of a pulse shaper in a split Hopkinson bar test. The strain is the
//     platen gap change over H, whatever the speed history;
//   - slow rates use density (mass) scaling: the density rises until the time to the static
//     strength, t_st = sigma_st / (E epsdot), equals N wave transits H / c (N = 100 by
//     default). Inertial stresses scale with (transit / t_st)^2, so they stay below 1e-4
//     of the load there; T_r and T_f are material times and are not scaled. Rates with
//     t_st below N real transits (>= 1e1 1/s for S1's materials) run at the true density,
//     so all inertia at high rates is real;
//   - dt is also capped at t_st / 200, so that the fracture and relaxation times (a fraction
//     of t_st at 1e3 1/s) span many steps.
#include "continuum/kinetic/HomogeneousUniaxial.h"
#include "continuum/kinetic/KineticNikolaevsky.h"

#include <memory>
#include <vector>

namespace geocomp::dynamics {

using kinetic::KineticNikolaevsky;
using kinetic::LoadingMode;

struct SpecimenGeometry {
  double width = 6.0e-3;     ///< [m] (S1: 6 mm)
  double height = 9.0e-3;    ///< [m] (S1: 9 mm), the loading direction
  unsigned int cells_x = 8;  ///< even, so that a node sits at mid-width
  unsigned int cells_y = 12;
};

struct DynamicsControls {
  double time_step_safety = 0.5;        ///< dt = safety * h_min / c
  double quasi_static_transits = 100.0; ///< N of the density scaling
  double min_steps_to_static = 200.0;   ///< dt <= t_st / this: resolves T_f and T_r at high rates
  double stop_load_fraction = 0.5;      ///< stop once the load fell below this fraction of the peak
  double max_time_factor = 4.0;         ///< stop at max_time_factor * k_S1(epsdot) * t_st at the latest
  bool fixed_bottom = false;            ///< true: the bottom platen stays, the top one moves at epsdot H and the strength is its force
  double platen_rise_fraction = 0.5;    ///< platen speed ramps smoothly from 0 over this fraction of t_st (0: impulsive start)
  bool bonded_platens = false;          ///< true: u_x = 0 on every end node (rough, bonded platens); false: smooth
  unsigned int curve_samples = 200;     ///< samples of the load curve kept in the result
};

struct CurveSample {
  double time = 0.0, strain = 0.0, stress = 0.0; ///< nominal axial strain and end stress (tension positive)
};

struct SpecimenRunResult {
  double strain_rate = 0.0;
  double peak_stress = 0.0;     ///< largest |end stress| in the loading direction [Pa]
  double strain_at_peak = 0.0;  ///< |nominal strain| at the peak
  double density_scale = 1.0;   ///< rho_used / rho
  double time_step = 0.0;       ///< [s]
  long steps = 0;
  unsigned int fractured_points = 0, points = 0;
  std::vector<CurveSample> curve;
};

class ExplicitSpecimen {
public:
  ExplicitSpecimen(const KineticNikolaevsky &model, SpecimenGeometry geometry, DynamicsControls controls);
  ~ExplicitSpecimen();
  ExplicitSpecimen(const ExplicitSpecimen &) = delete;
  ExplicitSpecimen &operator=(const ExplicitSpecimen &) = delete;

  /// One test at a constant nominal strain rate epsdot > 0 [1/s].
  SpecimenRunResult run(LoadingMode mode, double strain_rate) const;

  unsigned int n_dofs() const;
  unsigned int n_points() const;

private:
  struct Mesh; // deal.II objects and the precomputed B matrices (ExplicitSpecimen.cpp)
  const KineticNikolaevsky &model_;
  SpecimenGeometry geometry_;
  DynamicsControls controls_;
  std::unique_ptr<Mesh> mesh_;
};

} // namespace geocomp::dynamics
