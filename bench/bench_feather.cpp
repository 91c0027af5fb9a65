// Ray-query throughput of the feather shape: the default scene's generated 60-feather neck, seen
// by its own camera at 256x192, with 1 or 16 (4x4 stratified) rays per pixel traced pixel by
// pixel as the renderer does. With one ray per pixel, a pixel spans a few barb segments and
// every query fetches geometry no earlier query has touched; with 16, a pixel's rays share it.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <vector>
#include "builtin/default_scene.h"
#include "scene/scene.h"

using namespace columba;

namespace {

const Scene& neckScene() {
  static const std::unique_ptr<Scene> scene = std::make_unique<Scene>(
      loadDefaultScene({{"width", "256"}, {"height", "192"}}), SourceLocation{"<default scene>", 0});
  return *scene;
}

const std::vector<Ray>& cameraRays(int raysPerPixelSide) {
  static std::map<int, std::vector<Ray>> cache;
  std::vector<Ray>& rays = cache[raysPerPixelSide];
  if (rays.empty()) {
    const Sensor& sensor = neckScene().sensor();
    const float step = 1.0f / float(raysPerPixelSide);
    for (int y = 0; y < sensor.film().height(); ++y)
      for (int x = 0; x < sensor.film().width(); ++x)
        for (int sy = 0; sy < raysPerPixelSide; ++sy)
          for (int sx = 0; sx < raysPerPixelSide; ++sx)
            if (auto ray = sensor.generateRay(
                    Vec2(float(x) + (float(sx) + 0.5f) * step, float(y) + (float(sy) + 0.5f) * step)))
              rays.push_back(*ray);
  }
  return rays;
}

// Nearest hits with their surface interactions, as the integrators ask for them.
void BM_FeatherNeckCameraRays(benchmark::State& state) {
  const Scene& scene = neckScene();
  const std::vector<Ray>& rays = cameraRays(int(state.range(0)));
  for (auto _ : state) {
    size_t hits = 0;
    for (const Ray& ray : rays) hits += scene.intersect(ray).has_value();
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
}
BENCHMARK(BM_FeatherNeckCameraRays)->ArgName("raysPerPixelSide")->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

}  // namespace
