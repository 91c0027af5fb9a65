#pragma once
// Refractive index as a function of wavelength, by Cauchy's law n(lambda) = a + b / lambda^2
// (lambda in nm). A constant index is the case b = 0.
#include <optional>
#include <string>

namespace columba {

struct CauchyIOR {
  float a = 1.0f;
  float b = 0.0f;  // nm^2

  float operator()(float lambdaNm) const { return a + b / (lambdaNm * lambdaNm); }
  bool isConstant() const { return b == 0.0f; }

  static CauchyIOR constant(float n) { return {n, 0.0f}; }
  // Feather keratin (the cortex of the barbules): n = 1.532 + 5890 / lambda^2.
  static CauchyIOR keratin() { return {1.532f, 5890.0f}; }
};

// "keratin", a name of the constant-index table (lookupIOR), or a positive number written as
// text; nullopt for anything else.
std::optional<CauchyIOR> iorFromName(const std::string& name);

}  // namespace columba
