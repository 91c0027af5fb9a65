#pragma once
// Parameters of one plug-in element of a scene file, with the source line of each, and its
// nested plug-ins. Factories read what they understand; anything left unread is an error.
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include "core/error.h"
#include "core/object.h"
#include "core/spectrum.h"
#include "core/transform.h"

namespace columba {

// How a spectrum parameter is used: reflectances are clamped to [0, 1] when given as RGB;
// emission may exceed 1, and a single value or an RGB colour for it is an illuminant (times D65,
// as Mitsuba reads emitters); unbounded values (indices of refraction) are taken as given, and
// non-negative ones (a conductor's optical constants) too, but refused below zero, as emission is.
// A fraction (a medium's albedo) is refused outside [0, 1] in every form, an RGB colour included.
enum class SpectrumUse { Reflectance, Emission, Unbounded, NonNegative, Fraction };

// The largest emitted value (radiance, intensity, irradiance) a scene may give. An image's pixels
// are float sums of emitted values times the estimators' weights (geometry terms, over densities
// of directions and wavelengths) and the observer's conversion: this leaves eight decades of room
// under float's 3.4e38, where 1e35 already overflowed. The sun's radiance is about 2e4 W/(m^2 sr nm).
inline constexpr float kLargestEmission = 1e30f;

class Properties {
 public:
  // Element tag ("bsdf"), plug-in type ("diffuse"), optional id, and where it was declared.
  std::string tag, type, id;
  SourceLocation location;
  // Where a relative file name is looked for, in order (core/file_lookup.h): the declaring scene
  // file's directory, the main scene file's, the <path> directories; then the working directory.
  std::vector<std::string> searchDirs;
  // How messages name a parameter. Unset: as a scene element's ("<bsdf> 'diffuse', parameter
  // 'reflectance'"); a front end that builds Properties from its own options names them as its
  // users wrote them ("--film-ior").
  std::function<std::string(const std::string& name)> nameParameter;

  bool has(const std::string& name) const;
  // True when `name` was given as a <string> (e.g. a named IOR rather than a number).
  bool isString(const std::string& name) const;
  // True when `name` was given as a <vector> or <point>.
  bool isVector(const std::string& name) const;
  // Typed getters: a missing optional value returns `def`; a missing required value or one of
  // the wrong type throws InputError naming the file, line and parameter.
  float getFloat(const std::string& name) const;
  float getFloat(const std::string& name, float def) const;
  int getInt(const std::string& name) const;
  int getInt(const std::string& name, int def) const;
  bool getBool(const std::string& name, bool def) const;
  std::string getString(const std::string& name) const;
  std::string getString(const std::string& name, const std::string& def) const;
  // A list of numbers given as a <string>, separated by commas and/or white space (listNumbers);
  // InputError naming the file, line, the whole text and the bad place.
  std::vector<double> getNumberList(const std::string& name) const;
  Vec3 getVector(const std::string& name, const Vec3& def) const;  // <point> or <vector>
  Transform getTransform(const std::string& name, const Transform& def = Transform()) const;
  // A file name looked up in `searchDirs`, then the working directory; throws InputError (file,
  // line, value and the places looked) if no regular file of that name is found.
  std::string getPath(const std::string& name) const;
  // <float>, <spectrum> or <rgb>. Emission must not be negative anywhere, nor above
  // kLargestEmission (InputError).
  SpectralDistribution getSpectrum(const std::string& name, float def, SpectrumUse use) const;

  // Nested plug-ins (and <ref>s) of type T, in document order; each returned one counts as used.
  template <typename T>
  std::vector<std::shared_ptr<T>> children() const {
    std::vector<std::shared_ptr<T>> out;
    for (const Child& c : children_)
      if (auto p = std::dynamic_pointer_cast<T>(c.object)) {
        c.used = true;
        out.push_back(p);
      }
    return out;
  }
  // At most one nested plug-in of type T; nullptr if none, InputError if several.
  template <typename T>
  std::shared_ptr<T> child() const {
    auto all = children<T>();
    if (all.size() > 1) throw InputError(location, "'" + type + "' takes at most one nested " + tag + " of this kind");
    return all.empty() ? nullptr : all.front();
  }

