// @sect3{How far an unloading branch has come back}
//
// Why it exists: an unloading branch (S0 Fig. 2) is measured along the deviator it leaves
// with, signed, so that a path overshooting its target through zero still stops:
//   tau_D(s) = tau_o dev(s):d / (d:d),   d = dev(s_o),   tau_o = tau_max(s_o);
// an isotropic origin (d = 0) has no deviator to follow, and tau_max itself is used. The
// target is tau_D of the stress where the stage started, or the stage's `unload to` value.
// ProgramRunner plays branches with it and the LIGGGHTS import records them with it.
#pragma once

#include "common/LoadingProgram.h"
#include "common/Tensor.h"

namespace geocomp {

class UnloadingMeasure {
public:
  explicit UnloadingMeasure(const Tensor3 &origin)
    : d_(origin - mean_stress(origin) * Tensor3::Identity()), dd_((d_.array() * d_.array()).sum()),
      tau_o_(tau_max(origin))
  {}

  /// tau_D of `stress`.
  double operator()(const Tensor3 &stress) const
  {
    const Tensor3 dev = stress - mean_stress(stress) * Tensor3::Identity();
    return dd_ > 0.0 ? tau_o_ * (dev.array() * d_.array()).sum() / dd_ : tau_max(stress);
  }

  /// The level the branch of `stage` unloads to, its stage having started at `stage_start`.
  double target(const Stage &stage, const Tensor3 &stage_start) const
  {
    return stage.unload_to_start ? (*this)(stage_start) : stage.unload_to_tau;
  }

private:
  Tensor3 d_;
  double dd_;
  double tau_o_;
};

} // namespace geocomp
