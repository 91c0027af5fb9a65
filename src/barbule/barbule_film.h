#pragma once
// The film the R and TRT lobes see at a shading point: the keratin cortex alone (the paper's film,
// evaluated by FreeStandingFilm's fast path) or the cortex over further layers (LayeredFilm, by
// transfer matrices), with the same answers for the lobes either way.
#include <optional>

#include "barbule/parameters.h"
#include "optics/layered_film.h"
#include "optics/thin_film.h"

namespace columba {

class BarbuleFilm {
 public:
  // The cortex over the parameters' layer stack `layerStack` (BarbuleParameters::layerStack).
  BarbuleFilm(const BarbuleParameters& params, float thicknessUm, const Wavelengths& wl, int layerStack = 0)
      : cortex_(params.filmIOR, params.extIOR, thicknessUm, wl) {
    const FilmStack& below = params.layerStack(layerStack);
    if (!below.empty()) layered_.emplace(params.filmIOR, params.extIOR, thicknessUm, below, wl);
  }

  FreeStandingFilm::Reflectance reflectance(float cosIncidence) const {
    return layered_ ? layered_->reflectance(cosIncidence) : cortex_.reflectance(cosIncidence);
  }
  Spectrum transmittanceProduct(float cos1, float cos2) const {
    return layered_ ? layered_->transmittanceProduct(cos1, cos2) : cortex_.transmittanceProduct(cos1, cos2);
  }
  Spectrum weightedTransmittanceProducts(FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const {
    return layered_ ? layered_->weightedTransmittanceProducts(weight, cos1, cos2)
                    : cortex_.weightedTransmittanceProducts(weight, cos1, cos2);
  }
  FreeStandingFilm::Averages averagesOverWavelengths(FloatLanes cosIncidence, const Spectrum& weight) const {
    return layered_ ? layered_->averagesOverWavelengths(cosIncidence, weight)
                    : cortex_.averagesOverWavelengths(cosIncidence, weight);
  }

 private:
  FreeStandingFilm cortex_;
  std::optional<LayeredFilm> layered_;
};

}  // namespace columba
