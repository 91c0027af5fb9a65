#pragma once
// Virtual measurements of a barbule model (the ellipse's or the arms', barbule/lobe_source.h), as a
// gonioreflectometer or an imaging scatterometer would take them: the spectral reflectance of each lobe, and the hemisphere of reflected
// radiance for one light direction. All deterministic (grids and quadrature, no sampling).
#include <vector>
#include "barbule/lobe_source.h"
#include "io/image.h"

namespace columba {

// Spectra of the R and TRT lobes at the wavelengths `lambdas` (nm).
struct LobeSpectra {
  std::vector<float> lambdas, reflection, trt;
};

// Directional reflectance (albedo) of the R and TRT lobes for light from `omegaI` (local frame),
// at each wavelength of `lambdas` (nm): the integral over all outgoing directions of
// f_lobe(omegaI, omegaO) |cos theta_o|.
LobeSpectra lobeReflectance(const BarbuleLobeSource& model, const Vec3& omegaI, const std::vector<float>& lambdas);

// Linear RGB of what an imaging scatterometer records under a white beam (D65 of unit luminance)
// from `omegaI`: f(omegaI, omegaO) |cos theta_o| per solid angle toward every direction
// of the upper hemisphere, integrated against the colour matching functions. The image disk maps
// to the hemisphere as in the `bsdfvisualizer` sensor (theta = r pi/2, phi = atan2(v, u), v
// growing downward with the row); pixels outside it are black. `supersampling`^2 directions per
// pixel.
Image scatterometerImage(const BarbuleLobeSource& model, const Vec3& omegaI, int resolution, int supersampling = 2);

// What a microspectrophotometer measures: the reflectance factor pi f(omegaI, omegaO) (1 for a
// white diffuse standard) of the R and TRT lobes in the mirror direction of `omegaI` (its x and y
// negated), at each wavelength of `lambdas` (nm).
LobeSpectra specularSpectra(const BarbuleLobeSource& model, const Vec3& omegaI, const std::vector<float>& lambdas);

// The scatterometer quantity f(omegaI, omegaO) |cos theta_o| (per steradian, R + TRT) in the plane
// of incidence: omegaO at signed polar angles `thetaO` (radians; negative on the light's side,
// the mirror direction at -theta_i) and the light's azimuth `phi`, for each wavelength of
// `lambdas`: values[angle][wavelength].
struct PlaneSlice {
  std::vector<float> thetaO, lambdas;
  std::vector<std::vector<float>> values;
};
PlaneSlice planeSlice(const BarbuleLobeSource& model, const Vec3& omegaI, float phi, const std::vector<float>& thetaO,
                      const std::vector<float>& lambdas);
// Linear RGB of a slice's columns under a D65 beam of unit luminance (lambdas a uniform grid).
std::vector<Vec3> sliceRGB(const PlaneSlice& slice);

// The scatterometer image per wavelength bin: `bins` equal bins over [lambdaMin, lambdaMax], each
// the bin's mean of f(omegaI, omegaO) |cos theta_o| (per steradian, R + TRT, no illuminant), on
// the image disk of scatterometerImage (zero outside it).
SpectralBands spectralScatterometerBands(const BarbuleLobeSource& model, const Vec3& omegaI, int resolution, int bins,
                                         float lambdaMin, float lambdaMax, int supersampling = 2);

// Wavelengths from `first` to 830 nm every `step` nm: from kLambdaMin (360 nm) for human colour,
// from kSpectralMin (300 nm) for spectra, which birds see from there.
std::vector<float> wavelengthGrid(float first, float step);
// Wavelengths of the local maxima of `values` sampled at `lambdas` (interior points only).
std::vector<float> peakWavelengths(const std::vector<float>& lambdas, const std::vector<float>& values);

// Unit direction at polar angle `theta` from the vane normal and azimuth `phi` from the x axis
// (across the barbules), radians.
Vec3 directionFromAngles(float theta, float phi);

}  // namespace columba
