#pragma once
// Strict reading of a number from text: the whole text must be the number (no spaces, no trailing
// characters) and a floating-point value must be finite. Readers wrap it in their own messages.
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

namespace columba {

template <typename T>
std::optional<T> parseNumber(const std::string& text) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace columba
