#pragma once
// The BSDF parameters a shape may give per point (a feather's per-vertex barbule values), as a
// scene gave them: where each constant was given, so that the BSDF can warn, once and naming that
// line, when a shape's own values leave it without effect (BSDF::noteValuesGivenByShape).
#include <atomic>
#include <initializer_list>
#include <string>
#include <vector>
#include "core/error.h"
#include "core/properties.h"
#include "core/surface_attributes.h"

namespace columba {

class PerPointParameterSources {
 public:
  struct Parameter {
    const char* name;
    SurfaceAttributeKey key;  // its per-point value
    bool textured;            // given as a texture, which takes effect on every shape: not recorded
  };
  // Records each of `parameters` that `props` gives as a constant, itself or through the preset
  // parameter `preset` (which gives all of them; "" for none). `props.type` names the BSDF in
  // messages.
  PerPointParameterSources(const Properties& props, const std::string& preset,
                           std::initializer_list<Parameter> parameters);
  PerPointParameterSources(const PerPointParameterSources&) = delete;
  PerPointParameterSources& operator=(const PerPointParameterSources&) = delete;

  // Warns, once for each line, of the recorded parameters that `everywhere` holds: on `shape` they
  // have no effect.
  void warnIfShadowed(const SurfaceAttributeSet& everywhere, const std::string& shape) const;

 private:
  struct Source {
    std::string name;
    SurfaceAttributeKey key;
    SourceLocation where;
    bool fromPreset;
  };
  std::string plugin_, preset_;
  std::vector<Source> sources_;
  mutable std::atomic<uint32_t> warned_{0};  // bit i: sources_[i] was warned of
};

}  // namespace columba
