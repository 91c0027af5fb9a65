#include "feather/neck_layout.h"

#include "core/rng.h"

namespace columba {

namespace {
// The neck also curves away from the viewer above and below its middle.
constexpr float kMiddleY = 0.7f, kDrop = 0.3f, kDropScale = 1.9f;

float smoothstep(float e0, float e1, float x) {
  float t = clampf((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

float symmetricJitter(PCG32& rng) { return 2.0f * rng.nextFloat() - 1.0f; }
}  // namespace

Vec3 NeckSurface::point(float X, float Y) const {
  float a = X / kRadius, v = (Y - kMiddleY) / kDropScale;
  return {kCentreX + kRadius * std::sin(a), Y, kRadius * (std::cos(a) - 1.0f) - kDrop * v * v};
}

Vec3 NeckSurface::normal(float X, float Y) const {
  float a = X / kRadius;
  Vec3 alongX(std::cos(a), 0.0f, -std::sin(a));
  Vec3 alongY(0.0f, 1.0f, -2.0f * kDrop * (Y - kMiddleY) / (kDropScale * kDropScale));
  return normalize(cross(alongX, alongY));
}

NeckLayout layOutNeck(int featherCount, uint64_t seed) {
  NeckLayout layout;
  const float width = 2.0f * NeckSurface::kHalfWidth, height = NeckSurface::kBottom - NeckSurface::kTop;
  // Roughly square cells, one feather each.
  const int columns = std::max(1, int(std::lround(width / std::sqrt(width * height / float(featherCount)))));
  const int rows = (featherCount + columns - 1) / columns;
  layout.columnSpacing = width / float(columns);
  layout.rowSpacing = height / float(rows);
  // Each feather shows about the last 40% of its length and overlaps its neighbours' sides.
  layout.featherLength = 2.4f * layout.rowSpacing;
  layout.featherWidth = 1.6f * layout.columnSpacing;
  PCG32 rng(seed, 0x6e65636bULL);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns && int(layout.feathers.size()) < featherCount; ++c) {
      FeatherPlacement f;
      f.base.x = -NeckSurface::kHalfWidth + (float(c) + 0.5f + 0.15f * symmetricJitter(rng)) * layout.columnSpacing;
      // The first row starts above the top edge so that tips, not bases, fill the view.
      f.base.y = NeckSurface::kTop - 0.3f * layout.featherLength +
                 (float(r) + ((c % 2) ? 0.5f : 0.0f) + 0.1f * symmetricJitter(rng)) * layout.rowSpacing;
      f.heading = 0.1f * symmetricJitter(rng);
      f.scale = 1.0f + 0.06f * symmetricJitter(rng);
      // 0.15 keeps a neighbour half a row down a few barb thicknesses below.
      f.pitch = 0.15f;
      f.seed = hashCombine(seed, layout.feathers.size());
      layout.feathers.push_back(f);
    }
  }
  return layout;
}

NeckColouring::NeckColouring(uint64_t seed, float boundary, float blend) : boundary_(boundary), blend_(blend) {
  PCG32 rng(seed, 0x636f6c6fULL);
  phase1_ = kTwoPi * rng.nextFloat();
  phase2_ = kTwoPi * rng.nextFloat();
}

float NeckColouring::purple(float X, float Y) const {
  float boundary = boundary_ + 0.4f * std::sin(0.8f * X + phase1_) + 0.2f * std::sin(1.9f * X + phase2_);
  if (!(blend_ > 0.0f)) return Y >= boundary ? 1.0f : 0.0f;
  return smoothstep(-blend_, blend_, Y - boundary);
}

}  // namespace columba
