// Camera samples splatted as Mitsuba's hdrfilm does: each sample, uniform in its pixel, counts for
// every pixel its filter reaches, and each pixel is divided by its filter's mass on the film.
// Checked on images with closed-form pixels: a uniform view (every pixel, the film's edges
// included, is the radiance) and a step in radiance (each pixel is the step's share of its filter
// on the film, integrated here from the filter's eval independently of the renderer's table).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include "film/box_filter.h"
#include "film/gaussian_filter.h"
#include "film/tent_filter.h"
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

constexpr int kWidth = 32, kHeight = 8;
// The step's edge on the film, in pixels from its left: world x = 1 - 2 (13.3 / 32) under the
// orthographic camera, whose film x maps to camera x = 1 - 2 x / width.
constexpr double kEdge = 13.3;

// An orthographic view along +z of an emitting rectangle covering world x >= 1 - 2 kEdge / kWidth
// (the film left of kEdge), or, with `uniform`, of a constant emitter alone.
std::string stepScene(const std::string& rfilter, bool uniform, int spp) {
  const double x0 = 1.0 - 2.0 * kEdge / kWidth;
  const std::string lit = uniform ? R"(<emitter type="constant"><float name="radiance" value="1"/></emitter>)"
                                  : R"(<shape type="rectangle"><transform name="to_world"><scale x="5" y="5"/>
        <rotate y="1" angle="180"/><translate x=")" +
                                        std::to_string(5.0 + x0) +
                                        R"(" z="2"/></transform>
        <emitter type="area"><float name="radiance" value="1"/></emitter></shape>)";
  return R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="orthographic">
      <film type="hdrfilm"><integer name="width" value=")" +
         std::to_string(kWidth) + R"("/><integer name="height" value=")" + std::to_string(kHeight) + R"("/>)" +
         rfilter + R"(</film>
      <sampler type="ldsampler"><integer name="sample_count" value=")" +
         std::to_string(spp) + R"("/></sampler></sensor>)" + lit + "</scene>";
}

double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// The filter's integral over offsets [a, b], by the midpoint rule on its eval.
double filterMass(const ReconstructionFilter& filter, double a, double b) {
  const double r = filter.radius();
  a = std::max(a, -r);
  b = std::min(b, r);
  if (!(b > a)) return 0.0;
  const int steps = 20000;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) sum += filter.eval(float(a + (i + 0.5) * (b - a) / steps));
  return sum * (b - a) / steps;
}

struct FilterCase {
  std::string xml;
  std::shared_ptr<ReconstructionFilter> filter;
};

std::vector<FilterCase> filterCases() {
  return {{R"(<rfilter type="box"/>)", std::make_shared<BoxFilter>()},
          {R"(<rfilter type="tent"/>)", std::make_shared<TentFilter>(1.0f)},
          {"", std::make_shared<GaussianFilter>(0.5f)},
          {R"(<rfilter type="gaussian"><float name="stddev" value="1"/></rfilter>)",
           std::make_shared<GaussianFilter>(1.0f)}};
}

}  // namespace

TEST(CameraSplats, AUniformViewIsUniformUpToTheFilmsEdges) {
  // Without the division by each pixel's mass on the film, the corner pixels would keep about
  // half (Gaussian, stddev 0.5) to a quarter (stddev 1) of the radiance.
  for (const FilterCase& c : filterCases()) {
    const Image image = renderSceneString(stepScene(c.xml, true, 64));
    const Vec3 meanRgb = meanColour(image, 0, 0, kWidth, kHeight);
    const double mean = luminance(&meanRgb.x);
    ASSERT_GT(mean, 0.5) << c.xml;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) worst = std::max(worst, std::abs(luminance(image.pixel(x, y)) / mean - 1.0));
    EXPECT_LT(worst, 0.01) << c.xml;
  }
}

TEST(CameraSplats, AStepInRadianceIsTheStepsShareOfEachPixelsFilter) {
  for (const FilterCase& c : filterCases()) {
    const Image image = renderSceneString(stepScene(c.xml, false, 64));
    // Each column's mean over the rows (the step does not depend on y, nor then does a pixel).
    std::vector<double> column(kWidth, 0.0);
    for (int x = 0; x < kWidth; ++x)
      for (int y = 0; y < kHeight; ++y) column[size_t(x)] += luminance(image.pixel(x, y)) / kHeight;
    const double lit = column[0];  // the radiance: the film's first pixel lies wholly left of the step
    ASSERT_GT(lit, 0.5) << c.xml;
    double worst = 0.0;
    int partial = 0;
    for (int x = 0; x < kWidth; ++x) {
      const double centre = x + 0.5;
      const double expected =
          filterMass(*c.filter, -centre, kEdge - centre) / filterMass(*c.filter, -centre, kWidth - centre);
      worst = std::max(worst, std::abs(column[size_t(x)] / lit - expected));
      partial += expected > 0.01 && expected < 0.99;
    }
    EXPECT_LT(worst, 0.01) << c.xml;
    EXPECT_GE(partial, 1) << c.xml;  // the step falls within some pixel's footprint
  }
}
