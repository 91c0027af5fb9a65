#include "feather/rock_dove.h"

#include <fmt/format.h>
#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "barbule/parameters.h"
#include "core/math.h"
#include "core/number_text.h"
#include "core/rng.h"
#include "feather/feather_design.h"
#include "feather/feather_generator.h"

namespace columba {

namespace {

// The neck feathers' <bsdf type="barbulebsdf"> with its further parameters, escaped as XML by
// pugixml: a whole number as <integer>, another number as <float>, anything else as <string>, as
// Properties::setFromText reads them.
std::string barbuleElement(const std::vector<std::pair<std::string, std::string>>& parameters) {
  pugi::xml_document doc;
  pugi::xml_node bsdf = doc.append_child("bsdf");
  bsdf.append_attribute("type") = "barbulebsdf";
  bsdf.append_attribute("id") = "dove-barbules";
  for (const auto& [name, value] : parameters) {
    pugi::xml_node child = bsdf.append_child(parseNumber<int>(value)      ? "integer"
                                             : parseNumber<double>(value) ? "float"
                                                                          : "string");
    child.append_attribute("name") = name.c_str();
    child.append_attribute("value") = value.c_str();
  }
  std::ostringstream text;
  doc.print(text, "", pugi::format_raw | pugi::format_no_declaration);
  return text.str();
}

// The template feather as the generator writes a single one: rachis along +y from -kHalfLength
// to +kHalfLength, the vane in the plane z = 0 facing +z, 0.8 wide at most.
constexpr float kTemplateLength = 1.2f, kHalfLength = 0.6f;
constexpr float kPitch = 0.12f;  // radians: each feather rises from its base, so that it lies over the next

// How a part is feathered: feather length (cm) and the least distance between feather bases as a
// fraction of it (small enough that every point of the skin lies under several feathers).
struct PartFeathers {
  float length, spacing, narrowing;  // narrowing: the width's factor (tail feathers are narrow)
};
PartFeathers featheringOf(const BodyPart& part) {
  if (part.plumage == Plumage::Iridescent) return {0.75f, 0.22f, 1.0f};
  if (part.name == "head") return {0.55f, 0.22f, 1.0f};
  if (part.name == "breast") return {1.2f, 0.2f, 1.0f};
  if (part.name == "tail") return {4.0f, 0.22f, 0.6f};
  if (part.name.find("wing") != std::string::npos) return {1.5f, 0.22f, 1.0f};
  return {1.8f, 0.22f, 1.0f};
}

// Approximate surface area of an ellipsoid (Knud Thomsen's formula, within about 1 %).
float ellipsoidArea(const Vec3& r) {
  const float p = 1.6075f;
  const float mean = (std::pow(r.x * r.y, p) + std::pow(r.x * r.z, p) + std::pow(r.y * r.z, p)) / 3.0f;
  return 4.0f * kPi * std::pow(mean, 1.0f / p);
}

// A point uniform over the ellipsoid's area, by rejection from directions uniform on the sphere
// (the area element of the scaled sphere is proportional to |diag(1/r) u|).
Vec3 uniformOnEllipsoid(const Ellipsoid& e, PCG32& rng) {
  const float most = 1.0f / std::min({e.radii.x, e.radii.y, e.radii.z});
  for (;;) {
    const float cosTheta = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * kPi * rng.nextFloat();
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const Vec3 u(sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi));
    const float weight = length(Vec3(u.x / e.radii.x, u.y / e.radii.y, u.z / e.radii.z));
    if (rng.nextFloat() * most <= weight) return e.point(std::acos(cosTheta), phi);
  }
}

// Accepted feather bases in a hash grid, for the least-distance test.
class BaseGrid {
 public:
  explicit BaseGrid(float cell) : cell_(cell) {}
  bool clear(const Vec3& p, float distance) const {
    const int reach = int(std::ceil(distance / cell_));
    const int cx = index(p.x), cy = index(p.y), cz = index(p.z);
    for (int x = cx - reach; x <= cx + reach; ++x)
      for (int y = cy - reach; y <= cy + reach; ++y)
        for (int z = cz - reach; z <= cz + reach; ++z) {
          auto it = cells_.find(key(x, y, z));
          if (it == cells_.end()) continue;
          for (const Vec3& q : it->second)
            if (lengthSquared(q - p) < distance * distance) return false;
        }
    return true;
  }
  void add(const Vec3& p) { cells_[key(index(p.x), index(p.y), index(p.z))].push_back(p); }

