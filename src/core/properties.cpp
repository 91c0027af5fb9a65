#include "core/properties.h"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>

#include "core/file_lookup.h"
#include "core/number_text.h"

namespace columba {

namespace {

const char* describe(const Properties::Value& v) {
  switch (v.kind) {
    case Properties::ValueKind::Float:
      return "a <float>";
    case Properties::ValueKind::Integer:
      return "an <integer>";
    case Properties::ValueKind::Boolean:
      return "a <boolean>";
    case Properties::ValueKind::String:
      return "a <string>";
    case Properties::ValueKind::Vector:
      return "a <point>/<vector>";
    case Properties::ValueKind::Spectrum:
      return v.isRGB ? "an <rgb>" : "a <spectrum>";
    case Properties::ValueKind::Transform:
      return "a <transform>";
  }
  return "a value";
}

using Kind = Properties::ValueKind;

}  // namespace

std::string Properties::element() const { return "<" + tag + "> '" + type + "'"; }

const Properties::Value* Properties::find(const std::string& name, std::initializer_list<ValueKind> kinds,
                                          const char* expected) const {
  auto it = values_.find(name);
  if (it == values_.end()) return nullptr;
  const Value& v = it->second;
  v.used = true;
  if (std::find(kinds.begin(), kinds.end(), v.kind) == kinds.end())
    throw InputError(v.location,
                     "parameter '" + name + "' of " + element() + " must be " + expected + ", not " + describe(v));
  return &v;
}

const Properties::Value& Properties::require(const std::string& name, std::initializer_list<ValueKind> kinds,
                                             const char* expected) const {
  if (const Value* v = find(name, kinds, expected)) return *v;
  throw InputError(location, element() + " requires parameter '" + name + "' (" + expected + ")");
}

bool Properties::has(const std::string& name) const { return values_.count(name) > 0; }

bool Properties::isString(const std::string& name) const {
  auto it = values_.find(name);
  return it != values_.end() && it->second.kind == ValueKind::String;
}

bool Properties::isVector(const std::string& name) const {
  auto it = values_.find(name);
  return it != values_.end() && it->second.kind == ValueKind::Vector;
}

namespace {

float toFloat(const Properties::Value& v, const std::string& name) {
  float f = float(v.number);
  if (!std::isfinite(f)) throw InputError(v.location, "parameter '" + name + "' is out of the range of a float");
  return f;
}

int toInt(const Properties::Value& v, const std::string& name) {
  if (v.number < INT_MIN || v.number > INT_MAX)
    throw InputError(v.location, "parameter '" + name + "' is out of the range of an integer");
  return int(v.number);
}

}  // namespace

float Properties::getFloat(const std::string& name) const {
  return toFloat(require(name, {Kind::Float, Kind::Integer}, "a <float>"), name);
}

float Properties::getFloat(const std::string& name, float def) const {
  const Value* v = find(name, {Kind::Float, Kind::Integer}, "a <float>");
  return v ? toFloat(*v, name) : def;
}

int Properties::getInt(const std::string& name) const {
  return toInt(require(name, {Kind::Integer}, "an <integer>"), name);
}

int Properties::getInt(const std::string& name, int def) const {
  const Value* v = find(name, {Kind::Integer}, "an <integer>");
  return v ? toInt(*v, name) : def;
}

bool Properties::getBool(const std::string& name, bool def) const {
  const Value* v = find(name, {Kind::Boolean}, "a <boolean>");
  return v ? v->boolean : def;
}

std::string Properties::getString(const std::string& name) const {
  return require(name, {Kind::String}, "a <string>").text;
}

std::vector<double> Properties::getNumberList(const std::string& name) const {
  const std::string text = getString(name);
  try {
    return listNumbers(text);
  } catch (const std::invalid_argument& e) {
    throw error(name, e.what());
  }
}

std::string Properties::getString(const std::string& name, const std::string& def) const {
  const Value* v = find(name, {Kind::String}, "a <string>");
  return v ? v->text : def;
}

Vec3 Properties::getVector(const std::string& name, const Vec3& def) const {
  const Value* v = find(name, {Kind::Vector}, "a <point> or <vector>");
  return v ? v->vector : def;
}

Transform Properties::getTransform(const std::string& name, const Transform& def) const {
  const Value* v = find(name, {Kind::Transform}, "a <transform>");
  return v ? v->transform : def;
}

std::string Properties::getPath(const std::string& name) const {
  const Value& v = require(name, {Kind::String}, "a <string> file name");
  const std::string path = requireFile(v.text, searchDirs, v.location, "parameter '" + name + "': file");
  // Devices and pipes could be read forever, and a directory is no file.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(v.location, "parameter '" + name + "': '" + path + "' is not a regular file");
  return path;
}

SpectralDistribution Properties::getSpectrum(const std::string& name, float def, SpectrumUse use) const {
  const Value* v = find(name, {Kind::Float, Kind::Integer, Kind::Spectrum}, "a <float>, <spectrum> or <rgb>");
  if ((use == SpectrumUse::Emission || use == SpectrumUse::NonNegative) && v) {
    const float lowest = v->kind != Kind::Spectrum ? float(v->number)
                         : v->isRGB                ? std::min({v->rgb.x, v->rgb.y, v->rgb.z})
                                                   : v->lowest;
    if (lowest < 0.0f)
      throw InputError(v->location,
                       fmt::format("parameter '{}' of {} {}cannot be negative (its lowest value is {:g})", name,
                                   element(), use == SpectrumUse::Emission ? "is emitted light and " : "", lowest));
  }
  if (use == SpectrumUse::Fraction && v) {
    float lowest = 0.0f, highest = 0.0f;
    if (v->kind != Kind::Spectrum) {
      lowest = highest = float(v->number);
    } else if (v->isRGB) {
      lowest = std::min({v->rgb.x, v->rgb.y, v->rgb.z});
      highest = std::max({v->rgb.x, v->rgb.y, v->rgb.z});
    } else {
      // At every nanometre a path may carry.
      lowest = highest = v->spectrum.eval(kSpectralMin);
      for (float lambda = kSpectralMin; lambda <= kLambdaMax; lambda += 1.0f) {
        lowest = std::min(lowest, v->spectrum.eval(lambda));
        highest = std::max(highest, v->spectrum.eval(lambda));
      }
    }
    if (!(lowest >= 0.0f && highest <= 1.0f))
      throw error(name, fmt::format("a fraction must lie in [0, 1], not {:g}", lowest < 0.0f ? lowest : highest));
  }
  // Mitsuba's convention: a single value or a colour given for an emitter is an illuminant (D65
  // scaled to that luminance, or the colour's spectrum times D65); a tabulated spectrum is taken
  // as given.
  SpectralDistribution s;
  if (!v) {
    s = SpectralDistribution::constant(def);
  } else if (v->kind != Kind::Spectrum) {
    s = SpectralDistribution::constant(toFloat(*v, name));
  } else if (v->isRGB) {
    // Emission is fitted at half its largest component and scaled back, as Mitsuba's d65 does; any
    // other colour within [0, 1] is fitted as it is, as Mitsuba's srgb does even when unbounded (a
    // medium's extinction (1, 0.2, 1) gets a reflectance's spectrum shape, not pbrt's scaled one).
    const float largest = std::max({v->rgb.x, v->rgb.y, v->rgb.z});
    s = SpectralDistribution::fromRGB(
        v->rgb, use == SpectrumUse::Emission || (use != SpectrumUse::Reflectance && largest > 1.0f));
  } else {
    s = v->spectrum;
  }
  bool illuminant = use == SpectrumUse::Emission && (!v || v->kind != Kind::Spectrum || v->isRGB || s.isConstant());
  if (illuminant) s = s.timesD65();
  if (use == SpectrumUse::Emission && v && !(s.maxValue() <= kLargestEmission))
    throw InputError(v->location, fmt::format("parameter '{}' of {} is emitted light that reaches {:g}; a value "
                                              "above {:g} would overflow the image's float sums",
                                              name, element(), s.maxValue(), kLargestEmission));
  return s;
}

SourceLocation Properties::locationOf(const std::string& name) const {
  auto it = values_.find(name);
  if (it != values_.end()) return it->second.location;
  for (const Child& c : children_)
    if (!c.name.empty() && c.name == name) return c.location;
  return location;
}

SourceLocation Properties::childLocation(const Object& child) const {
  for (const Child& c : children_)
    if (c.object.get() == &child) return c.location;
  return location;
}

InputError Properties::error(const std::string& name, const std::string& message) const {
  const std::string named = nameParameter ? nameParameter(name) : element() + ", parameter '" + name + "'";
  return InputError(locationOf(name), named + ": " + message);
}

void Properties::checkAllUsed() const {
  // Report the unread item that comes first in the file, whatever its kind.
  const std::pair<const std::string, Value>* value = nullptr;
  for (const auto& entry : values_)
    if (!entry.second.used && (!value || entry.second.location.line < value->second.location.line)) value = &entry;
  const Child* child = nullptr;
  for (const Child& c : children_)
    if (!c.used && (!child || c.location.line < child->location.line)) child = &c;

  if (child && (!value || child->location.line < value->second.location.line)) {
    std::string what = "<" + child->tag + "> '" + child->type + "'";
    if (!child->name.empty()) what += " (name '" + child->name + "')";
    throw InputError(child->location, "unexpected nested " + what + " in " + element());
  }
  if (value) throw InputError(value->second.location, "unknown parameter '" + value->first + "' for " + element());
}

void Properties::set(const std::string& name, Value value) {
  auto it = values_.find(name);
  if (it != values_.end())
    throw InputError(value.location, "duplicate parameter '" + name + "' in " + element() + " (first set at " +
                                         it->second.location.str() + ")");
  values_.emplace(name, std::move(value));
}

void Properties::setNumber(const std::string& name, ValueKind kind, double value) {
  Value v;
  v.kind = kind;
  v.location = location;
  v.number = value;
  set(name, std::move(v));
}

void Properties::setFloat(const std::string& name, double value) { setNumber(name, Kind::Float, value); }

void Properties::setInt(const std::string& name, int value) { setNumber(name, Kind::Integer, value); }

void Properties::setFromText(const std::string& name, const std::string& text) {
  if (std::optional<int> whole = parseNumber<int>(text))
    setInt(name, *whole);
  else if (std::optional<double> number = parseNumber<double>(text))
    setFloat(name, *number);
  else
    setString(name, text);
}

void Properties::setString(const std::string& name, const std::string& value) {
  Value v;
  v.kind = Kind::String;
  v.location = location;
  v.text = value;
  set(name, std::move(v));
}

void Properties::setSpectrum(const std::string& name, const SpectralDistribution& value, float lowest) {
  Value v;
  v.kind = Kind::Spectrum;
  v.location = location;
  v.spectrum = value;
  v.lowest = lowest;
  set(name, std::move(v));
}

}  // namespace columba
