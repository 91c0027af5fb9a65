#pragma once
// Checks shared by the BSDF tests: chi-square of `sample` against `pdf`, weight consistency,
// albedo estimates, and building plug-in parameters by hand.
#include <memory>
#include <string>
#include "bsdfs/bsdf.h"
#include "core/properties.h"
#include "support/chi_square.h"

namespace columba::testing {

// The wavelengths every BSDF test evaluates at.
Wavelengths testWavelengths();
// A direction in the local frame at polar angle theta from the normal and azimuth phi (degrees).
Vec3 directionAt(float thetaDegrees, float phiDegrees = 0.0f);

// Per-test significance level keeping the chance of any false alarm among `tests` independent
// tests at `familyAlpha` (Sidak correction).
double sidakThreshold(double familyAlpha, int tests);

// Bins of a chi-square direction test and midpoints per bin side integrating the pdf over them.
struct ChiSquareGrid {
  int thetaBins = 20, phiBins = 40, quadrature = 16;
};
// A grid fine enough for a lobe of roughness `alpha`: the bins are equal in cos(theta), so near
// the pole such a lobe is only ~alpha^2 wide in them.
ChiSquareGrid chiSquareGrid(float alpha);

// Directions of the non-delta samples of `bsdf` from `wi` against its `pdf`.
ChiSquareResult chiSquareBSDF(const BSDF& bsdf, const Vec3& wi, ChiSquareGrid grid = {}, int sampleCount = 200000,
                              uint64_t seed = 1);

// Largest relative difference between a non-delta sample's weight and eval / pdf, over
// `sampleCount` samples from `wi` (every wavelength).
double maxWeightError(const BSDF& bsdf, const Vec3& wi, int sampleCount = 20000);

// Mean sample weight: the fraction of light from wi that is scattered (delta components included).
Spectrum sampledAlbedo(const BSDF& bsdf, const Vec3& wi, int sampleCount, uint64_t seed = 7);
// Integral of eval over all directions by cosine-weighted sampling of both hemispheres,
// independent of the BSDF's own sampler (non-delta components only).
Spectrum integratedAlbedo(const BSDF& bsdf, const Vec3& wi, int sampleCount, uint64_t seed = 11);

// eval and pdf from the unnormalised wi = (1, 0, 1) toward wo at theta = i / 19 * 90 degrees,
// i = 0 ... 19, in the x-z plane (the arc of Mitsuba's BSDF regression tests), against tabulated
// `values` and `pdfs` within the relative tolerances (first wavelength).
void expectValuesAlongMitsubasTestArc(const BSDF& bsdf, const double (&values)[20], const double (&pdfs)[20],
                                      double valueTolerance, double pdfTolerance);

// The BSDF plug-in `type` as a scene file builds it from `parameters` (XML elements), and the
// message of the InputError that building it throws ("" when none).
std::shared_ptr<BSDF> loadBSDF(const std::string& type, const std::string& parameters);
std::string loadBSDFError(const std::string& type, const std::string& parameters);

// Parameters of a plug-in as a scene file would give them.
void setFloat(Properties& props, const std::string& name, float value);
void setInt(Properties& props, const std::string& name, int value);
void setString(Properties& props, const std::string& name, const std::string& value);
void setBool(Properties& props, const std::string& name, bool value);
void addNested(Properties& props, std::shared_ptr<Object> object);

}  // namespace columba::testing
