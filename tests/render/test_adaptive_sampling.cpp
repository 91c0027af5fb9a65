#include <gtest/gtest.h>

#include <cmath>
#include "render/sample_allocation.h"
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

// A pilot pixel of two samples a and b: sum a + b, one sample's variance (a - b)^2 / 2.
PilotPixel twoSamples(double a, double b) { return {a + b, a * a + b * b, true}; }

// A camera looking at the horizon: the upper half of the image sees a uniform sky of radiance 1
// (its samples vary only with their wavelengths), the lower half a diffuse ground of albedo 0.5 lit
// by that sky, which reflects 0.5 (much noisier: one emitter and one BSDF sample per pixel sample).
// A grey ground under a white sky. The ground is lit by emitter sampling alone, which draws sky
// directions uniformly (half of them under the ground): noisy, where the sky seen directly has only
// the noise of its wavelengths.
std::string horizonScene(int spp) {
  return R"(<scene version="3.0.0"><integrator type="direct"><integer name="emitter_samples" value="1"/>
      <integer name="bsdf_samples" value="0"/></integrator>
    <sensor type="perspective"><float name="fov" value="60"/>
      <transform name="to_world"><lookat origin="0, 0, 1" target="0, 10, 1" up="0, 0, 1"/></transform>
      <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="32"/><rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value=")" +
         std::to_string(spp) + R"("/></sampler></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="1000"/></transform>
      <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
    <emitter type="constant"><float name="radiance" value="1"/></emitter></scene>)";
}

// RMS difference of the green channel from `expected` over rows [y0, y1).
double rmsError(const Image& image, int y0, int y1, float expected) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width; ++x) sum += std::pow(image.pixel(x, y)[1] - expected, 2.0);
  return std::sqrt(sum / (double(y1 - y0) * image.width));
}

}  // namespace

TEST(SamplePlan, SamplesGoWhereTheNeighboursVaryAndTheBudgetIsKept) {
  // One row: the first two pixels vary (one sample's variance 2), the last two do not. From the
  // neighbours: s = sqrt(2), sqrt((2 + 0) / 2) = 1, sqrt((2 + 0) / 2) = 1, sqrt(0) = 0, sum
  // 3.41421. A mean budget of 10 leaves 40 - 4 x 2 = 32 to share: 13.25, 9.37, 9.37, 0 ->
  // 13, 9, 9, 0 more.
  std::vector<PilotPixel> pilot = {twoSamples(0, 2), twoSamples(0, 2), twoSamples(1, 1), twoSamples(1, 1)};
  SamplePlan plan = planSamples(pilot, 4, 1, {2, 10.0, 0.0, 1 << 24});
  EXPECT_EQ(plan.counts, (std::vector<int>{15, 11, 11, 2}));
  EXPECT_EQ(plan.total, 39);
  // Mean luminance 1; predicted error sqrt((2 / 15 + 1 / 11 + 1 / 11 + 0) / 4).
  EXPECT_NEAR(plan.predictedRelativeError, std::sqrt((2.0 / 15 + 2.0 / 11) / 4), 1e-12);

  // A target of 0.5 needs only (sum s)^2 / (4 x 0.5^2) = 11.657 samples: 3.657 to share.
  SamplePlan targeted = planSamples(pilot, 4, 1, {2, 10.0, 0.5, 1 << 24});
  EXPECT_EQ(targeted.counts, (std::vector<int>{4, 3, 3, 2}));
  // The cap holds.
  EXPECT_EQ(planSamples(pilot, 4, 1, {2, 10.0, 0.0, 12}).counts, (std::vector<int>{12, 11, 11, 2}));
}

TEST(SamplePlan, APixelsOwnPilotDoesNotChooseItsCountAndUnseenPixelsTakeNone) {
  // The middle pixel varies wildly, its neighbours not at all: it keeps its pilot (its count must
  // not depend on its own samples, or its mean would be biased); the neighbours of a varying pixel
  // get the extra samples instead. Unseen pixels take no samples and are no one's neighbours.
  std::vector<PilotPixel> pilot = {twoSamples(1, 1), twoSamples(0, 100), twoSamples(1, 1), PilotPixel{},
                                   twoSamples(1, 1)};
  SamplePlan plan = planSamples(pilot, 5, 1, {2, 6.0, 0.0, 1 << 24});
  EXPECT_EQ(plan.counts[1], 2);
  EXPECT_EQ(plan.counts[3], 0);
  EXPECT_EQ(plan.counts[0], plan.counts[2]);
  EXPECT_GT(plan.counts[0], 2);
  EXPECT_EQ(plan.counts[4], 2);  // its only seen neighbour is unseen-adjacent: none vary
}

