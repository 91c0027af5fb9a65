#pragma once
// Per-point values of a BSDF's parameters that a shape supplies at each hit, as Mitsuba's shape
// attributes: a feather gives its per-vertex barbule spacing "H", tilt "mu" and cortex thickness
// "height", interpolated to the hit. Keyed by the parameter's name in a scene file: a BSDF reads
// the names it knows and keeps its own value for any the point does not give.
#include <array>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace columba {

class SurfaceAttributes {
 public:
  static constexpr int kCapacity = 4;

  // `name` must outlive the record (a string literal).
  void set(std::string_view name, float value) {
    for (int i = 0; i < count_; ++i)
      if (names_[i] == name) {
        values_[i] = value;
        return;
      }
    if (count_ == kCapacity) throw std::logic_error("more than SurfaceAttributes::kCapacity attributes");
    names_[count_] = name;
    values_[count_++] = value;
  }
  // The value at this point, or nullopt where the point does not give it.
  std::optional<float> find(std::string_view name) const {
    for (int i = 0; i < count_; ++i)
      if (names_[i] == name) return values_[i];
    return std::nullopt;
  }

 private:
  std::array<std::string_view, kCapacity> names_{};
  std::array<float, kCapacity> values_{};
  int count_ = 0;
};

}  // namespace columba