  // The nested plug-in (or <ref>) of type T given for parameter `name` by its name attribute, e.g.
  // <texture name="reflectance">; nullptr if none. It counts as used.
  template <typename T>
  std::shared_ptr<T> namedChild(const std::string& name) const {
    for (const Child& c : children_)
      if (c.name == name)
        if (auto p = std::dynamic_pointer_cast<T>(c.object)) {
          c.used = true;
          return p;
        }
    return nullptr;
  }

  // Where a parameter was declared (the element's own location if unknown).
  SourceLocation locationOf(const std::string& name) const;
  // Where the nested plug-in (or the <ref> to it) `child` stands (the element's own location if
  // it is not one of them).
  SourceLocation childLocation(const Object& child) const;
  // An error pointing at parameter `name`.
  InputError error(const std::string& name, const std::string& message) const;
  // Throws for the first parameter or nested plug-in no factory read.
  void checkAllUsed() const;

  // Filled by the scene loader.
  enum class ValueKind { Float, Integer, Boolean, String, Vector, Spectrum, Transform };
  struct Value {
    ValueKind kind;
    SourceLocation location;
    double number = 0;
    bool boolean = false;
    std::string text;
    Vec3 vector;
    SpectralDistribution spectrum;  // for <spectrum>: given value; for <rgb>: see rgb
    float lowest = 0.0f;            // for <spectrum>: its smallest value
    bool isRGB = false;
    Vec3 rgb;
    Transform transform;
    mutable bool used = false;
  };
  struct Child {
    std::string name;  // the `name` attribute, if any
    std::shared_ptr<Object> object;
    SourceLocation location;
    std::string tag, type;  // of the nested element (or of the referenced one), for messages
    mutable bool used = false;
  };
  // Throws InputError if `name` is already set.
  void set(const std::string& name, Value value);
  // Values given by a front end's options instead of a scene file (as Mitsuba's load_dict takes a
  // dictionary), at the element's own location.
  void setFloat(const std::string& name, double value);
  void setInt(const std::string& name, int value);
  // A value a front end has as text (NAME=VALUE on a command line): a whole number as an
  // <integer> (which a float parameter takes too), any other number as a <float>, anything else as
  // a <string>, as a scene file would have given it.
  void setFromText(const std::string& name, const std::string& text);
  void setString(const std::string& name, const std::string& value);
  void setSpectrum(const std::string& name, const SpectralDistribution& value, float lowest);
  void addChild(Child child) { children_.push_back(std::move(child)); }

 private:
  void setNumber(const std::string& name, ValueKind kind, double value);
  // The value of `name` (marked used), nullptr if absent; InputError if its kind is not one of
  // `kinds` (`expected` describes them for the message).
  const Value* find(const std::string& name, std::initializer_list<ValueKind> kinds, const char* expected) const;
  const Value& require(const std::string& name, std::initializer_list<ValueKind> kinds, const char* expected) const;
  std::string element() const;  // "<bsdf> 'diffuse'", for messages
  std::map<std::string, Value> values_;
  std::vector<Child> children_;
};

// The plug-in a scene leaves out (e.g. the diffuse BSDF of a shape with none nested), built by
// its factory with every parameter at its default and reported at `where`.
template <typename T>
std::shared_ptr<T> makeDefaultPlugin(std::shared_ptr<Object> (*factory)(const Properties&), const std::string& tag,
                                     const std::string& type, const SourceLocation& where) {
  Properties defaults;
  defaults.tag = tag;
  defaults.type = type;
  defaults.location = where;
  auto object = std::dynamic_pointer_cast<T>(factory(defaults));
  if (!object) throw InputError(where, "the default " + tag + " '" + type + "' is not a " + tag);
  return object;
}

}  // namespace columba
