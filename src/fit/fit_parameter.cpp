#include "fit/fit_parameter.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace columba {

namespace {

double parseNumber(const std::string& text, const std::string& whole) {
  double value = 0.0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw std::runtime_error(fmt::format("--vary '{}': '{}' is not a number", whole, text));
  return value;
}

}  // namespace

FitParameter parseFitParameter(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::runtime_error(fmt::format("--vary expects NAME=LO:HI[:START], got '{}'", text));
  std::vector<std::string> fields;
  for (size_t from = eq + 1;;) {
    size_t colon = text.find(':', from);
    fields.push_back(text.substr(from, colon == std::string::npos ? std::string::npos : colon - from));
    if (colon == std::string::npos) break;
    from = colon + 1;
  }
  if (fields.size() < 2 || fields.size() > 3)
    throw std::runtime_error(fmt::format("--vary expects NAME=LO:HI[:START], got '{}'", text));
  FitParameter p;
  p.name = text.substr(0, eq);
  p.lower = parseNumber(fields[0], text);
  p.upper = parseNumber(fields[1], text);
  if (!(p.lower < p.upper))
    throw std::runtime_error(
        fmt::format("--vary '{}': the lower bound {} must be below the upper bound {}", text, p.lower, p.upper));
  if (fields.size() == 3) {
    p.start = parseNumber(fields[2], text);
    if (*p.start < p.lower || *p.start > p.upper)
      throw std::runtime_error(
          fmt::format("--vary '{}': the start {} lies outside [{}, {}]", text, *p.start, p.lower, p.upper));
  }
  return p;
}

}  // namespace columba
