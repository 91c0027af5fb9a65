#include "scene/xml_transform.h"

#include <fmt/format.h>

#include <stdexcept>
#include "core/frame.h"
#include "scene/xml_values.h"

namespace columba {

namespace {

std::string describe(const XmlElement& op, const char* attribute) {
  return "attribute '" + std::string(attribute) + "' of <" + op.tag() + ">";
}

float component(const XmlElement& op, const char* axis, float def) {
  return op.has(axis) ? float(parseFloat(op.attribute(axis), describe(op, axis), op.location())) : def;
}

// value="x, y, z" or separate x/y/z attributes with a default for the missing ones.
Vec3 vectorOperand(const XmlElement& op, float def) {
  if (op.has("value")) {
    if (op.has("x") || op.has("y") || op.has("z"))
      throw InputError(op.location(), "<" + op.tag() + "> takes either 'value' or x/y/z, not both");
    return parseVec3(op.attribute("value"), describe(op, "value"), op.location());
  }
  return Vec3(component(op, "x", def), component(op, "y", def), component(op, "z", def));
}

Transform matrixOperand(const XmlElement& op) {
  std::vector<double> v = parseFloatList(op.attribute("value"), describe(op, "value"), op.location());
  Matrix4 m = Matrix4::identity();
  if (v.size() == 16) {
    for (int i = 0; i < 16; ++i) m.m[i / 4][i % 4] = v[i];
  } else if (v.size() == 9) {
    for (int i = 0; i < 9; ++i) m.m[i / 3][i % 3] = v[i];
  } else {
    throw InputError(op.location(), "<matrix> needs 16 (4x4) or 9 (3x3) numbers, got " + std::to_string(v.size()));
  }
  return Transform(m);
}

Transform operation(const XmlElement& op) {
  const std::string tag = op.tag();
  if (tag == "translate") {
    op.allowAttributes({"x", "y", "z", "value"});
    return Transform::translate(vectorOperand(op, 0.0f));
  }
  if (tag == "scale") {
    op.allowAttributes({"x", "y", "z", "value"});
    return Transform::scale(vectorOperand(op, 1.0f));
  }
  if (tag == "rotate") {
    op.allowAttributes({"x", "y", "z", "value", "angle"});
    float angle = float(parseFloat(op.attribute("angle"), describe(op, "angle"), op.location()));
    Vec3 axis = vectorOperand(op, 0.0f);
    if (lengthSquared(axis) == 0.0f) throw InputError(op.location(), "<rotate> needs a non-zero axis");
    if (std::abs(length(axis) - 1.0f) > 1e-5f)
      warn(op.location(), fmt::format("<rotate> axis ({}, {}, {}) has length {:.6g}, not 1: it is used as given, "
                                      "as Mitsuba does, which also scales and shears",
                                      axis.x, axis.y, axis.z, length(axis)));
    return Transform::rotate(axis, angle);
  }
  if (tag == "lookat") {
    op.allowAttributes({"origin", "target", "up"});
    auto point = [&](const char* name) { return parseVec3(op.attribute(name), describe(op, name), op.location()); };
    const Vec3 origin = point("origin"), target = point("target");
    Vec3 up = op.has("up") ? point("up") : Vec3(0, 0, 0);
    // Without an up (or with a zero one), Mitsuba 3 takes the first axis of the frame it builds
    // around the view direction (Duff et al. 2017), which Frame::fromNormal builds alike.
    if (up == Vec3(0, 0, 0) && !(target == origin)) up = Frame::fromNormal(normalize(target - origin)).s;
    return Transform::lookAt(origin, target, up);
  }
  if (tag == "matrix") {
    op.allowAttributes({"value"});
    return matrixOperand(op);
  }
  throw InputError(op.location(),
                   "unknown transform operation <" + tag + "> (expected translate, scale, rotate, lookat or matrix)");
}

}  // namespace

Transform parseTransform(const XmlElement& transform) {
  Transform t;
  for (const XmlElement& op : transform.children()) {
    op.requireNoChildren();
    try {
      t = operation(op) * t;
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      // Degenerate operations (zero scale or axis, singular matrix, lookat along up).
      throw InputError(op.location(), "invalid <" + op.tag() + ">: " + e.what());
    }
  }
  return t;
}

}  // namespace columba
