#pragma once
// @sect3{The RveMaterialFactory class: an FE mesh of RVEs and its imperfection}
//
// Why it exists: the FE cube asks its MaterialFactory (continuum/driver/Materials.h) for
// the base material of its points and, inside its imperfection, for a weaker variant: the
// plasticity models lower their cohesion by `cohesion_factor`. A granular RVE has no
// cohesion to lower; its weak variant is the same prepared cell whose grains slide at a
// lower friction coefficient,
// $$ \mu_{\text{weak}} = f\,\mu, \qquad f = \text{the imperfection factor} \in (0, 1], $$
// the same packing at the same stress (the contacts are re-evaluated with mu_weak, so the
// weak cell starts from the same network, tangential forces capped at the new cone), which
// yields first under the same program and so seeds a band where the zone is. The crack
// band's `softening_scale` has no meaning for a cell - its softening is the grains' own -
// and is ignored. Each variant's cell is made once, at the cube's set-up.
#include "continuum/driver/Materials.h"
#include "coupled/RveMaterial.h"

#include <memory>

namespace geocomp::coupled {

class RveMaterialFactory : public continuum::MaterialFactory {
public:
  /// @param[in] base the material of every point outside the imperfection.
  explicit RveMaterialFactory(std::shared_ptr<const RveMaterial> base);
  /// The base material (cohesion_factor = 1), or an RVE of the same cell with mu f.
  std::shared_ptr<const continuum::ConstitutiveModel> make(const continuum::MaterialVariant &variant) const override;

private:
  std::shared_ptr<const RveMaterial> base_;
};

} // namespace geocomp::coupled
