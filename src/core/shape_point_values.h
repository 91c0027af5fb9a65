#pragma once
// What a shape gives its BSDF at its points (a feather's per-vertex barbule values), told to the
// BSDF once, when the shape is built (BSDF::noteValuesGivenByShape), so that the BSDF can warn of
// its own constants that those values leave without effect and refuse choices it cannot honour.
#include <string>

#include "core/error.h"
#include "core/surface_attributes.h"

namespace columba {

struct ShapePointValues {
  std::string shape;               // names the shape in messages: "the feather 'neck.ply'"
  SurfaceAttributeSet everywhere;  // the BSDF parameters given at every point
  // The largest layer stack a point chooses by number (barbule/parameters.h), -1 where the shape
  // chooses none; where its file first chooses it, and which element does ("vertex 12").
  int largestLayerStack = -1;
  SourceLocation largestLayerStackAt;
  std::string largestLayerStackElement;
};

}  // namespace columba
