#include "sensors/sensor.h"

#include "film/film.h"
#include "samplers/independent_sampler.h"

namespace columba {

std::shared_ptr<Film> sensorFilm(const Properties& props) {
  auto film = props.child<Film>();
  return film ? film : makeDefaultPlugin<Film>(makeHDRFilm, "film", "hdrfilm", props.location);
}

std::shared_ptr<Sampler> sensorSampler(const Properties& props) {
  auto sampler = props.child<Sampler>();
  return sampler ? sampler
                 : makeDefaultPlugin<Sampler>(makeIndependentSampler, "sampler", "independent", props.location);
}

}  // namespace columba
