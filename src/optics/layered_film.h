#pragma once
// A barbule's keratin cortex over further layers (melanin, air gaps, melanosome layers as
// effective media), with the surrounding medium above and below, at a path's wavelengths: the
// general case of the free-standing film (thin_film.h), by transfer matrices (multilayer.h). It
// answers what FreeStandingFilm answers, so the lobes use either; with no layer below the cortex
// it is the same film within rounding (FreeStandingFilm stays the fast path for that case).
// docs/model.md, "Layered films".
#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "core/fast_math.h"
#include "core/spectrum.h"
#include "optics/dispersion.h"
#include "optics/multilayer.h"
#include "optics/thin_film.h"

namespace columba {

// What a layer is made of: its index n(lambda) + i k(lambda). The extinction
// k(lambda) = k exp(-lambda / kDecayNm) falls with wavelength as melanin's does; kDecayNm = 0 keeps
// it constant.
struct LayerMaterial {
  RefractiveIndex n;
  float k = 0.0f;
  float kDecayNm = 0.0f;

  float extinction(float lambdaNm) const { return kDecayNm > 0.0f ? k * std::exp(-lambdaNm / kDecayNm) : k; }
  std::complex<double> index(float lambdaNm) const { return {n(lambdaNm), extinction(lambdaNm)}; }
};

// Melanin (optics/melanin_index.h: a Cauchy n and an exponentially falling k).
LayerMaterial melanin();

// A layer below the cortex: one material, or (`fraction` < 1) an effective medium of `material`
// taking that share of the layer's volume within `matrix` (a slice of a row of melanosomes,
// optics/rod_layer.h), and its thickness.
struct FilmLayer {
  LayerMaterial material;
  float thicknessUm = 0.0f;
  float fraction = 1.0f;
  LayerMaterial matrix;

  // The layer's complex index: the material's, or the effective medium's, whose permittivity is
  // the volume average of the two (docs/model.md, "Rows of melanosomes as effective layers").
  std::complex<double> index(float lambdaNm) const;
};

// The layers below the cortex, from it down, with the repeats they were written with: each run's
// layers are listed once (optics/multilayer.h, LayerRun).
struct FilmStack {
  std::vector<FilmLayer> layers;
  std::vector<LayerRun> runs;  // covering `layers` in order; empty where nothing repeats

  bool empty() const { return layers.empty(); }
};

class LayeredFilm {
 public:
  LayeredFilm(const RefractiveIndex& cortex, float nOutside, float cortexThicknessUm, const FilmStack& below,
              const Wavelengths& wl);

  // As FreeStandingFilm's, per polarisation, at incidence cosine `cosIncidence` (clamped to
  // [1e-4, 1] as there).
  FreeStandingFilm::Reflectance reflectance(float cosIncidence) const;
  // 1/2 (T_s(cos1) T_s(cos2) + T_p(cos1) T_p(cos2)): into the medium below the stack and back.
  Spectrum transmittanceProduct(float cos1, float cos2) const;
  // The same for four pairs, one per lane, weighted and summed over the lanes.
  Spectrum weightedTransmittanceProducts(FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const;
  // Means over the wavelengths of (R_s + R_p) / 2 and of w (T_s^2 + T_p^2) / 2, one cosine a lane.
  FreeStandingFilm::Averages averagesOverWavelengths(FloatLanes cosIncidence,
                                                     const Spectrum& transmittanceWeight) const;

 private:
  MultilayerResponse at(int k, float cosIncidence) const;

  std::array<LayerStack, kSpectrumSamples> stacks_;  // one a wavelength, the indices evaluated there
  std::array<float, kSpectrumSamples> lambdas_{};
};

}  // namespace columba
