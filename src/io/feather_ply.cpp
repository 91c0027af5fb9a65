#include "io/feather_ply.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "io/ply_file.h"

namespace columba {

namespace {

// What each vertex property is used for.
enum VertexRole { kX, kY, kZ, kNX, kNY, kNZ, kH, kMu, kHeight, kStack, kRoleCount, kIgnored = -1 };

std::vector<int> vertexRoles(const PlyReader& ply, const PlyElement& e) {
  std::vector<int> roles(e.properties.size(), kIgnored);
  auto has = [&](const char* name) { return e.findScalar(name) >= 0; };
  auto assign = [&](const char* name, int role) {
    int i = e.findScalar(name);
    if (i >= 0) roles[i] = role;
    return i >= 0;
  };
  for (const char* axis : {"x", "y", "z"})
    if (!assign(axis, kX + (axis[0] - 'x')))
      throw ply.headerError(e, std::string("element vertex has no float property '") + axis + "'");
  bool out = has("out1") && has("out2") && has("out3");
  bool n = has("nx") && has("ny") && has("nz");
  if (!out && !n)
    throw ply.headerError(e, "element vertex has no vane normal (properties out1 out2 out3, or nx ny nz)");
  if (out) {
    assign("out1", kNX);
    assign("out2", kNY);
    assign("out3", kNZ);
  } else {
    assign("nx", kNX);
    assign("ny", kNY);
    assign("nz", kNZ);
  }
  const bool h = has("H"), mu = has("mu"), height = has("height");
  if (h && mu && height) {
    assign("H", kH);
    assign("mu", kMu);
    assign("height", kHeight);
  } else if (h || mu || height) {
    warn({ply.path(), e.line},
         "element vertex has only some of the barbule values H, mu and height; like the "
         "original implementation, Columba uses them only all together, so the feather's "
         "defaults apply");
  }
  assign("stack", kStack);
  return roles;
}

std::string valueText(double v) { return fmt::format("{}", v); }

void readVertices(PlyReader& ply, const PlyElement& e, FeatherPlyData& out) {
  std::vector<int> roles = vertexRoles(ply, e);
  auto hasRole = [&](int role) { return std::find(roles.begin(), roles.end(), role) != roles.end(); };
  out.positions.resize(e.count);
  out.normals.resize(e.count);
  if (hasRole(kH)) {
    out.barbuleH.resize(e.count);
    out.barbuleMu.resize(e.count);
    out.barbuleHeight.resize(e.count);
  }
  if (hasRole(kStack)) out.layerStack.resize(e.count);
  for (size_t i = 0; i < e.count; ++i) {
    ply.next();
    float v[kRoleCount] = {};
    double stack = 0.0;
    for (size_t k = 0; k < e.properties.size(); ++k) {
      if (roles[k] == kIgnored) continue;
      if (roles[k] == kStack) {
        // Checked as the file gives it, before any rounding.
        stack = ply.scalar(k);
        if (!(stack >= 0.0 && stack <= double(kMaxVertexLayerStack) && stack == std::floor(stack)))
          ply.fail("stack is " + valueText(stack) + "; a layer stack is a whole number from 0 to " +
                   std::to_string(kMaxVertexLayerStack));
        continue;
      }
      v[roles[k]] = float(ply.scalar(k));
      if (!std::isfinite(v[roles[k]])) ply.fail("property '" + e.properties[k].name + "' is not a finite float");
    }
    Vec3 normal(v[kNX], v[kNY], v[kNZ]);
    if (!(lengthSquared(normal) > 0.0f)) ply.fail("the vane normal is zero");
    out.positions[i] = Vec3(v[kX], v[kY], v[kZ]);
    out.normals[i] = normalize(normal);
    if (out.hasBarbuleValues()) {
      if (!(v[kH] > 0.0f)) ply.fail("H is " + valueText(v[kH]) + "; the barbule spacing must be positive");
      if (!(v[kHeight] >= 0.0f))
        ply.fail("height is " + valueText(v[kHeight]) + "; the cortex thickness (um) cannot be negative");
      out.barbuleH[i] = v[kH];
      out.barbuleMu[i] = v[kMu];
      out.barbuleHeight[i] = v[kHeight];
    }
    if (!out.layerStack.empty()) out.layerStack[i] = uint8_t(stack);
    if (i == 0) out.firstVertexLine = ply.line();
  }
}

void readFaces(PlyReader& ply, const PlyElement& e, FeatherPlyData& out) {
  const int list = ply.vertexIndexList(e);
  out.barbIndices.reserve(e.count * kBarbVertices);
  const size_t vertexCount = out.positions.size();
  for (size_t i = 0; i < e.count; ++i) {
    ply.next();
    if (i == 0) out.firstFaceLine = ply.line();
    const std::vector<double>& indices = ply.list(size_t(list));
    if (indices.size() != size_t(kBarbVertices))
      ply.fail("has " + std::to_string(indices.size()) + " vertex indices; a barb is a polyline of exactly " +
               std::to_string(kBarbVertices));
    for (double index : indices) out.barbIndices.push_back(ply.vertexIndex(index, vertexCount));
  }
}

// The largest stack a barb's vertex chooses (vertices no barb uses choose nothing), and the first
// vertex in the file choosing it.
void findLargestLayerStack(FeatherPlyData& out) {
  for (uint32_t v : out.barbIndices) {
    const int stack = out.layerStack.empty() ? -1 : out.layerStack[v];
    if (stack > out.largestLayerStack || (stack == out.largestLayerStack && v < out.largestLayerStackVertex)) {
      out.largestLayerStack = stack;
      out.largestLayerStackVertex = v;
    }
  }
  // One vertex to a line in ASCII files.
  if (out.largestLayerStack >= 0 && out.firstVertexLine > 0)
    out.largestLayerStackLine = out.firstVertexLine + int(out.largestLayerStackVertex);
}

void readBody(PlyReader& ply, FeatherPlyData& out) {
  bool sawVertex = false, sawFace = false;
  for (const PlyElement& e : ply.elements()) {
    if (e.name == "vertex" && !sawVertex) {
      readVertices(ply, e, out);
      sawVertex = true;
    } else if (e.name == "face" && !sawFace) {
      if (!sawVertex) throw ply.headerError(e, "element face must come after element vertex");
      readFaces(ply, e, out);
      sawFace = true;
    } else {
      for (size_t i = 0; i < e.count; ++i) ply.next();
    }
  }
  if (!sawVertex) throw InputError({out.path, ply.endHeaderLine()}, "the file has no element vertex");
  if (!sawFace) throw InputError({out.path, ply.endHeaderLine()}, "the file has no element face (the barbs)");
  ply.finish();
  findLargestLayerStack(out);
}

// `comment barbwidth W`: W positive and finite.
std::optional<float> recordedBarbWidth(const PlyReader& ply) {
  std::optional<float> width;
  for (const PlyComment& c : ply.comments()) {
    std::istringstream words(c.text);
    std::string key, value, extra;
    if (!(words >> key) || key != kBarbWidthComment) continue;
    words >> value >> extra;
    char* end = nullptr;
    const double w = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !extra.empty() || !(w > 0.0) || !std::isfinite(float(w)))
      throw InputError({ply.path(), c.line}, "'comment " + c.text + "': the barb width must be one positive number");
    width = float(w);
  }
  return width;
}

}  // namespace

SourceLocation FeatherPlyData::faceLocation(size_t i) const {
  return {path, firstFaceLine > 0 ? firstFaceLine + int(i) : 0};
}

bool FeatherPlyData::barbsAreSequential() const {
  if (barbIndices.size() != positions.size()) return false;
  for (size_t i = 0; i < barbIndices.size(); ++i)
    if (barbIndices[i] != i) return false;
  return true;
}

FeatherPlyData readFeatherPly(const std::string& path) {
  PlyReader ply(path, "feather PLY file");
  FeatherPlyData data;
  data.path = path;
  data.barbWidth = recordedBarbWidth(ply);
  readBody(ply, data);
  return data;
}

}  // namespace columba
