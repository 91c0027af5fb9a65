// Light-transport tests with answers known in closed form or from another estimator: a
// multi-bounce furnace that reaches the Russian-roulette depth, and the path tracer's
// combination of emitter and BSDF sampling against each strategy alone, with several emitters
// of different kinds. Each compares a mean with its own standard error, so a bias of a few
// tenths of a percent fails and noise does not.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

// Mean luminance over the image and its standard error, for images whose pixels are independent
// estimates of one value.
Estimate pixelMean(const Image& image) {
  double sum = 0, sumSquares = 0;
  const int n = image.width * image.height;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double v = luminance(image, x, y);
      sum += v;
      sumSquares += v * v;
    }
  double mean = sum / n, variance = (sumSquares - n * mean * mean) / (n - 1);
  return {mean, std::sqrt(variance / n)};
}

// Inside a closed sphere whose inner surface is diffuse with albedo a and emits Le, every ray
// sees L = Le (1 + a + ... + a^(m-1)) for paths of at most m vertices after the camera, and
// Le / (1 - a) without a limit. Le is white of luminance 1 (a <spectrum> value, as Mitsuba
// reads emitters), so the answer is the image's luminance.
std::string closedDiffuseSphere(float albedo, int maxDepth, int rrDepth) {
  return R"(<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value=")" +
         std::to_string(maxDepth) + R"("/>
      <integer name="rr_depth" value=")" +
         std::to_string(rrDepth) + R"("/></integrator>
    <sensor type="perspective"><float name="fov" value="90"/>
      <transform name="to_world"><lookat origin="0.1, 0.2, 0" target="1, 0.2, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/>
        <rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="64"/></sampler></sensor>
    <shape type="sphere"><float name="radius" value="1"/><boolean name="flip_normals" value="true"/>
      <bsdf type="diffuse"><float name="reflectance" value=")" +
         std::to_string(albedo) + R"("/></bsdf>
      <emitter type="area"><spectrum name="radiance" value="1"/></emitter></shape>
    </scene>)";
}

double closedSphereRadiance(double albedo, int maxDepth) {
  if (maxDepth < 0) return 1.0 / (1.0 - albedo);
  return (1.0 - std::pow(albedo, maxDepth)) / (1.0 - albedo);
}

// White's luminance is 1 only to the accuracy of the spectral tables (D65, CIE matching
// functions) and the wavelength sampling: their agreement, measured, is within 0.1 %.
constexpr double kWhiteLuminanceTolerance = 0.002;
// Means further than this many standard errors apart fail (a 1-in-1.7-million chance when the
// estimators agree and their errors are normal).
constexpr double kSigmas = 5.0;

}  // namespace

TEST(Transport, ClosedDiffuseSphereMatchesTheGeometricSeriesSlow) {
  const float albedo = 0.8f;
  struct Depths {
    int maxDepth, rrDepth;
  };
  // Unlimited paths with roulette from the first, third and fifth bounce; limited ones that
  // stop before, at and after the roulette starts.
  for (Depths d : {Depths{-1, 1}, Depths{-1, 3}, Depths{-1, 5}, Depths{3, 5}, Depths{8, 2}, Depths{12, 5}}) {
    Estimate e = pixelMean(renderSceneString(closedDiffuseSphere(albedo, d.maxDepth, d.rrDepth)));
    double expected = closedSphereRadiance(albedo, d.maxDepth);
    SCOPED_TRACE("max_depth " + std::to_string(d.maxDepth) + ", rr_depth " + std::to_string(d.rrDepth));
    EXPECT_NEAR(e.mean, expected, kSigmas * e.standardError + kWhiteLuminanceTolerance * expected)
        << "standard error " << e.standardError;
    std::printf("furnace max_depth %3d rr_depth %d: %.4f (closed form %.4f, standard error %.4f)\n", d.maxDepth,
                d.rrDepth, e.mean, expected, e.standardError);
  }
}