 private:
  int index(float v) const { return int(std::floor(v / cell_)); }
  static uint64_t key(int x, int y, int z) {
    return (uint64_t(uint32_t(x)) * 73856093u) ^ (uint64_t(uint32_t(y)) * 19349663u) ^
           (uint64_t(uint32_t(z)) * 83492791u) ^ (uint64_t(uint32_t(z)) << 40);
  }
  float cell_;
  std::unordered_map<uint64_t, std::vector<Vec3>> cells_;
};

Matrix4 featherMatrix(const Vec3& base, const Vec3& x, const Vec3& y, const Vec3& z, float scaleX, float scaleY) {
  // The template scaled, turned into the frame (x, y, z) and moved so that its base (y = -0.6) is at `base`.
  Matrix4 m = Matrix4::identity();
  const Vec3 axes[3] = {x * scaleX, y * scaleY, z * scaleY};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m.m[r][c] = double(axes[c][r]);
  const Vec3 shifted = base + y * (scaleY * kHalfLength);
  m.m[0][3] = shifted.x;
  m.m[1][3] = shifted.y;
  m.m[2][3] = shifted.z;
  return m;
}

Vec3 apply(const Matrix4& m, const Vec3& p) {
  return Vec3(float(m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3]),
              float(m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3]),
              float(m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3]));
}

