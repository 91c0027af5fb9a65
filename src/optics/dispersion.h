#pragma once
// Refractive index as a function of wavelength: Cauchy's law n(lambda) = a + b / lambda^2
// (lambda in nm; a constant index is the case b = 0), or a measured table of n against
// wavelength, interpolated linearly.
#include <memory>
#include <optional>
#include <string>
#include "core/spectrum.h"

namespace columba {

struct RefractiveIndex {
  float a = 1.0f;
  float b = 0.0f;                                     // nm^2
  std::shared_ptr<const SpectralDistribution> table;  // when set, n(lambda) is read from it

  float operator()(float lambdaNm) const { return table ? table->eval(lambdaNm) : a + b / (lambdaNm * lambdaNm); }
  bool isConstant() const { return !table && b == 0.0f; }
  // The smallest and the largest index over 300-830 nm, the range Columba models (1 nm steps for a
  // table).
  float minimumVisible() const;
  float maximumVisible() const;

  static RefractiveIndex constant(float n) { return {n, 0.0f, nullptr}; }
  static RefractiveIndex cauchy(float a, float b) { return {a, b, nullptr}; }
  static RefractiveIndex tabulated(SpectralDistribution n) {
    return {1.0f, 0.0f, std::make_shared<const SpectralDistribution>(std::move(n))};
  }
  // Feather keratin (the cortex of the barbules): n = 1.532 + 5890 / lambda^2.
  static RefractiveIndex keratin() { return cauchy(1.532f, 5890.0f); }
};

// Far beyond any material of a feather, or a metal (n and k below 10 over 300-830 nm): an index
// above it is a typing mistake, and the films' arithmetic is only held to stay finite below it.
inline constexpr float kMaxFilmIndex = 100.0f;

// "keratin", a name of the constant-index table (lookupIOR), or a positive number written as
// text; nullopt for anything else.
std::optional<RefractiveIndex> iorFromName(const std::string& name);

}  // namespace columba
