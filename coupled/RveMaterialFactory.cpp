#include "coupled/RveMaterialFactory.h"

#include <stdexcept>

namespace geocomp::coupled {

RveMaterialFactory::RveMaterialFactory(std::shared_ptr<const RveMaterial> base) : base_(std::move(base))
{
  if (!base_)
    throw std::invalid_argument("dem rve: no RVE material");
}

std::shared_ptr<const continuum::ConstitutiveModel> RveMaterialFactory::make(const continuum::MaterialVariant &v) const
{
  if (v.cohesion_factor == 1.0)
    return base_;
  if (!(v.cohesion_factor > 0.0 && v.cohesion_factor < 1.0))
    throw std::invalid_argument("dem rve: the imperfection factor must be in (0, 1]");
  dem::PeriodicCell weak = base_->prepared();
  dem::PeriodicCell::Parameters p = weak.parameters();
  p.friction *= v.cohesion_factor; // mu_weak = f mu
  weak.set_parameters(p);
  return std::make_shared<const RveMaterial>(std::move(weak), base_->parameters());
}

} // namespace geocomp::coupled
