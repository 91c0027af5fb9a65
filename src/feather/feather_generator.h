#pragma once
// Procedural feathers written as a feather PLY: one feather centred on the origin (for the
// single-feather scene), or a neck of many overlapping feathers (see neck_layout.h). Each
// feather is its rachis followed by its barbs, every one a face of the PLY; the rachis, as
// wide as a barb at its base, closes the seam where the barbs of both sides meet.
//
// Per-vertex barbule parameters, meant as the model's and written in the file convention of
// shapes/feather_barbule_values.h (file H = H / 2.5, file mu = -mu), so that the feather shape,
// like the original implementation, renders them as meant (the ramus tilt comes on top):
// - H (barbule spacing) 1.25, varied by +-4% from barb to barb (file H 0.5);
// - mu (barbule tilt) -0.35 rad (file mu 0.35);
// - height (keratin cortex thickness, um): 0.60 for green barbules, 0.51 for purple ones (or the
//   options' own), with +-0.008 from barb to barb and the options' spread from feather to feather. Through the thin
//   film, 0.60 um reflects green at normal incidence and turns lilac toward 40 degrees; 0.51 um reflects red and blue
//   (purple) at normal incidence and turns yellow-green toward 40 degrees, the colour swap of real neck feathers. A
//   single feather is green; on a neck the two blend smoothly over a boundary region.
// The vane normal is that of the feather's surface (the neck, the feather's pitch and its
// slight dome across the vane). The header records the barbwidth at which neighbouring barbs lie
// edge to edge (`comment barbwidth W`), which the feather shape uses when the scene sets none.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include "feather/neck_layout.h"
#include "io/feather_ply.h"

namespace columba {

inline constexpr float kGreenCortexThickness = 0.60f;   // um
inline constexpr float kPurpleCortexThickness = 0.51f;  // um
inline constexpr float kBarbThicknessSpread = 0.008f;   // um, from barb to barb

// The most faces (rachises and barbs) a file may hold: a feather PLY numbers its vertices with
// 32-bit signed integers, kBarbVertices to a face (2^25 faces, 2^31 vertices; some 77 GB binary).
inline constexpr size_t kMaxFeatherFaces = (size_t(1) << 31) / kBarbVertices;

struct FeatherGenerationOptions {
  bool neck = false;
  int feathers = 60;     // neck only
  int barbsPerSide = 0;  // 0: as many as lie edge to edge at the feather shape's default barbwidth
  uint64_t seed = 1;
  bool binary = false;
  const std::atomic<bool>* cancel = nullptr;  // when set, the generation stops at the next barb
  // Cortex thickness (um) of the green barbules (a single feather's) and of the purple ones, and
  // the spread of each feather's thickness about them (uniform in +-spread).
  float greenHeight = kGreenCortexThickness, purpleHeight = kPurpleCortexThickness, heightSpread = 0.0f;
  // Neck only: the height on the neck (surface coordinate Y, -1.6 at the top to 3.0 at the bottom)
  // around which green turns purple, and the width of the change on either side (0: sharp).
  float purpleBelow = NeckColouring::kDefaultBoundary, colourBlend = NeckColouring::kDefaultBlend;
  // The barbule BSDF's layer stack of every vertex (on a neck, of the green barbules; 0 when not
  // given), and on a neck of the purple barbules (where more than half purple; 0: as the green).
  // The file has the per-vertex `stack` only where one of them is given.
  std::optional<int> stack;
  int purpleStack = 0;
};

struct FeatherGenerationSummary {
  size_t feathers = 0, barbs = 0;
  size_t faces = 0, vertices = 0;  // in the PLY: every barb and every rachis
  // The `barbwidth` at which neighbouring (tapering) barbs lie edge to edge, in PLY units.
  float tilingBarbWidth = 0;
  bool written = true;  // false when cancelled: there is no file
};

// Writes the PLY to `path` (atomically: a temporary file renamed when complete, removed when the
// generation fails or is cancelled). Memory use does not grow with the number of barbs, and by
// some 40 bytes per feather of a neck. std::invalid_argument, naming the option and its value, for
// negative counts, a neck without feathers, more than kMaxFeatherFaces faces or a negative
// thickness.
FeatherGenerationSummary generateFeatherPly(const FeatherGenerationOptions& options, const std::string& path);

}  // namespace columba
