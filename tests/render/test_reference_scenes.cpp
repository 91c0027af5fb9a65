// The paper's own scene files, loaded unchanged from the reference folder kept beside the
// repository (COLUMBA_SHARED_DIR; not part of it, so the tests skip where it is missing). The
// feather PLY files they name were never published: generated stand-ins are placed where they look.
#include <gtest/gtest.h>

#include <filesystem>

#include "builtin/builtin_plugins.h"
#include "feather/feather_generator.h"
#include "render/renderer.h"
#include "scene/scene.h"

using namespace columba;
namespace fs = std::filesystem;

namespace {
const fs::path kReferenceScenes = fs::path(COLUMBA_SHARED_DIR) / "reference" / "scenes";

// Why these tests cannot run here ("" when they can).
std::string referenceScenesMissing() {
  if (fs::is_directory(kReferenceScenes)) return "";
  return "the reference scene files are not available (looked in " + kReferenceScenes.string() + ")";
}

#define SKIP_WITHOUT_REFERENCE_SCENES()                                                         \
  do {                                                                                          \
    if (std::string reason = referenceScenesMissing(); !reason.empty()) GTEST_SKIP() << reason; \
  } while (false)

Image renderFile(const fs::path& path, const Defines& defines, int spp) {
  ParsedScene parsed = loadSceneFile(path.string(), defines, builtinPlugins());
  Scene scene(parsed, SourceLocation{path.string(), 0});
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  EXPECT_TRUE(stats.complete);
  return image;
}

double meanLuminance(const Image& image) {
  double sum = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3)
    sum += 0.2126 * image.rgb[i] + 0.7152 * image.rgb[i + 1] + 0.0722 * image.rgb[i + 2];
  return sum / (image.rgb.size() / 3);
}

bool allFinite(const Image& image) {
  for (float v : image.rgb)
    if (!std::isfinite(v)) return false;
  return true;
}

// A directory mirroring the reference scene directory, plus generated feathers.
class ReferenceSceneDirectory {
 public:
  ReferenceSceneDirectory() {
    dir_ = fs::temp_directory_path() / ("columba_reference_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "feathers");
    for (const char* name : {"la.xml", "neck.xml", "meshes"}) fs::create_symlink(kReferenceScenes / name, dir_ / name);
    FeatherGenerationOptions single;
    single.binary = true;
    generateFeatherPly(single, (dir_ / "feathers" / "feather.ply").string());
    FeatherGenerationOptions neck = single;
    neck.neck = true;
    neck.feathers = 12;
    generateFeatherPly(neck, (dir_ / "feathers" / "feathers.ply").string());
  }
  ~ReferenceSceneDirectory() { fs::remove_all(dir_); }
  fs::path operator/(const char* name) const { return dir_ / name; }

 private:
  fs::path dir_;
};
}  // namespace

TEST(ReferenceScenes, BSDFVisualisationsRenderSlow) {
  SKIP_WITHOUT_REFERENCE_SCENES();
  for (const char* name : {"simulation1.xml", "simulation2.xml", "simulation3.xml"}) {
    SCOPED_TRACE(name);
    Image image = renderFile(kReferenceScenes / name, {{"res", "48"}, {"spp", "8"}}, 0);
    EXPECT_EQ(image.width, 48);
    EXPECT_TRUE(allFinite(image));
    EXPECT_GT(meanLuminance(image), 1e-3);
    // The scatterometer disk: the corners are outside it and black.
    EXPECT_EQ(image.pixel(0, 0)[1], 0.0f);
  }
}

TEST(ReferenceScenes, LinearLightSequenceAndNeckRenderWithGeneratedFeathersSlow) {
  SKIP_WITHOUT_REFERENCE_SCENES();
  ReferenceSceneDirectory dir;
  for (const char* o : {"-1", "00", "06"}) {
    SCOPED_TRACE(o);
    Image image = renderFile(dir / "la.xml", {{"o", o}, {"res", "32"}, {"spp", "4"}}, 0);
    EXPECT_EQ(image.width, 32);
    EXPECT_TRUE(allFinite(image));
    EXPECT_GT(meanLuminance(image), 1e-4);
  }
  Image neck = renderFile(dir / "neck.xml", {{"spp", "1"}}, 1);
  EXPECT_EQ(neck.width, 1024);
  EXPECT_EQ(neck.height, 768);
  EXPECT_TRUE(allFinite(neck));
  EXPECT_GT(meanLuminance(neck), 1e-3);
}
