#include "app/cli_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace columba {

namespace {

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closestName(const std::string& given, const std::vector<std::string>& candidates) {
  std::string best;
  size_t bestDistance = 0;
  for (const std::string& candidate : candidates) {
    size_t distance = editDistance(given, candidate);
    if (best.empty() || distance < bestDistance) {
      best = candidate;
      bestDistance = distance;
    }
  }
  // A third of the name may be wrong (at least one letter, at most three).
  const size_t allowed = std::clamp<size_t>(given.size() / 3, 1, 3);
  return bestDistance <= allowed ? best : "";
}

void requireFiniteNumbers(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) -> std::string {
        try {
          if (std::isfinite(std::stod(text))) return "";
        } catch (const std::invalid_argument&) {
          return "";  // not a number at all: the conversion reports it
        } catch (const std::out_of_range&) {
        }
        return "must be a finite number, not '" + text + "'";
      },
      "");
  // The type name reads "FLOAT", followed by the descriptions of any checks (":POSITIVE").
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().rfind("FLOAT", 0) == 0) option->check(finite);
  for (CLI::App* command : app.get_subcommands({})) requireFiniteNumbers(*command);
}

std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

int parseCount(const char* option, const std::string& text, int lowest, int highest) {
  if (text.empty()) return 0;
  long long value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::invalid_argument || end != text.data() + text.size())
    throw std::runtime_error(fmt::format("{} expects a whole number, not '{}'", option, text));
  if (ec != std::errc() || value < lowest || value > highest)
    throw std::runtime_error(fmt::format("{} must be between {} and {}, not {}", option, lowest, highest, text));
  return int(value);
}

}  // namespace columba
