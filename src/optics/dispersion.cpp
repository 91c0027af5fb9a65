#include "optics/dispersion.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include "optics/ior_table.h"

namespace columba {

float RefractiveIndex::minimumVisible() const {
  if (!table) return std::min((*this)(kSpectralMin), (*this)(kLambdaMax));  // monotonic in lambda
  float n = (*this)(kSpectralMin);
  for (float l = kSpectralMin + 1.0f; l <= kLambdaMax; l += 1.0f) n = std::min(n, (*this)(l));
  return n;
}

float RefractiveIndex::maximumVisible() const {
  if (!table) return std::max((*this)(kSpectralMin), (*this)(kLambdaMax));
  float n = (*this)(kSpectralMin);
  for (float l = kSpectralMin + 1.0f; l <= kLambdaMax; l += 1.0f) n = std::max(n, (*this)(l));
  return n;
}

std::optional<RefractiveIndex> iorFromName(const std::string& name) {
  if (name == "keratin") return RefractiveIndex::keratin();
  if (auto named = lookupIOR(name)) return RefractiveIndex::constant(*named);
  // Mitsuba also accepts the index itself in a string parameter.
  char* end = nullptr;
  float value = std::strtof(name.c_str(), &end);
  if (!name.empty() && end == name.c_str() + name.size() && std::isfinite(value) && value > 0.0f)
    return RefractiveIndex::constant(value);
  return std::nullopt;
}

}  // namespace columba
