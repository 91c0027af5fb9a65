#pragma once
// The sensor interface: camera rays for positions on the film.
#include <memory>
#include <optional>
#include "core/ray.h"
#include "film/film.h"
#include "samplers/sampler.h"

namespace columba {

class Sensor : public Object {
 public:
  Sensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler)
      : film_(std::move(film)), sampler_(std::move(sampler)) {}
  // `filmPosition` in pixels, (0, 0) the top-left corner of the image; `apertureSample` in
  // [0, 1)^2 picks the point of the lens for sensors that have one (needsApertureSample()), and
  // the others ignore it. nullopt: no ray (black).
  virtual std::optional<Ray> generateRay(Vec2 filmPosition, Vec2 apertureSample) const = 0;
  // A sensor without a lens: the ray through the film position.
  std::optional<Ray> generateRay(Vec2 filmPosition) const { return generateRay(filmPosition, Vec2(0.5f, 0.5f)); }
  // Whether generateRay uses its aperture sample. The renderer draws one from the sampler only
  // then, so that pinhole sensors use the sampler's dimensions as they always have.
  virtual bool needsApertureSample() const { return false; }
  // Whether generateRay may return a ray anywhere in the film rectangle [lo, hi]: the renderer
  // skips pixels whose filter footprint lies wholly where the sensor sees nothing.
  virtual bool seesAnyOf(Vec2 /*lo*/, Vec2 /*hi*/) const { return true; }
  const Film& film() const { return *film_; }
  const Sampler& sampler() const { return *sampler_; }

 private:
  std::shared_ptr<Film> film_;
  std::shared_ptr<Sampler> sampler_;
};

// The nested film and sampler of a sensor element, or the defaults (hdrfilm, independent).
std::shared_ptr<Film> sensorFilm(const Properties& props);
std::shared_ptr<Sampler> sensorSampler(const Properties& props);
// near_clip and far_clip (0.01 and 10000 by default, as in Mitsuba), checked: 0 <= near < far.
struct ClipRange {
  float nearClip, farClip;
};
ClipRange sensorClipRange(const Properties& props);

}  // namespace columba
