#include "feather/feather_generator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include "core/rng.h"
#include "feather/feather_design.h"
#include "feather/neck_layout.h"
#include "io/feather_ply_writer.h"
#include "shapes/feather_barbule_values.h"
#include "shapes/feather_shape.h"

namespace columba {

namespace {

// The barbules the generator means, in the model's terms; the file stores them in its own
// convention, so that they render so in Columba and in the original implementation alike.
constexpr float kBarbuleH = 1.25f, kBarbuleMu = -0.35f;

// Takes one feather's own 2D frame (x along the rachis, y across) to the PLY's 3D space: onto
// the plane z = 0 (no neck) or the neck's surface, raised by the feather's pitch and lowered
// toward its edges by a slight dome.
class VaneMapping {
 public:
  VaneMapping(const NeckSurface* neck, const FeatherPlacement& placement, const FeatherDesign& design)
      : neck_(neck),
        placement_(placement),
        halfWidth_(0.5f * design.width),
        dome_(0.01f * design.width),
        step_(1e-3f * design.length) {}

  // Surface coordinates (X, Y) of a local point.
  Vec2 surfaceCoordinates(Vec2 local) const {
    float s = std::sin(placement_.heading), c = std::cos(placement_.heading);
    Vec2 along(s, c), across(c, -s);
    return placement_.base + (along * local.x + across * local.y) * placement_.scale;
  }

  Vec3 position(Vec2 local) const {
    Vec2 st = surfaceCoordinates(local);
    float yn = local.y / halfWidth_;
    float lift = placement_.scale * (placement_.pitch * local.x - dome_ * yn * yn);
    if (!neck_) return Vec3(st.x, st.y, lift);
    return neck_->point(st.x, st.y) + neck_->normal(st.x, st.y) * lift;
  }

  // Normal of the mapped vane; differentiated numerically because the mapping stacks several
  // bends (neck, pitch, dome) that are simplest kept in position() alone.
  Vec3 normal(Vec2 local) const {
    Vec3 dx = position(local + Vec2(step_, 0)) - position(local - Vec2(step_, 0));
    Vec3 dy = position(local + Vec2(0, step_)) - position(local - Vec2(0, step_));
    Vec3 n = normalize(cross(dx, dy));
    Vec2 st = surfaceCoordinates(local);
    Vec3 up = neck_ ? neck_->normal(st.x, st.y) : Vec3(0, 0, 1);
    return dot(n, up) < 0.0f ? -n : n;
  }