float smoothStep(float lo, float hi, float x) {
  const float t = clampf((x - lo) / (hi - lo), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

std::vector<Vec3> featherOutline() {
  // The rachis and the vane's edge every twentieth of the length, in the template's frame (its
  // planform, feather/feather_design.h).
  const FeatherDesign design;
  std::vector<Vec3> points;
  for (int i = 0; i <= 20; ++i) {
    const float t = 0.05f * float(i);
    const Vec2 c = rachisPoint(design, t), d = rachisDirection(design, t);
    const Vec2 across(d.y, -d.x);
    // Barbs are up to 5 % longer than the outline; the vane domes down by 1 % of its width at the edges.
    const float w = 1.05f * vaneHalfWidth(design, t);
    for (float side : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) {
      const Vec2 q = c + across * (side * w);
      points.push_back(Vec3(q.y, q.x - kHalfLength, -0.01f * design.width * side * side));
    }
  }
  return points;
}

RockDovePlumage layOutRockDove(const RockDoveBody& body, const RockDoveOptions& options) {
  const std::vector<Vec3> outline = featherOutline();
  RockDovePlumage plumage;
  const std::vector<BodyPart>& parts = body.parts();
  // The grid's cells as small as the least distance between bases on any part.
  float smallest = INFINITY;
  for (const BodyPart& part : parts)
    if (part.plumage != Plumage::None) {
      const PartFeathers f = featheringOf(part);
      smallest = std::min(smallest, f.spacing * f.length * options.featherScale);
    }
  BaseGrid grid(smallest);
  PCG32 colourRng(options.seed, 0x636f6c6fULL);
  const float wobblePhase = 2.0f * kPi * colourRng.nextFloat();
  for (size_t index = 0; index < parts.size(); ++index) {
    const BodyPart& part = parts[index];
    if (part.plumage == Plumage::None) continue;
    const PartFeathers feathering = featheringOf(part);
    const float length = feathering.length * options.featherScale, distance = feathering.spacing * length;
    const size_t candidates = size_t(8.0f * ellipsoidArea(part.shape.radii) / (0.87f * distance * distance));
    PCG32 rng(hashCombine(options.seed, index), 0x646f7665ULL);
    for (size_t c = 0; c < candidates; ++c) {
      const Vec3 p = uniformOnEllipsoid(part.shape, rng);
      const float jitter = rng.nextFloat();
      if (!body.onSurface(p, index) || !grid.clear(p, distance)) continue;
      const Vec3 n = part.shape.normal(p), d = body.featherDirection(p, index);
      const Vec3 y = normalize(d * std::cos(kPitch) + n * std::sin(kPitch));
      const Vec3 z = normalize(n - y * dot(n, y));
      const Vec3 x = cross(y, z);
      const float scale = length / kTemplateLength;
      // Lifted off the skin until its outline is outside the body everywhere; where the body curves
      // in under it (a crease), a smaller feather, as real ones are there.
      Matrix4 m;
      std::vector<Vec3> placed(outline.size());
      bool outside = false;
      float size = scale;
      for (int shrink = 0; shrink <= 4 && !outside; ++shrink, size *= 0.8f)
        for (int step = 1; step <= 30 && !outside; ++step) {
          m = featherMatrix(p + n * (0.02f * length * float(step)), x, y, z, size * feathering.narrowing, size);
          outside = true;
          for (size_t k = 0; k < outline.size() && outside; ++k) {
            placed[k] = apply(m, outline[k]);
            outside = body.inside(placed[k]) >= 0.0f;
          }
        }
      if (!outside) continue;
      for (size_t k = 0; k < outline.size(); ++k) placed[k] = apply(m, outline[k]);
      if (std::any_of(placed.begin(), placed.end(), [&](const Vec3& q) { return body.face(q, false); })) continue;
      grid.add(p);
      PlacedFeather f;
      f.templateIndex = int(jitter * float(options.templates)) % options.templates;
      f.part = index;
      f.plumage = part.plumage;
      f.toWorld = m;
      const float t = body.neckFraction(p);
      // The head's grey comes down to the top of the neck; the breast is purple where it meets it.
      if (part.plumage == Plumage::Iridescent && t > 0.9f) f.plumage = Plumage::Grey;
      if (part.name == "breast" && p.y > RockDoveBody::kNeckBaseY && p.x > 2.0f) f.plumage = Plumage::Iridescent;
      if (f.plumage == Plumage::Iridescent) {
        // Purple on the lower neck, green above, the boundary wavy around the neck.
        const float wobble = 0.06f * std::sin(2.5f * std::atan2(p.z, p.x - RockDoveBody::kNeckBaseX) + wobblePhase);
        const float purple = 1.0f - smoothStep(0.3f, 0.6f, t + wobble);
        PCG32 own(hashCombine(options.seed, plumage.feathers.size()), 0x68656967ULL);
        f.height = lerp(purple, options.greenHeight, options.purpleHeight) +
                   options.heightSpread * (2.0f * own.nextFloat() - 1.0f);
        f.purple = purple > 0.5f;
      }
      plumage.feathers.push_back(f);
      if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return plumage;
    }
  }
  return plumage;
}

RockDoveSummary writeRockDove(const RockDoveOptions& options, const std::string& directory) {
  if (!(options.featherScale >= 0.2f && options.featherScale <= 5.0f))
    throw std::invalid_argument(fmt::format("the feather scale must lie in [0.2, 5], not {}", options.featherScale));
  if (options.templates < 1 || options.templates > 16)
    throw std::invalid_argument(
        fmt::format("the number of feather templates must be 1 to 16, not {}", options.templates));
  if (!(options.heightSpread >= 0.0f) ||
      std::min(options.greenHeight, options.purpleHeight) - options.heightSpread < 0.0f)
    throw std::invalid_argument("cortex thicknesses and their spread must leave every feather's thickness at least 0");
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  RockDoveSummary summary;
  if (options.purpleStack < 0 || options.purpleStack >= kMaxLayerStacks)
    throw std::invalid_argument(fmt::format("the purple feathers' layer stack must be 1 to {} (0: none), not {}",
                                            kMaxLayerStacks - 1, options.purpleStack));
  for (int k = 0; k < options.templates; ++k) {
    FeatherGenerationOptions feather;
    feather.seed = hashCombine(options.seed, 0x7465u + uint64_t(k));
    feather.binary = true;
    feather.cancel = options.cancel;
    // With a purple stack, every template chooses stack 0 (the green feathers' and the grey
    // ones', whose BSDF ignores it), and a copy of it chooses the purple stack.
    std::vector<std::pair<std::string, int>> files = {{fmt::format("rock_dove_feather_{}.ply", k), 0}};
    if (options.purpleStack > 0)
      files.emplace_back(fmt::format("rock_dove_feather_{}_purple.ply", k), options.purpleStack);
    for (const auto& [name, stack] : files) {
      if (options.purpleStack > 0) feather.stack = stack;
      FeatherGenerationSummary written = generateFeatherPly(feather, (fs::path(directory) / name).string());
      if (!written.written) return {0, 0, 0, false};
      summary.templateBarbs += written.barbs;
    }
  }
  const RockDoveBody body;
  const RockDovePlumage plumage = layOutRockDove(body, options);
  if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return {0, 0, 0, false};

  const fs::path path = fs::path(directory) / "rock_dove.xml", temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << "<scene version=\"3.0.0\">\n"
           "  <!-- A procedural rock dove (columba feather --bird): its body, and feathers as copies of a few\n"
           "       templates. Iridescent neck feathers use the barbule BSDF with each copy's cortex thickness;\n"
           "       the grey feathers a diffuse grey. Lengths in centimetres. -->\n"
           "  "
        << barbuleElement(options.barbule)
        << "\n"
           "  <bsdf type=\"diffuse\" id=\"dove-grey\"><rgb name=\"reflectance\" value=\"0.33, 0.35, 0.41\"/></bsdf>\n";
    for (int k = 0; k < options.templates; ++k) {
      for (const char* kind : {"neck", "grey"})
        out << fmt::format(
            "  <shape type=\"shapegroup\" id=\"dove-{0}-{1}\"><shape type=\"feather\">"
            "<string name=\"filename\" value=\"rock_dove_feather_{1}.ply\"/><ref id=\"dove-{2}\"/></shape></shape>\n",
            kind, k, kind == std::string("neck") ? "barbules" : "grey");
      if (options.purpleStack > 0)
        out << fmt::format(
            "  <shape type=\"shapegroup\" id=\"dove-purple-{0}\"><shape type=\"feather\">"
            "<string name=\"filename\" value=\"rock_dove_feather_{0}_purple.ply\"/><ref id=\"dove-barbules\"/>"
            "</shape></shape>\n",
            k);
    }
    for (const PlacedFeather& f : plumage.feathers) {
      const bool iridescent = f.plumage == Plumage::Iridescent;
      summary.iridescent += iridescent;
      const auto& m = f.toWorld.m;
      const char* group = !iridescent ? "grey" : f.purple && options.purpleStack > 0 ? "purple" : "neck";
      out << fmt::format("  <shape type=\"instance\"><ref id=\"dove-{}-{}\"/>", group, f.templateIndex);
      if (iridescent) out << fmt::format("<float name=\"height\" value=\"{:.4f}\"/>", f.height);
      out << fmt::format(
          "<transform name=\"to_world\"><matrix value=\"{:.6g} {:.6g} {:.6g} {:.6g} {:.6g} {:.6g} {:.6g} {:.6g} "
          "{:.6g} {:.6g} {:.6g} {:.6g} 0 0 0 1\"/></transform></shape>\n",
          m[0][0], m[0][1], m[0][2], m[0][3], m[1][0], m[1][1], m[1][2], m[1][3], m[2][0], m[2][1], m[2][2], m[2][3]);
    }
    for (const BodyPart& part : body.parts()) {
      const Ellipsoid& e = part.shape;
      const char* colour = part.name == "beak"                          ? "0.12, 0.10, 0.10"
                           : part.name.find("eye") != std::string::npos ? "0.85, 0.40, 0.08"
                                                                        : "0.20, 0.21, 0.24";
      out << fmt::format(
          "  <shape type=\"sphere\"><!-- {} --><transform name=\"to_world\"><scale x=\"{}\" y=\"{}\" z=\"{}\"/>"
          "<rotate z=\"1\" angle=\"{:.4f}\"/><translate x=\"{}\" y=\"{}\" z=\"{}\"/></transform>"
          "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"{}\"/></bsdf></shape>\n",
          part.name, e.radii.x, e.radii.y, e.radii.z, e.pitch * 180.0f / kPi, e.centre.x, e.centre.y, e.centre.z,
          colour);
      if (part.name.find("eye") != std::string::npos) {
        const Vec3 pupil = e.centre + Vec3(0.12f, 0.02f, e.centre.z > 0.0f ? 0.26f : -0.26f);
        out << fmt::format(
            "  <shape type=\"sphere\"><!-- pupil --><float name=\"radius\" value=\"0.2\"/>"
            "<point name=\"center\" x=\"{}\" y=\"{}\" z=\"{}\"/>"
            "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.01, 0.01, 0.01\"/></bsdf></shape>\n",
            pupil.x, pupil.y, pupil.z);
      }
    }
    out << "</scene>\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  }
  fs::rename(temporary, path);
  summary.feathers = plumage.feathers.size();
  return summary;
}

}  // namespace columba
