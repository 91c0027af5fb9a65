#pragma once
// A procedural rock dove: its body (feather/rock_dove_body.h) covered by feathers laid along the
// direction they grow in, each a copy (an `instance`) of one of a few feather templates with its
// own placement and, on the neck, its own cortex thickness, so that a bird of thousands of
// feathers stores only the templates' barbs. Written as a scene fragment for <include>: the
// templates' feather PLYs, a shapegroup of each, an instance per feather and the body's shapes.
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "core/transform.h"
#include "feather/rock_dove_body.h"

namespace columba {

struct RockDoveOptions {
  uint64_t seed = 1;
  // Every feather's size is multiplied by this, and their number divided by its square: 0.7 gives
  // a bird of about twice as many, smaller feathers.
  float featherScale = 1.0f;
  int templates = 3;  // distinct feathers, each with its own barbs
  // Cortex thickness (um) of the neck's green and purple barbules, and each feather's spread about
  // them (uniform in +-spread).
  float greenHeight = 0.60f, purpleHeight = 0.51f, heightSpread = 0.012f;
  // Further parameters of the neck feathers' barbulebsdf, as a scene names and writes them (a
  // number becomes a <float>, anything else a <string>): a cross-section's profile_exponent, a
  // layer stack. The caller checks them (the feather command reads them as the plug-in does).
  std::vector<std::pair<std::string, std::string>> barbule;
  // The layer stack (1 to 15) of the neck's purple feathers (more purple than green), whose
  // barbule BSDF must then give layers_1 to layers_<purpleStack>; 0: one stack for all.
  int purpleStack = 0;
  const std::atomic<bool>* cancel = nullptr;
};

// One feather of the bird: which template, where (the template's frame, its rachis along +y from
// -0.6 to 0.6 and its vane facing +z, to the bird's space), and for the neck its cortex thickness.
struct PlacedFeather {
  int templateIndex = 0;
  size_t part = 0;  // of RockDoveBody::parts()
  Plumage plumage = Plumage::Grey;
  Matrix4 toWorld;
  float height = 0.0f;  // um; iridescent feathers only
  bool purple = false;  // iridescent and more purple than green
};

struct RockDovePlumage {
  std::vector<PlacedFeather> feathers;
};

// Deterministic for a seed. Every feather's outline lies outside the body (it is lifted off the
// skin where the body curves inward under it).
RockDovePlumage layOutRockDove(const RockDoveBody& body, const RockDoveOptions& options);

// The template's planform points, in its own frame, that the layout keeps outside the body.
std::vector<Vec3> featherOutline();

struct RockDoveSummary {
  size_t feathers = 0, iridescent = 0;
  size_t templateBarbs = 0;  // barbs stored, in all templates
  bool written = true;       // false when cancelled
};

// Writes `directory`/rock_dove.xml (a <scene> to include) and its templates
// `directory`/rock_dove_feather_K.ply (with a purple stack, each also as
// rock_dove_feather_K_purple.ply, every vertex choosing that stack, and the others stack 0).
// std::invalid_argument for options out of range.
RockDoveSummary writeRockDove(const RockDoveOptions& options, const std::string& directory);

}  // namespace columba
