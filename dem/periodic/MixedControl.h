// @sect3{The MixedControl class: each component of L by strain rate or by stress}
//
// Why it exists: a stand-alone RVE test (isotropic compression to a pressure, triaxial
// shear at constant lateral stress) prescribes some components of the deformation and
// some of the stress, as Yade's PeriTriaxController does. Each component (a, b) of the
// velocity gradient L is either given ($L_{ab}$ prescribed, a strain rate in 1/s) or
// follows a target stress $\sigma^*_{ab}$ through a servo. The servo is a stiffness-scaled
// proportional law (Itasca's servo for walls, here on the cell's strain):
// $$ L_{ab} = \mathrm{clamp}\Big(\frac{g\,(\sigma^*_{ab} - \sigma_{ab})}{K_{ab}\,\Delta t},\ \pm\dot\varepsilon_{max}\Big)
//    \qquad\text{(servo)}, $$
// with $\sigma$ the contacts' elastic stress and $K_{ab}$ the cell's stiffness (CellStress.h), g < 1 the fraction of the error
// removed per step if the packing responded affinely (it relaxes, so the servo keeps
// pushing while the error lasts). Without contacts ($K_{ab} = 0$) the component moves at
// the largest rate toward the target. A shear component is best servoed through the upper
// triangle of L ($L_{ab}$, a < b, with $L_{ba} = 0$): H then stays upper triangular.
// Tension positive: a target $\sigma^* = -p$ above
// the current stress compresses the cell ($L_{aa} < 0$).
#pragma once

#include "dem/periodic/CellStress.h"

#include <array>

namespace geocomp::dem {

class MixedControl
{
public:
  enum class Mode { strain_rate, stress };

  struct Parameters
  {
    double gain = 0.2;              ///< g: share of the stress error removed per step
    double max_strain_rate = 1.0;   ///< [1/s] largest |L_ab| a servo may set
  };

  MixedControl() = default;
  explicit MixedControl(const Parameters& p);

  const Parameters& parameters() const { return p_; }
  void set_parameters(const Parameters& p);

  /// Component (a, b) of L prescribed: L_ab = rate [1/s].
  void set_strain_rate(int a, int b, double rate);
  /// Component (a, b) follows the target stress sigma*_ab [Pa] (tension positive).
  void set_stress(int a, int b, double target);
  /// Every component prescribed by L.
  void set_velocity_gradient(const Mat3& l);

  Mode mode(int a, int b) const { return mode_[index(a, b)]; }
  double target(int a, int b) const { return value_[index(a, b)]; }
  bool any_stress() const;

  /// The velocity gradient for the next step from the last stress and stiffness.
  Mat3 velocity_gradient(const CellStress& stress, double dt) const;

private:
  static int index(int a, int b) { return 3 * a + b; }

  Parameters p_{};
  std::array<Mode, 9> mode_{};
  std::array<double, 9> value_{};
};

}  // namespace geocomp::dem
