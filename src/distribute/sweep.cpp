#include "distribute/sweep.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "io/output_directory.h"

namespace columba {

namespace {

constexpr size_t kMostFrames = 1000000;
// The longest file name and path Linux takes (NAME_MAX, PATH_MAX): a frame's file is refused
// before any work when it could not be created.
constexpr size_t kLongestFileName = 255, kLongestPath = 4095;

bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

// Digits after the decimal point, or -1 for a number in exponent notation.
int decimalsOf(const std::string& text) {
  if (text.find_first_of("eE") != std::string::npos) return -1;
  size_t point = text.find('.');
  return point == std::string::npos ? 0 : int(text.size() - point - 1);
}

std::string formatValue(double value, int decimals) {
  std::string text = decimals < 0 ? fmt::format("{:.12g}", value) : fmt::format("{:.{}f}", value, decimals);
  if (decimals > 0 && text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> items;
  size_t start = 0;
  for (;;) {
    size_t at = text.find(separator, start);
    items.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return items;
    start = at + 1;
  }
}

const std::string& valueOf(const SweepFrame& frame, const std::string& name, const std::string& pattern) {
  for (const auto& [n, v] : frame.values)
    if (n == name) return v;
  std::string names;
  for (const auto& [n, v] : frame.values) names += (names.empty() ? "" : ", ") + n;
  throw std::runtime_error(fmt::format("--frames '{}': {{{}}} names no swept variable (swept: {})", pattern, name,
                                       names.empty() ? "none" : names));
}

// A name cut to its first characters, for messages.
std::string shortened(const std::string& name) { return name.size() <= 80 ? name : name.substr(0, 80) + "..."; }

void checkFileNameLength(const std::string& file) {
  if (file.size() > kLongestPath)
    throw std::runtime_error(fmt::format("cannot write '{}': its path is {} bytes long, more than {}", shortened(file),
                                         file.size(), kLongestPath));
  for (size_t start = 0; start < file.size();) {
    size_t end = std::min(file.find('/', start), file.size());
    if (end - start > kLongestFileName)
      throw std::runtime_error(fmt::format("cannot write '{}': a name in its path is {} bytes long, more than {}",
                                           shortened(file), end - start, kLongestFileName));
    start = end + 1;
  }
}

}  // namespace

SweepAxis parseSweep(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::runtime_error("--sweep expects NAME=START:STOP:STEP or NAME=v1,v2,..., not '" + text + "'");
  SweepAxis axis;
  axis.spec = text;
  axis.name = text.substr(0, eq);
  const std::string values = text.substr(eq + 1);
  if (values.empty()) throw std::runtime_error("--sweep " + text + ": no values after '='");
  const std::vector<std::string> range = split(values, ':');
  if (range.size() == 3 && values.find(',') == std::string::npos) {
    double start = 0, stop = 0, step = 0;
    for (size_t i = 0; i < 3; ++i)
      if (!parseNumber(range[i], i == 0 ? start : i == 1 ? stop : step))
        throw std::runtime_error(fmt::format("--sweep {}: '{}' is not a number (START:STOP:STEP)", text, range[i]));
    if (step == 0.0) throw std::runtime_error("--sweep " + text + ": the step must not be 0");
    if ((stop - start) / step < 0.0)
      throw std::runtime_error(
          fmt::format("--sweep {}: a step of {} never gets from {} to {}", text, range[2], range[0], range[1]));
    // Up to STOP inclusive, allowing for the round-off of a decimal step (0.1 is not exact).
    const double steps = std::floor((stop - start) / step + 1e-9);
    if (steps + 1 > double(kMostFrames))
      throw std::runtime_error(fmt::format("--sweep {}: {} values, more than {}", text, steps + 1, kMostFrames));
    int decimals = 0;
    for (const std::string& r : range) {
      int d = decimalsOf(r);
      decimals = d < 0 || decimals < 0 ? -1 : std::max(decimals, d);
    }
    for (long i = 0; i <= long(steps); ++i) axis.values.push_back(formatValue(start + double(i) * step, decimals));
  } else if (range.size() != 1 && values.find(',') == std::string::npos) {
    throw std::runtime_error("--sweep " + text + ": a range is START:STOP:STEP (three numbers)");
  } else {
    axis.values = split(values, ',');
    for (const std::string& v : axis.values)
      if (v.empty()) throw std::runtime_error("--sweep " + text + ": an empty value in the list");
  }
  std::set<std::string> distinct(axis.values.begin(), axis.values.end());
  if (distinct.size() != axis.values.size()) throw std::runtime_error("--sweep " + text + ": a value is given twice");
  return axis;
}

std::vector<SweepFrame> expandSweeps(const std::vector<SweepAxis>& axes) {
  std::set<std::string> names;
  size_t total = 1;
  for (const SweepAxis& axis : axes) {
    if (!names.insert(axis.name).second) throw std::runtime_error("--sweep " + axis.name + " is given twice");
    if (axis.values.empty()) throw std::runtime_error("--sweep " + axis.name + " has no values");
    total *= axis.values.size();
    if (total > kMostFrames) throw std::runtime_error(fmt::format("the sweeps make more than {} frames", kMostFrames));
  }
  std::vector<SweepFrame> frames(total);
  for (size_t f = 0; f < total; ++f) {
    frames[f].index = int(f);
    size_t rest = f;
    // The last axis varies fastest.
    std::vector<std::pair<std::string, std::string>> values(axes.size());
    for (size_t a = axes.size(); a-- > 0;) {
      values[a] = {axes[a].name, axes[a].values[rest % axes[a].values.size()]};
      rest /= axes[a].values.size();
    }
    frames[f].values = std::move(values);
  }
  return frames;
}

std::string frameFileFromOutput(const std::string& output, const SweepFrame& frame) {
  if (frame.values.empty()) return output;
  std::filesystem::path path(output);
  std::string extension = path.extension().string();
  std::string name = path.replace_extension().string();
  for (const auto& [n, v] : frame.values) name += "_" + safeForFileName(n + "=" + v);
  return name + extension;
}

std::string frameFileFromPattern(const std::string& pattern, const SweepFrame& frame) {
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i) {
    const char c = pattern[i];
    if (c == '%') {
      if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
        out += '%';
        ++i;
        continue;
      }
      size_t j = i + 1;
      bool zero = j < pattern.size() && pattern[j] == '0';
      if (zero) ++j;
      size_t digitsStart = j;
      while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
      if (j >= pattern.size() || pattern[j] != 'd' || j - digitsStart > 2)
        throw std::runtime_error(
            fmt::format("--frames '{}': '%' must start %d, %0Nd or %Nd (the frame index) or "
                        "be written %%",
                        pattern));
      int width = j > digitsStart ? std::atoi(pattern.substr(digitsStart, j - digitsStart).c_str()) : 0;
      out += zero ? fmt::format("{:0{}d}", frame.index, width) : fmt::format("{:{}d}", frame.index, width);
      i = j;
    } else if (c == '{') {
      if (i + 1 < pattern.size() && pattern[i + 1] == '{') {
        out += '{';
        ++i;
        continue;
      }
      size_t close = pattern.find('}', i);
      if (close == std::string::npos)
        throw std::runtime_error(fmt::format("--frames '{}': '{{' without its '}}'", pattern));
      std::string field = pattern.substr(i + 1, close - i - 1);
      size_t colon = field.find(':');
      const std::string& value = valueOf(frame, field.substr(0, colon), pattern);
      if (colon == std::string::npos) {
        out += safeForFileName(value);
      } else {
        const std::string spec = "{:" + field.substr(colon + 1) + "}";
        // A width or precision is a run of digits (the fill, if a digit, is one alone): bounded
        // before formatting, which would make a string as long as either.
        for (size_t d = colon + 1; d < field.size();) {
          size_t end = d, first = d;
          while (end < field.size() && std::isdigit(static_cast<unsigned char>(field[end]))) ++end;
          while (first < end && field[first] == '0') ++first;
          if (end - first > 3 || (end > first && std::stoi(field.substr(first, end - first)) > int(kLongestFileName)))
            throw std::runtime_error(
                fmt::format("--frames '{}': {{{}}}: a width or precision of {}, more than {} (the longest file name)",
                            pattern, field, field.substr(d, end - d), kLongestFileName));
          d = std::max(end, d + 1);
        }
        double number = 0;
        if (!parseNumber(value, number))
          throw std::runtime_error(
              fmt::format("--frames '{}': {{{}}} formats a number, but the value is '{}'", pattern, field, value));
        try {
          // Whole numbers as integers ("{angle:03}"), unless the spec is for floating point.
          std::string text;
          if (number == std::floor(number) && std::abs(number) < 1e15 &&
              value.find_first_of(".eE") == std::string::npos)
            try {
              text = fmt::format(fmt::runtime(spec), (long long)number);
            } catch (const fmt::format_error&) {
            }
          out += text.empty() ? fmt::format(fmt::runtime(spec), number) : text;
        } catch (const fmt::format_error& e) {
          throw std::runtime_error(fmt::format("--frames '{}': {{{}}}: {}", pattern, field, e.what()));
        }
      }
      i = close;
    } else if (c == '}') {
      if (i + 1 < pattern.size() && pattern[i + 1] == '}') ++i;
      out += '}';
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<std::string> frameFiles(const std::string& output, const std::string& pattern,
                                    const std::vector<SweepFrame>& frames) {
  std::vector<std::string> files;
  std::map<std::string, int> first;
  for (const SweepFrame& frame : frames) {
    files.push_back(pattern.empty() ? frameFileFromOutput(output, frame) : frameFileFromPattern(pattern, frame));
    checkFileNameLength(files.back());
    auto [at, inserted] = first.emplace(files.back(), frame.index);
    if (!inserted)
      throw std::runtime_error(fmt::format("frames {} and {} would both be written to '{}'{}", at->second, frame.index,
                                           files.back(),
                                           pattern.empty() ? "" : " (put %d or every swept {name} in --frames)"));
  }
  return files;
}

}  // namespace columba
