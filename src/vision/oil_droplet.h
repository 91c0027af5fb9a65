#pragma once
// The spectral transmittance of a cone oil droplet, the long-pass filter in front of a bird's cone
// outer segment: the model of Hart & Vorobyev (2005), "Modelling oil droplet absorption spectra and
// spectral sensitivities of bird cone photoreceptors", J Comp Physiol A 191:381-392.
#include <optional>
#include <string>

namespace columba {

// A droplet by its cut-off wavelength lambdaCut (nm) and the slope bMid (1/nm) of its absorbance
// at lambdaMid, the wavelength half-way up its absorbance edge; lambdaMid = lambdaCut + 0.5 / bMid.
struct OilDroplet {
  double lambdaCutNm = 0.0;
  double bMidPerNm = 0.0;
};

// T(lambda) = exp(-exp(-2.89 bMid (lambda - lambdaCut) + 1.08)). At lambdaMid the exponent is
// -0.365, so T(lambdaMid) = exp(-exp(-0.365)) = 0.4995.
double oilDropletTransmission(const OilDroplet& droplet, double lambdaNm);

// lambdaCut + 0.5 / bMid.
double oilDropletMidpoint(const OilDroplet& droplet);

// The droplet with the given cut-off and mid-point wavelengths (lambdaMid > lambdaCut).
OilDroplet oilDropletFromCutAndMid(double lambdaCutNm, double lambdaMidNm);

// The droplet types of bird cones: T (transparent, in UVS/VS cones), C (SWS), Y (MWS), R (LWS),
// P (the principal member of the double cone).
enum class OilDropletType { T, C, Y, R, P };

// "T", "C", "Y", "R" or "P"; nullopt for anything else.
std::optional<OilDropletType> parseOilDropletType(const std::string& letter);

// A droplet of a type with only its cut-off known: lambdaMid from Hart & Vorobyev's (2005) linear
// regressions of lambdaMid on lambdaCut across species (C: 0.99 lambdaCut + 24.38, Y: 0.90 lambdaCut
// + 70.03, R: 0.99 lambdaCut + 28.65, P: 0.96 lambdaCut + 33.57), as pavo's sensmodel applies them.
// nullopt for a T droplet, which filters nothing in the model.
std::optional<OilDroplet> oilDropletOfType(OilDropletType type, double lambdaCutNm);

}  // namespace columba