namespace {

// A diffuse room corner with a glossy sphere, lit at once by a rectangular area light, a small
// spherical area light and a uniform sky: three emitters of two kinds, so emitter sampling
// chooses among them and the choice's probability enters every MIS weight.
std::string threeEmitterScene(const std::string& strategy, int emitterCandidates = 1) {
  return R"(<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="4"/>
      <integer name="emitter_candidates" value=")" +
         std::to_string(emitterCandidates) + R"("/>
      <string name="strategy" value=")" +
         strategy + R"("/></integrator>
    <sensor type="perspective"><float name="fov" value="50"/>
      <transform name="to_world"><lookat origin="0, 1.2, 4" target="0, 0.3, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/>
        <rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="256"/></sampler></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
      <bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.6, 0.5"/></bsdf></shape>
    <shape type="rectangle"><transform name="to_world"><scale value="3"/><translate z="-1.5"/></transform>
      <bsdf type="diffuse"><float name="reflectance" value="0.6"/></bsdf></shape>
    <shape type="sphere"><point name="center" x="0.4" y="0.5" z="0"/><float name="radius" value="0.5"/>
      <bsdf type="roughplastic"><float name="alpha" value="0.3"/></bsdf></shape>
    <shape type="rectangle"><transform name="to_world"><scale value="0.6"/><rotate x="1" angle="90"/>
        <translate x="-0.6" y="2" z="0"/></transform>
      <emitter type="area"><spectrum name="radiance" value="6"/></emitter></shape>
    <shape type="sphere"><point name="center" x="-0.8" y="0.35" z="0.6"/><float name="radius" value="0.2"/>
      <emitter type="area"><rgb name="radiance" value="8, 4, 2"/></emitter></shape>
    <emitter type="constant"><spectrum name="radiance" value="0.5"/></emitter>
    </scene>)";
}

Estimate meanOverSeeds(const std::string& strategy, int renders, int emitterCandidates = 1) {
  return meanLuminanceOverSeeds(threeEmitterScene(strategy, emitterCandidates), renders, 1000);
}

}  // namespace

TEST(Transport, MISAgreesWithEmitterSamplingAndBSDFSamplingAloneSlow) {
  const int renders = 8;
  Estimate mis = meanOverSeeds("mis", renders), emitter = meanOverSeeds("emitter", renders),
           bsdf = meanOverSeeds("bsdf", renders);
  std::printf("mean luminance: mis %.5f +- %.5f, emitter sampling %.5f +- %.5f, BSDF sampling %.5f +- %.5f\n", mis.mean,
              mis.standardError, emitter.mean, emitter.standardError, bsdf.mean, bsdf.standardError);
  EXPECT_LT(standardErrorsApart(mis, emitter), kSigmas) << "MIS and emitter sampling disagree";
  EXPECT_LT(standardErrorsApart(mis, bsdf), kSigmas) << "MIS and BSDF sampling disagree";
  EXPECT_LT(standardErrorsApart(emitter, bsdf), kSigmas) << "emitter and BSDF sampling disagree";
  // The combination must also be the least noisy of the three.
  EXPECT_LT(mis.standardError, emitter.standardError * 1.2);
  EXPECT_LT(mis.standardError, bsdf.standardError);
}

// Resampled emitter samples are another unbiased estimate of the same image: with 4 candidates
// per first vertex, chosen among three emitters of two kinds by a glossy and two diffuse BSDFs,
// the mean must agree with one emitter sample's.
TEST(Transport, ResampledEmitterSamplesAgreeWithOneEmitterSampleSlow) {
  const int renders = 8;
  Estimate one = meanOverSeeds("mis", renders), resampled = meanOverSeeds("mis", renders, 4),
           resampledAlone = meanOverSeeds("emitter", renders, 4);
  std::printf(
      "mean luminance: 1 emitter sample %.5f +- %.5f, 4 candidates %.5f +- %.5f, 4 candidates without BSDF "
      "samples %.5f +- %.5f\n",
      one.mean, one.standardError, resampled.mean, resampled.standardError, resampledAlone.mean,
      resampledAlone.standardError);
  EXPECT_LT(standardErrorsApart(resampled, one), kSigmas);
  EXPECT_LT(standardErrorsApart(resampledAlone, one), kSigmas);
}

TEST(Transport, EmitterCandidatesOutsideZeroToEightAreAnErrorSlow) {
  for (const char* value : {"9", "-2"}) {
    std::string xml = std::string(R"(<scene version="3.0.0"><integrator type="path">
      <integer name="emitter_candidates" value=")") +
                      value + R"("/></integrator></scene>)";
    try {
      renderSceneString(xml);
      FAIL() << "no error for " << value;
    } catch (const InputError& e) {
      EXPECT_NE(
          std::string(e.what()).find(
              std::string("emitter_candidates must be 0 (automatic) or a whole number from 1 to 8, not ") + value),
          std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(":2: <integrator>"), std::string::npos) << e.what();  // file and line
    }
  }
}

