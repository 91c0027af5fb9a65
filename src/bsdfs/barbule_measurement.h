#pragma once
// Virtual measurements of the barbule BSDF, as a gonioreflectometer or an imaging scatterometer
// would take them: the spectral reflectance of each lobe, and the hemisphere of reflected
// radiance for one light direction. All deterministic (grids and quadrature, no sampling).
#include <vector>
#include "bsdfs/barbule_bsdf.h"
#include "render/image.h"

namespace columba {

// Directional reflectance (albedo) of the R and TRT lobes for light from `omegaI` (local frame),
// at each wavelength of `lambdas` (nm): the integral over all outgoing directions of
// f_lobe(omegaI, omegaO) |cos theta_o|.
struct LobeReflectance {
  std::vector<float> lambdas, reflection, trt;
};
LobeReflectance lobeReflectance(const BarbuleBSDF& bsdf, const Vec3& omegaI, const std::vector<float>& lambdas);

// Linear RGB of what an imaging scatterometer records under a white beam (D65 of unit luminance)
// from `omegaI`: f(omegaI, omegaO) |cos theta_o| per solid angle toward every direction
// of the upper hemisphere, integrated against the colour matching functions. The image disk maps
// to the hemisphere as in the `bsdfvisualizer` sensor (theta = r pi/2, phi = atan2(v, u), v
// growing downward with the row); pixels outside it are black. `supersampling`^2 directions per
// pixel.
Image scatterometerImage(const BarbuleBSDF& bsdf, const Vec3& omegaI, int resolution, int supersampling = 2);

// Wavelengths from 360 to 830 nm every `step` nm.
std::vector<float> visibleWavelengthGrid(float step);

}  // namespace columba
