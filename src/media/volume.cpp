#include "media/volume.h"

#include <fmt/format.h>

#include "media/const_volume.h"

namespace columba {

std::optional<std::pair<float, float>> Volume::clip(const Ray& ray) const {
  if (!bounded_) return ray.tmin < ray.tmax ? std::optional(std::pair(ray.tmin, ray.tmax)) : std::nullopt;
  // Slabs of the unit cube in the volume's space, where the ray keeps its parameter t.
  const Vec3 o = toLocal_.point(ray.o), d = toLocal_.vector(ray.d);
  float t0 = ray.tmin, t1 = ray.tmax;
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0.0f) {  // parallel to this slab: within it everywhere or nowhere
      if (o[axis] < 0.0f || o[axis] > 1.0f) return std::nullopt;
      continue;
    }
    float near = -o[axis] / d[axis], far = (1.0f - o[axis]) / d[axis];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
  }
  if (!(t0 < t1)) return std::nullopt;
  return std::pair(t0, t1);
}

std::shared_ptr<Volume> mediumVolume(const Properties& props, const std::string& name, float def, SpectrumUse use) {
  if (auto nested = props.namedChild<Volume>(name)) {
    if (props.has(name)) throw props.error(name, "'" + name + "' is given both as a value and as a nested <volume>");
    // The values are not negative (every volume refuses that); a fraction's must not pass 1.
    const float largest = nested->largestGivenValue();
    if (use == SpectrumUse::Fraction && largest > 1.0f)
      throw props.error(name, fmt::format("a fraction must lie in [0, 1]; the volume's values reach {:g}", largest));
    return nested;
  }
  return std::make_shared<ConstVolume>(props.getSpectrum(name, def, use), std::nullopt);
}

}  // namespace columba
