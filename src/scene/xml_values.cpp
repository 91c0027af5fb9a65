#include "scene/xml_values.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/byte_order_mark.h"
#include "core/number_text.h"

namespace columba {

namespace {

InputError badValue(const std::string& kind, const std::string& text, const std::string& what,
                    const SourceLocation& loc) {
  return InputError(loc, "invalid " + kind + " '" + text + "' for " + what);
}

// std::from_chars accepts neither a leading '+' nor surrounding spaces; the scene format allows both.
std::string numberBody(const std::string& text) {
  std::string t = trimmed(text);
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.erase(0, 1);
  return t;
}

GivenSpectrum fromPairs(std::vector<float> lambdas, std::vector<float> values, const std::string& what,
                        const SourceLocation& loc) {
  if (lambdas.empty()) throw InputError(loc, "no wavelength:value pairs for " + what);
  for (size_t i = 1; i < lambdas.size(); ++i)
    if (!(lambdas[i] > lambdas[i - 1]))
      throw InputError(loc, "wavelengths must increase for " + what + " (" + std::to_string(lambdas[i - 1]) +
                                " is followed by " + std::to_string(lambdas[i]) + ")");
  const float lowest = *std::min_element(values.begin(), values.end());
  return {SpectralDistribution::piecewiseLinear(std::move(lambdas), std::move(values)), lowest};
}

}  // namespace

double parseFloat(const std::string& text, const std::string& what, const SourceLocation& loc) {
  std::string t = numberBody(text);
  double v = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v))
    throw badValue("number", text, what, loc);
  // Scene values are used as floats: a larger one would silently become infinite.
  if (std::abs(v) > double(std::numeric_limits<float>::max()))
    throw InputError(loc, "number '" + trimmed(text) + "' for " + what + " is out of the range of a float (at most " +
                              "3.4e38 in magnitude)");
  return v;
}

long long parseInteger(const std::string& text, const std::string& what, const SourceLocation& loc) {
  std::string t = numberBody(text);
  long long v = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size()) throw badValue("integer", text, what, loc);
  return v;
}

bool parseBoolean(const std::string& text, const std::string& what, const SourceLocation& loc) {
  std::string t = trimmed(text);
  for (char& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (t == "true") return true;
  if (t == "false") return false;
  throw badValue("boolean (true or false)", text, what, loc);
}

std::vector<double> parseFloatList(const std::string& text, const std::string& what, const SourceLocation& loc) {
  std::vector<double> out;
  for (const std::string& token : listItems(text)) out.push_back(parseFloat(token, what, loc));
  return out;
}

Vec3 parseVec3(const std::string& text, const std::string& what, const SourceLocation& loc) {
  std::vector<double> v = parseFloatList(text, what, loc);
  if (v.size() == 1) return Vec3(float(v[0]), float(v[0]), float(v[0]));
  if (v.size() == 3) return Vec3(float(v[0]), float(v[1]), float(v[2]));
  throw InputError(loc, "expected 1 or 3 numbers for " + what + ", got '" + text + "'");
}

GivenSpectrum parseSpectrum(const std::string& text, const std::string& what, const SourceLocation& loc) {
  if (text.find(':') == std::string::npos) {
    std::vector<std::string> tokens = listItems(text);
    if (tokens.size() != 1)
      throw InputError(loc, "expected one number or wavelength:value pairs for " + what + ", got '" + text + "'");
    const float value = float(parseFloat(tokens[0], what, loc));
    return {SpectralDistribution::constant(value), value};
  }
  std::vector<float> lambdas, values;
  for (const std::string& token : listItems(text)) {
    size_t colon = token.find(':');
    if (colon == std::string::npos || token.find(':', colon + 1) != std::string::npos)
      throw InputError(loc, "expected wavelength:value, got '" + token + "' for " + what);
    lambdas.push_back(float(parseFloat(token.substr(0, colon), what, loc)));
    values.push_back(float(parseFloat(token.substr(colon + 1), what, loc)));
  }
  return fromPairs(std::move(lambdas), std::move(values), what, loc);
}

GivenSpectrum readSpectrumFile(const std::string& path, const std::string& what, const SourceLocation& loc) {
  // Devices and pipes could be read forever.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(loc, "spectrum file '" + path + "' for " + what + " is not a regular file" +
                              (std::filesystem::exists(path, ec) ? "" : " (it does not exist)"));
  std::ifstream in(path);
  if (!in) throw InputError(loc, "cannot open spectrum file '" + path + "' for " + what);
  skipByteOrderMark(in);
  std::vector<float> lambdas, values;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    line = line.substr(0, line.find('#'));
    std::vector<std::string> tokens = listItems(line);
    if (tokens.empty()) continue;
    SourceLocation here{path, lineNo};
    if (tokens.size() != 2) throw InputError(here, "expected 'wavelength value', got '" + trimmed(line) + "'");
    lambdas.push_back(float(parseFloat(tokens[0], "the wavelength", here)));
    values.push_back(float(parseFloat(tokens[1], "the value", here)));
  }
  return fromPairs(std::move(lambdas), std::move(values), what + " (file '" + path + "')", loc);
}

}  // namespace columba
