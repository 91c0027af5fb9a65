#pragma once
// Reading numbers and lists from text, as every reader of a user's text does: a number strictly
// (the whole text must be the number, no spaces, no trailing characters; a floating-point value
// must be finite), text trimmed, lists split, and text shortened for messages.
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

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

// `text` shortened for a message to its first 60 characters, so that a huge value cannot flood the
// terminal.
inline std::string excerpt(const std::string& text) {
  constexpr size_t kMaxQuoted = 60;
  return text.size() <= kMaxQuoted ? text : text.substr(0, kMaxQuoted) + "...";
}

// `text` without the white space around it.
inline std::string trimmed(const std::string& text) {
  const char* space = " \t\r\n\f\v";
  const size_t first = text.find_first_not_of(space), last = text.find_last_not_of(space);
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

// The items of a list separated by commas and/or white space, empty items dropped: how scene files
// write lists of numbers and biologists' CSV and whitespace tables mix.
inline std::vector<std::string> listItems(const std::string& text) {
  std::vector<std::string> items;
  std::string item;
  for (char c : text) {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      if (!item.empty()) items.push_back(item);
      item.clear();
    } else {
      item += c;
    }
  }
  if (!item.empty()) items.push_back(item);
  return items;
}

// The numbers of a list a scene gives as text (tabphase's values, barbulearms' tilts): separated by
// commas and/or white space, as listItems splits them, but an empty place between commas (or a
// comma first or last) is an error, not dropped, since it shifts every number after it. Throws
// std::invalid_argument naming the text and the place: the number of the item, the item.
inline std::vector<double> listNumbers(const std::string& text) {
  std::vector<double> numbers;
  const bool commas = text.find(',') != std::string::npos;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string field = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::vector<std::string> items = listItems(field);
    if (items.empty() && commas)
      throw std::invalid_argument("'" + excerpt(text) + "' has an empty place between its commas, item " +
                                  std::to_string(numbers.size() + 1) +
                                  (numbers.empty() ? " (before the first comma)" : ""));
    for (const std::string& item : items) {
      const std::optional<double> number = parseNumber<double>(item);
      if (!number)
        throw std::invalid_argument("'" + excerpt(text) + "': item " + std::to_string(numbers.size() + 1) + ", '" +
                                    excerpt(item) + "', is not a number");
      numbers.push_back(*number);
    }
    if (comma == std::string::npos) return numbers;
    start = comma + 1;
  }
}

}  // namespace columba
