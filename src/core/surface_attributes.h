#pragma once
// Per-point values of a BSDF's parameters that a shape supplies at each hit, as Mitsuba's shape
// attributes: a feather gives its per-vertex barbule spacing "H", tilt "mu" and cortex thickness
// "height", interpolated to the hit. Keyed by the parameter's name in a scene file, resolved once
// to a slot (SurfaceAttributeKey) when a shape or BSDF is built, so that setting and reading a
// value at each hit is an array access, not a string comparison.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace columba {

class SurfaceAttributeKey {
 public:
  // The slot of `name`: the same for every key of that name in the program (std::logic_error
  // past SurfaceAttributes::kCapacity distinct names).
  explicit SurfaceAttributeKey(std::string_view name);
  // The key of `name` if some shape or BSDF declared it, without declaring it (a texture naming a
  // parameter no code gives per point takes no slot).
  static std::optional<SurfaceAttributeKey> find(std::string_view name);
  int slot() const { return slot_; }
  std::string name() const;

 private:
  explicit SurfaceAttributeKey(int slot) : slot_(slot) {}
  int slot_;
};

// A set of attribute names, e.g. the BSDF parameters a shape gives at every one of its points.
class SurfaceAttributeSet {
 public:
  void add(SurfaceAttributeKey key) { bits_ |= uint32_t(1) << key.slot(); }
  bool contains(SurfaceAttributeKey key) const { return bits_ >> key.slot() & 1u; }

 private:
  uint32_t bits_ = 0;
};

class SurfaceAttributes {
 public:
  static constexpr int kCapacity = 8;

  void set(SurfaceAttributeKey key, float value) {
    values_[key.slot()] = value;
    given_ |= uint32_t(1) << key.slot();
  }
  // The value at this point, or nullopt where the point does not give it.
  std::optional<float> find(SurfaceAttributeKey key) const {
    if (!(given_ >> key.slot() & 1u)) return std::nullopt;
    return values_[key.slot()];
  }
  bool empty() const { return given_ == 0; }
  // Takes every value `other` gives, keeping the others.
  void overrideWith(const SurfaceAttributes& other) {
    for (int i = 0; i < kCapacity; ++i)
      if (other.given_ >> i & 1u) values_[i] = other.values_[i];
    given_ |= other.given_;
  }
  // The names given here, each after `prefix`, for messages ("vertex_H, vertex_mu").
  std::string names(const std::string& prefix) const;

 private:
  std::array<float, kCapacity> values_{};
  uint32_t given_ = 0;  // bit i: slot i holds a value
};

}  // namespace columba
