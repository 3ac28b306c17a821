#pragma once
// The optional contact parts of a case (rolling resistance, S3 bonds and adhesion, S3
// friction) composed onto the base law that `make_contact_model` builds from the
// `contact` section: one place maps the case entries to the ContactModel alternatives
// (ContactLaw.h), so that a case with none of them gets exactly the base law.
#include "dem/case/DemParameters.h"
#include "dem/ContactLaw.h"

namespace geocomp::dem {

/// `base` (LinearSpringDashpot or HertzMindlin) with the parts `c` switches on; throws
/// std::invalid_argument for combinations without a law (bonds or S3 friction on Hertz).
ContactModel with_contact_parts(const ContactModel &base, const ContactParameters &c);

} // namespace geocomp::dem