TEST(AdaptiveSampling, SpendsTheBudgetWhereTheImageIsNoisyAndStaysUnbiased) {
  RenderSettings uniform;
  uniform.samplesPerPixel = 16;
  uniform.seed = 3;
  RenderSettings adaptive = uniform;
  adaptive.adaptive = true;
  RenderStats uniformStats, adaptiveStats;
  Image u = renderSceneString(horizonScene(16), uniform, &uniformStats);
  Image a = renderSceneString(horizonScene(16), adaptive, &adaptiveStats);
  ASSERT_TRUE(adaptiveStats.complete);
  EXPECT_EQ(adaptiveStats.pilotSamples, 4);
  EXPECT_LT(adaptiveStats.fewestSamples, 12);  // the sky
  EXPECT_GT(adaptiveStats.mostSamples, 24);    // the ground
  // The same budget, up to rounding (at most half a sample per pixel either way).
  EXPECT_NEAR(double(adaptiveStats.samples), double(uniformStats.samples), 0.5 * 32 * 32);
  // Both unbiased (sky 1, ground 0.5), the ground closer to 0.5 than in the uniform render.
  EXPECT_NEAR(meanColour(a, 0, 0, 32, 12)[1], 1.0f, 0.005f);
  EXPECT_NEAR(meanColour(a, 0, 20, 32, 32)[1], 0.5f, 0.01f);
  double uniformError = rmsError(u, 20, 32, 0.5f), adaptiveError = rmsError(a, 20, 32, 0.5f);
  EXPECT_LT(adaptiveError, 0.9 * uniformError) << "uniform " << uniformError << ", adaptive " << adaptiveError;
}

TEST(AdaptiveSampling, IsBitIdenticalForAnyThreadCount) {
  RenderSettings settings;
  settings.samplesPerPixel = 8;
  settings.adaptive = true;
  settings.threads = 1;
  Image one = renderSceneString(horizonScene(8), settings);
  settings.threads = 3;
  Image three = renderSceneString(horizonScene(8), settings);
  ASSERT_EQ(one.rgb.size(), three.rgb.size());
  EXPECT_TRUE(bitIdentical(one.rgb, three.rgb));
}

TEST(AdaptiveSampling, TargetErrorSpendsLessAndRefusesPieces) {
  RenderSettings settings;
  settings.samplesPerPixel = 64;
  settings.adaptive = true;
  settings.targetError = 0.2;
  RenderStats stats;
  renderSceneString(horizonScene(64), settings, &stats);
  EXPECT_LT(stats.samples, uint64_t(64 * 32 * 32) / 2);
  EXPECT_LE(stats.predictedRelativeError, 0.2 * 1.01);

  RenderSettings part = settings;
  part.window = PixelRect{0, 0, 16, 32};
  EXPECT_THROW(renderSceneString(horizonScene(64), part), std::runtime_error);
  RenderSettings pass = settings;
  pass.sampleEnd = 32;
  EXPECT_THROW(renderSceneString(horizonScene(64), pass), std::runtime_error);
  RenderSettings few = settings;
  few.samplesPerPixel = 2;
  EXPECT_THROW(renderSceneString(horizonScene(2), few), std::runtime_error);
}

TEST(AdaptiveSampling, ACroppedFilmIsPlannedWithinTheCrop) {
  // The same scene with hdrfilm's crop window: the plan covers the crop's pixels only, and every
  // pixel of the crop is rendered (the sky and the ground both show).
  std::string scene = horizonScene(8);
  const std::string film = R"(<rfilter type="box"/></film>)";
  scene.replace(scene.find(film), film.size(),
                R"(<integer name="crop_offset_x" value="5"/><integer name="crop_offset_y" value="9"/>
      <integer name="crop_width" value="20"/><integer name="crop_height" value="16"/><rfilter type="box"/></film>)");
  RenderSettings settings;
  settings.samplesPerPixel = 8;
  settings.adaptive = true;
  RenderStats stats;
  Image image = renderSceneString(scene, settings, &stats);
  ASSERT_EQ(image.width, 20);
  ASSERT_EQ(image.height, 16);
  EXPECT_NEAR(double(stats.samples), 8.0 * 20 * 16, 0.5 * 20 * 16);
  EXPECT_GT(meanColour(image, 0, 0, 20, 2)[1], 0.9f);    // sky
  EXPECT_LT(meanColour(image, 0, 14, 20, 16)[1], 0.7f);  // ground
}
