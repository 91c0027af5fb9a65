#pragma once
// `moment`, Mitsuba's wrapper that records the first and second moments of a nested integrator's
// samples: Columba renders the nested integrator (the first moment is its image) and warns that
// the second moments are not recorded.
#include "core/object.h"
#include "core/properties.h"

namespace columba {

std::shared_ptr<Object> makeMomentIntegrator(const Properties& props);

}  // namespace columba
