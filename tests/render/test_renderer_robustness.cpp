// The renderer under numerical failures and stop requests.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>

#include "builtin/builtin_plugins.h"
#include "integrators/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"

using namespace columba;

namespace {

const char* const kCamera = R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="60"/>
    <film type="hdrfilm"><integer name="width" value="$width"/><integer name="height" value="2"/>
      <rfilter type="box"/></film>
    <sampler type="independent"><integer name="sample_count" value="4"/></sampler></sensor>
</scene>)";

// Radiance 1 where the camera ray has d.x >= 0 (the left half of the image, as in Mitsuba's
// camera), NaN elsewhere; optionally asks the render to stop after a number of samples.
class TestIntegrator : public Integrator {
 public:
  Spectrum radiance(const Scene&, const Ray& ray, Sampler&, const Wavelengths&, uint64_t&) const override {
    if (++calls_ == stopAfter && stop) *stop = true;
    return Spectrum(ray.d.x < 0 ? std::numeric_limits<float>::quiet_NaN() : 1.0f);
  }
  mutable std::atomic<long long> calls_{0};
  long long stopAfter = 0;
  std::atomic<bool>* stop = nullptr;
};

struct TestScene {
  explicit TestScene(int width) {
    ParsedScene parsed = loadSceneString(kCamera, "<test>", ".", {{"width", std::to_string(width)}}, builtinPlugins());
    integrator = std::make_shared<TestIntegrator>();
    parsed.objects.push_back(integrator);
    scene = std::make_unique<Scene>(parsed, SourceLocation{"<test>", 0});
  }
  std::shared_ptr<TestIntegrator> integrator;
  std::unique_ptr<Scene> scene;
};

}  // namespace

TEST(RendererRobustness, NonFiniteSamplesAreCountedAndLeftOut) {
  TestScene test(4);
  RenderSettings settings;
  settings.threads = 1;
  RenderStats stats;
  Image image = renderImage(*test.scene, settings, stats);
  // The right half of the 4 x 2 image: 4 pixels of 4 samples.
  EXPECT_EQ(stats.nonFiniteSamples, 16u);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_TRUE(std::isfinite(image.pixel(x, y)[1]));
      EXPECT_EQ(image.pixel(x, y)[1] == 0.0f, x >= 2) << x << ", " << y;
    }
}

TEST(RendererRobustness, AStopIsAnsweredWithinASample) {
  // One pixel of 2^24 samples: the stop must not wait for the pixel to finish.
  TestScene test(1);
  std::atomic<bool> stop{false};
  test.integrator->stop = &stop;
  test.integrator->stopAfter = 10;
  RenderSettings settings;
  settings.samplesPerPixel = 1 << 24;
  settings.cancel = &stop;
  RenderStats stats;
  renderImage(*test.scene, settings, stats);
  EXPECT_FALSE(stats.complete);
  EXPECT_LE(test.integrator->calls_.load(), 10);
}
