// Ray-query throughput of the feather shape: the default scene's generated 60-feather neck, seen
// by its own camera at 256x192, one ray through every pixel centre.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>
#include "app/default_scene.h"
#include "scene/scene.h"

using namespace columba;

namespace {

struct NeckView {
  std::unique_ptr<Scene> scene;
  std::vector<Ray> cameraRays;
};

const NeckView& neckView() {
  static const NeckView view = [] {
    NeckView v;
    v.scene = std::make_unique<Scene>(loadDefaultScene({{"width", "256"}, {"height", "192"}}),
                                      SourceLocation{"<default scene>", 0});
    const Film& film = v.scene->sensor().film();
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        if (auto ray = v.scene->sensor().generateRay(Vec2(float(x) + 0.5f, float(y) + 0.5f)))
          v.cameraRays.push_back(*ray);
    return v;
  }();
  return view;
}

// Nearest hits with their surface interactions, as the integrators ask for them.
size_t traceCameraRays(const NeckView& view) {
  size_t hits = 0;
  for (const Ray& ray : view.cameraRays) hits += view.scene->intersect(ray).has_value();
  return hits;
}

void BM_FeatherNeckCameraRays(benchmark::State& state) {
  const NeckView& view = neckView();
  for (auto _ : state) benchmark::DoNotOptimize(traceCameraRays(view));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(view.cameraRays.size()));
}
BENCHMARK(BM_FeatherNeckCameraRays)->Unit(benchmark::kMillisecond);

}  // namespace
