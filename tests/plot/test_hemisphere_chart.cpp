// The scatterometer chart: markers where the visualiser's mapping puts the light and its mirror
// direction, rings of equal polar angle, corners outside the disk left white.
#include <gtest/gtest.h>

#include <cmath>
#include "core/math.h"
#include "plot/hemisphere_chart.h"

using namespace columba;

namespace {
bool near(const float* p, float r, float g, float b, float tol = 0.15f) {
  return std::abs(p[0] - r) < tol && std::abs(p[1] - g) < tol && std::abs(p[2] - b) < tol;
}
}  // namespace

TEST(HemisphereChart, MarksTheLightAndMirrorWhereTheMappingSays) {
  const int size = 200;
  Image disk(size, size);  // black everywhere
  HemisphereChart chart{"title", "a subtitle"};
  chart.lightTheta = degToRad(45.0f);
  chart.lightPhi = degToRad(90.0f);  // v downward: the light is below the centre
  Image image = drawHemisphereChart(disk, chart);
  const int x0 = 60, cx = x0 + size / 2;
  // Below the title and subtitle, the disk's top is the first row that is black both in the
  // centre column and, half a disk lower, near the left rim.
  int top = 40;
  for (; top < image.height; ++top)
    if (near(image.pixel(cx, top), 0, 0, 0, 0.05f) && near(image.pixel(x0 + 5, top + size / 2), 0, 0, 0, 0.2f)) break;
  ASSERT_LT(top, image.height);
  const int cy = top + size / 2;
  // Light at r = 0.5 of the radius straight below the centre; its mirror straight above.
  const float* light = image.pixel(cx, cy + size / 4);
  EXPECT_GT(light[0], 0.7f);  // the yellow cross
  EXPECT_GT(light[1], 0.5f);
  EXPECT_LT(light[2], 0.3f);
  bool ringAbove = false;
  for (int dy = -10; dy <= 10 && !ringAbove; ++dy)
    ringAbove = image.pixel(cx, cy - size / 4 + dy)[2] > 0.6f && image.pixel(cx, cy - size / 4 + dy)[0] < 0.3f;
  EXPECT_TRUE(ringAbove);  // the cyan ring of the mirror direction
  // A corner of the square, outside the disk, is white.
  EXPECT_TRUE(near(image.pixel(x0 + 2, top + 2), 1, 1, 1, 0.01f));
}
