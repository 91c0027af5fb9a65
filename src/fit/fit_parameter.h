#pragma once
// A parameter to fit: a name (a scene $variable or a barbule BSDF parameter), its bounds and
// where the search starts.
#include <optional>
#include <string>

namespace columba {

struct FitParameter {
  std::string name;
  double lower = 0.0, upper = 1.0;
  std::optional<double> start;  // the middle of the bounds when not given
  double startValue() const { return start ? *start : 0.5 * (lower + upper); }
};

// "NAME=LO:HI" or "NAME=LO:HI:START"; throws std::runtime_error quoting `text` when it is
// malformed, LO >= HI or START lies outside [LO, HI].
FitParameter parseFitParameter(const std::string& text);

}  // namespace columba
