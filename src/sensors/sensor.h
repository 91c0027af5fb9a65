#pragma once
// The sensor interface: camera rays for positions on the film, and for light tracing the
// sensor's importance toward points and directions of the scene.
#include <memory>
#include <optional>
#include "core/ray.h"
#include "film/film.h"
#include "samplers/sampler.h"

namespace columba {

class Medium;

// A connection of light tracing to the sensor: where light from the reference lands on the film
// and how much it counts there.
struct ImportanceSample {
  Vec3 origin;        // the point of the sensor the connection reaches (pinhole, lens point, ...)
  Vec3 rayStart;      // where the camera ray from `origin` toward the reference begins (its near
                      // clip): a shadow ray from the reference ends here
  Vec2 filmPosition;  // pixels, as generateRay takes them
  // The sensor's importance toward the reference times the geometry between them, without the
  // cosine at the reference, over the density of `origin`: light of radiance L leaving the
  // reference toward the sensor (that cosine included) adds L * weight around filmPosition, for
  // an image whose pixels are the means of their filter-weighted camera samples.
  float weight = 0.0f;
};

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
  // skips pixels that lie wholly where the sensor sees nothing.
  virtual bool seesAnyOf(Vec2 /*lo*/, Vec2 /*hi*/) const { return true; }
  // Light tracing. sampleImportance connects the point `ref` to the sensor, `u` picking the
  // point of the lens for sensors that have one; sampleImportanceFrom connects light arriving
  // from infinity: `direction` (unit) points from the sensor toward where the light comes from.
  // nullopt where the sensor does not see it. Film positions up to the filter's radius outside
  // the film count, as camera samples of the pixels at the edge reach there.
  // Sensors that cannot (no importance, or none toward directions) say so: the renderer refuses
  // light tracing through them.
  virtual bool hasImportance() const { return false; }
  virtual bool hasImportanceFromDirections() const { return false; }
  virtual std::optional<ImportanceSample> sampleImportance(const Vec3& /*ref*/, Vec2 /*u*/) const {
    return std::nullopt;
  }
  virtual std::optional<ImportanceSample> sampleImportanceFrom(const Vec3& /*direction*/, Vec2 /*u*/) const {
    return std::nullopt;
  }
  // Whether the film position `p` (pixels) lies on the film, where camera samples lie.
  bool onFilm(Vec2 p) const;
  const Film& film() const { return *film_; }
  const Sampler& sampler() const { return *sampler_; }
  // The medium the sensor sits in, where its camera rays start (null: none).
  const Medium* medium() const { return medium_.get(); }
  // Takes the sensor element's nested <medium> (or <ref> to one), if any.
  void readMedium(const Properties& props);

 private:
  std::shared_ptr<Film> film_;
  std::shared_ptr<Sampler> sampler_;
  std::shared_ptr<Medium> medium_;
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
