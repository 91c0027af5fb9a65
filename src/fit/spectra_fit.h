#pragma once
// Fits barbule BSDF parameters to measured reflectance spectra, evaluating the BSDF directly (no
// rendering): the reflectance factor pi (f_R + f_TRT)(omega_i, omega_o), what `columba bsdf --mode
// specular` reports in the mirror direction, at each measured pair of directions and wavelength.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "barbule/parameters.h"
#include "fit/aperture.h"
#include "fit/fit_result.h"
#include "fit/scaled_loss.h"
#include "fit/spectra_table.h"

namespace columba {

// The model's reflectance factor at each sample's directions and wavelength, averaged over the
// instrument's aperture where it has one.
std::vector<float> modelSpectra(const BarbuleParameters& parameters, const std::vector<SpectraSample>& samples,
                                const InstrumentAperture& aperture = {});

// The barbule's parameters with the named ones (b, phi_0, phi_1, mu, H, height, ..., as the scene
// plug-in spells them) set and the rest at their defaults, read as the plug-in reads them
// (barbule/parameter_reader.h): `values` numbers, `given` texts as -D gives them (a number, or a
// name: preset=dove-purple, film_ior=keratin). A value named in a text as $name stands there
// instead (layers="[rods(melanin, $d, 0.15), keratin:0.04] x 9" with d varied). Throws InputError
// for an unknown name or values it refuses; values it takes but that are probably a mistake go
// to `implausible` where given.
BarbuleParameters barbuleParametersWith(const std::map<std::string, double>& values,
                                        const std::map<std::string, std::string>& given = {},
                                        std::optional<BarbuleParameterProblem>* implausible = nullptr);

struct SpectraFitSettings {
  std::vector<SpectraSample> samples;
  InstrumentAperture aperture;  // of the instrument that measured them
  // Held at a value (-D: a number or a name); the rest not fitted are defaults.
  std::map<std::string, std::string> fixed;
  std::vector<FitParameter> parameters;
  LossKind loss = LossKind::MSE;
  ScaleMode scale = ScaleMode::Free;
  FitSettings fit;
};

struct SpectraFitResult {
  FitResult fit;
  std::vector<float> model;  // modelSpectra at the fitted values, before scaling
};

// Throws std::invalid_argument for settings checkFitSettings refuses (`fixed` held fixed), and for
// a varied parameter whose bounds are implausible (a film thickness of hundreds of um: nm given).
SpectraFitResult fitSpectra(const SpectraFitSettings& settings);

// What a fitted scale far from 1 suggests: the model's reflectance factor is relative to a white
// standard, so measured spectra within a factor of 3 of it need no comment; a scale near 100 or
// 1/100 is percent against fractions, others a geometry (or standard) the model does not share.
std::optional<std::string> implausibleScaleWarning(double scale);

}  // namespace columba