namespace {

// A barbule vane under a 1 x 0.1 rectangular light (or a directional light) and a uniform sky, as
// in the neck's lighting: the barbule's narrow R lobe sees a small part of the rectangle.
std::string barbuleScene(int emitterCandidates, bool directional = false) {
  const std::string light =
      directional ? R"(<emitter type="directional"><vector name="direction" x="0.2" y="0.3" z="-1"/>
                         <spectrum name="irradiance" value="3"/></emitter>)"
                  : R"(<shape type="rectangle"><transform name="to_world"><scale x="0.5" y="0.05" z="0.5"/>
                         <rotate y="1" angle="180"/><translate z="1"/></transform>
                         <emitter type="area"><spectrum name="radiance" value="10"/></emitter></shape>)";
  return R"(<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="3"/>
      <integer name="emitter_candidates" value=")" +
         std::to_string(emitterCandidates) + R"("/></integrator>
    <sensor type="perspective"><float name="fov" value="60"/>
      <transform name="to_world"><lookat origin="0, -0.4, 0.8" target="0, 0.1, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/>
        <rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="128"/></sampler></sensor>
    <shape type="rectangle"><bsdf type="barbulebsdf"><float name="b" value="0.25"/>
      <float name="mu" value="-0.35"/></bsdf></shape>)" +
         light + R"(<emitter type="constant"><spectrum name="radiance" value="0.2"/></emitter>
    </scene>)";
}

}  // namespace

// The barbule's candidates are chosen by its cheap targets (R and a bound of TRT), not its values:
// the mean must still agree with one emitter sample's.
TEST(Transport, BarbuleResampledByItsTargetsAgreesWithOneEmitterSampleSlow) {
  const int renders = 8;
  Estimate one = meanLuminanceOverSeeds(barbuleScene(1), renders, 2000),
           automatic = meanLuminanceOverSeeds(barbuleScene(0), renders, 2000),
           eight = meanLuminanceOverSeeds(barbuleScene(8), renders, 2000);
  std::printf("mean luminance: 1 emitter sample %.5f +- %.5f, automatic %.5f +- %.5f, 8 candidates %.5f +- %.5f\n",
              one.mean, one.standardError, automatic.mean, automatic.standardError, eight.mean, eight.standardError);
  EXPECT_LT(standardErrorsApart(automatic, one), kSigmas);
  EXPECT_LT(standardErrorsApart(eight, one), kSigmas);
}

// emitter_candidates 0 (the default) draws 3 candidates where the BSDF has cheap resampling
// targets and an emitter with extent is drawn from, and 1 elsewhere: the same pixels as those
// explicit counts.
TEST(Transport, AutomaticEmitterCandidatesAreThreeAtABarbuleUnderAnAreaLightAndOneElsewhereSlow) {
  RenderSettings settings;
  settings.seed = 7;
  EXPECT_TRUE(samePixels(renderSceneString(barbuleScene(0), settings), renderSceneString(barbuleScene(3), settings)));
  EXPECT_FALSE(samePixels(renderSceneString(barbuleScene(0), settings), renderSceneString(barbuleScene(1), settings)));
  // Under a directional light (the sky left to BSDF samples) every candidate would be the same.
  EXPECT_TRUE(samePixels(renderSceneString(barbuleScene(0, true), settings),
                         renderSceneString(barbuleScene(1, true), settings)));
  // Diffuse and glossy BSDFs evaluate in full toward every candidate.
  EXPECT_TRUE(samePixels(renderSceneString(threeEmitterScene("mis", 0), settings),
                         renderSceneString(threeEmitterScene("mis", 1), settings)));
}

TEST(Transport, StrategyOtherThanTheThreeIsAnErrorSlow) {
  std::string xml = R"(<scene version="3.0.0"><integrator type="path"><string name="strategy" value="light"/>
    </integrator></scene>)";
  try {
    renderSceneString(xml);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("strategy must be 'mis', 'emitter' or 'bsdf', not 'light'"), std::string::npos)
        << e.what();
  }
}
