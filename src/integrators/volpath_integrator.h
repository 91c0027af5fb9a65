#pragma once
// `volpath` and `volpathmis`, Mitsuba's volumetric path tracers, for scenes without participating
// media (which the loader refuses): there they trace the paths `path` traces.
#include "core/object.h"
#include "core/properties.h"

namespace columba {

std::shared_ptr<Object> makeVolumetricPathIntegrator(const Properties& props);

}  // namespace columba
