#pragma once
// Reflectance spectrum of the melanin layer beneath the keratin cortex of rock dove barbules.

namespace columba {

// Intensity reflectance at `lambdaNm`: piecewise linear through the measured table, constant
// beyond its ends (250-900 nm).
float melaninReflectance(float lambdaNm);

}  // namespace columba
