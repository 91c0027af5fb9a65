/*! parameters clip
| parameter | type | default | meaning | Mitsuba 3 |
| near_clip | float | 0.01 | the nearest distance seen; at least 0 | same |
| far_clip | float | 10000 | the farthest distance seen; more than `near_clip` | same |
*/
#include "sensors/sensor.h"

#include <fmt/format.h>

#include "film/film.h"
#include "media/medium.h"
#include "samplers/independent_sampler.h"

namespace columba {

bool Sensor::onFilm(Vec2 p) const {
  return p.x >= 0.0f && p.x < float(film_->width()) && p.y >= 0.0f && p.y < float(film_->height());
}

void Sensor::readMedium(const Properties& props) { medium_ = props.child<Medium>(); }

std::shared_ptr<Film> sensorFilm(const Properties& props) {
  auto film = props.child<Film>();
  return film ? film : makeDefaultPlugin<Film>(makeHDRFilm, "film", "hdrfilm", props.location);
}

std::shared_ptr<Sampler> sensorSampler(const Properties& props) {
  auto sampler = props.child<Sampler>();
  return sampler ? sampler
                 : makeDefaultPlugin<Sampler>(makeIndependentSampler, "sampler", "independent", props.location);
}

ClipRange sensorClipRange(const Properties& props) {
  const ClipRange clip{props.getFloat("near_clip", 0.01f), props.getFloat("far_clip", 10000.0f)};
  if (!(clip.nearClip >= 0.0f))
    throw props.error("near_clip", fmt::format("near_clip must be at least 0, not {:g}", clip.nearClip));
  if (!(clip.farClip > clip.nearClip))
    throw props.error("far_clip",
                      fmt::format("far_clip must exceed near_clip ({:g}), not {:g}", clip.nearClip, clip.farClip));
  return clip;
}

}  // namespace columba