 private:
  const NeckSurface* neck_;
  FeatherPlacement placement_;
  float halfWidth_, dome_, step_;
};

float symmetricJitter(PCG32& rng) { return 2.0f * rng.nextFloat() - 1.0f; }

// The rachis first, then the barbs of one side and of the other, each as one face; false when
// options.cancel stopped it.
bool writeFeather(const FeatherDesign& design, const VaneMapping& mapping, const NeckColouring* colouring,
                  const FeatherGenerationOptions& options, uint64_t seed, FeatherPlyWriter& writer) {
  PCG32 rng(seed, 0x66656174ULL);
  // The feather's own thickness offset, from a stream of its own (the barbs' draws stay as they are).
  PCG32 featherRng(seed, 0x636f7274ULL);
  const float featherOffset = options.heightSpread * symmetricJitter(featherRng);
  BarbVertex vertices[kBarbVertices];
  auto write = [&](const std::array<Vec2, kBarbVertices>& polyline, float barbuleH, float thicknessOffset) {
    for (int k = 0; k < kBarbVertices; ++k) {
      BarbVertex& v = vertices[k];
      v.position = mapping.position(polyline[k]);
      v.normal = mapping.normal(polyline[k]);
      v.fileH = fileSpacingFromModel(barbuleH);
      v.fileMu = fileTiltFromModel(kBarbuleMu);
      float purple = 0.0f;
      if (colouring) {
        Vec2 st = mapping.surfaceCoordinates(polyline[k]);
        purple = colouring->purple(st.x, st.y);
      }
      v.height = lerp(purple, options.greenHeight, options.purpleHeight) + thicknessOffset + featherOffset;
      v.stack = uint8_t(purple > 0.5f && options.purpleStack > 0 ? options.purpleStack : options.stack.value_or(0));
    }
    writer.writeBarb(vertices);
  };
  write(rachisPolyline(design), kBarbuleH, 0.0f);
  for (int side : {-1, 1}) {
    for (int b = 0; b < design.barbsPerSide; ++b) {
      if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return false;
      float lengthScale = 1.0f + 0.05f * symmetricJitter(rng);
      float angleOffset = 0.035f * symmetricJitter(rng);
      float barbuleH = kBarbuleH * (1.0f + 0.04f * symmetricJitter(rng));
      float thicknessOffset = kBarbThicknessSpread * symmetricJitter(rng);
      write(barbPolyline(design, side, b, lengthScale, angleOffset), barbuleH, thicknessOffset);
    }
  }
  return true;
}

}  // namespace

namespace {
std::string number(float value) { return fmt::format("{}", value); }
}  // namespace

FeatherGenerationSummary generateFeatherPly(const FeatherGenerationOptions& options, const std::string& path) {
  if (options.neck && options.feathers < 1) throw std::invalid_argument("a neck needs at least one feather");
  if (options.barbsPerSide < 0) throw std::invalid_argument("the number of barbs per side cannot be negative");
  // Every feather is at least a rachis and a barb on each side; checked before the neck's layout,
  // which takes memory by the feather.
  if (options.neck && size_t(options.feathers) > kMaxFeatherFaces / 3)
    throw std::invalid_argument(
        fmt::format("{} feathers are too many: a feather PLY holds at most {} faces, 3 or "
                    "more to a feather, so at most {} feathers",
                    options.feathers, kMaxFeatherFaces, kMaxFeatherFaces / 3));
  const std::pair<const char*, float> thicknesses[] = {{"height", options.greenHeight},
                                                       {"purple height", options.purpleHeight},
                                                       {"height spread", options.heightSpread}};
  for (const auto& [name, value] : thicknesses)
    if (!(std::isfinite(value) && value >= 0.0f))
      throw std::invalid_argument(std::string("the ") + name + " must be a number of micrometres, at least 0, not " +
                                  number(value));
  // The thinnest cortex written: each feather's spread and each barb's come on top of the colours'.
  const float thinnest = std::min(options.greenHeight, options.neck ? options.purpleHeight : options.greenHeight) -
                         options.heightSpread - kBarbThicknessSpread;
  if (thinnest < 0.0f)
    throw std::invalid_argument("a height spread of " + number(options.heightSpread) + " um about a height of " +
                                number(thinnest + options.heightSpread + kBarbThicknessSpread) + " um (with +-" +
                                number(kBarbThicknessSpread) +
                                " um from barb to barb) would make cortices thinner than 0");
  if (!std::isfinite(options.purpleBelow))
    throw std::invalid_argument("the height where purple begins must be a number, not " + number(options.purpleBelow));
  if (!(std::isfinite(options.colourBlend) && options.colourBlend >= 0.0f))
    throw std::invalid_argument("the colour blend must be a width of at least 0, not " + number(options.colourBlend));
  for (int stack : {options.purpleStack, options.stack.value_or(0)})
    if (stack < 0 || stack > kMaxVertexLayerStack)
      throw std::invalid_argument("a layer stack is a whole number from 0 to " + std::to_string(kMaxVertexLayerStack) +
                                  ", not " + std::to_string(stack));
  if (options.purpleStack != 0 && !options.neck)
    throw std::invalid_argument("a purple layer stack applies to a neck: a single feather has no purple barbules");
  const float barbWidth = FeatherShapeParams().barbWidth;

  FeatherDesign design;
  NeckLayout layout;
  if (options.neck) {
    layout = layOutNeck(options.feathers, options.seed);
    design.length = layout.featherLength;
    design.width = layout.featherWidth;
  } else {
    FeatherPlacement centred;
    centred.base = Vec2(0.0f, -0.5f * design.length);
    centred.seed = hashCombine(options.seed, 0);
    layout.feathers.push_back(centred);
  }
  const float meanWidth = FeatherShape::kMeanWidthFraction;
  design.barbsPerSide = options.barbsPerSide > 0 ? options.barbsPerSide : barbsToTile(design, barbWidth, meanWidth);
  design.rachisHalfWidth = 0.5f * barbWidth;

  FeatherGenerationSummary summary;
  summary.feathers = layout.feathers.size();
  summary.barbs = summary.feathers * 2 * size_t(design.barbsPerSide);
  summary.faces = summary.barbs + summary.feathers;
  summary.vertices = summary.faces * kBarbVertices;
  summary.tilingBarbWidth = barbSpacing(design) / meanWidth;
  if (summary.faces > kMaxFeatherFaces)
    throw std::invalid_argument(
        fmt::format("{} barbs per side make {} faces, more than the {} a feather PLY holds "
                    "(at most {} barbs per side for {} feather{})",
                    design.barbsPerSide, summary.faces, kMaxFeatherFaces, (kMaxFeatherFaces / summary.feathers - 1) / 2,
                    summary.feathers, summary.feathers == 1 ? "" : "s"));

  NeckSurface neck;
  NeckColouring colouring(options.seed, options.purpleBelow, options.colourBlend);
  FeatherPlyWriter writer(path, options.binary, summary.faces, summary.tilingBarbWidth,
                          {/*barbuleValues=*/true, /*layerStack=*/options.stack || options.purpleStack > 0});
  for (const FeatherPlacement& placement : layout.feathers) {
    VaneMapping mapping(options.neck ? &neck : nullptr, placement, design);
    if (!writeFeather(design, mapping, options.neck ? &colouring : nullptr, options, placement.seed, writer)) {
      summary.written = false;  // the writer removes its temporary file
      return summary;
    }
  }
  writer.commit();
  return summary;
}

}  // namespace columba
