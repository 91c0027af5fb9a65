#pragma once
// The body of a <transform> element: translate, scale, rotate, lookat and matrix operations,
// each applied after the ones before it (T = op * T), as in Mitsuba.
#include "core/transform.h"
#include "scene/xml_source.h"

namespace columba {

Transform parseTransform(const XmlElement& transform);

}  // namespace columba
