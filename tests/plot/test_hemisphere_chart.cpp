// The scatterometer chart: markers where the visualiser's mapping puts the light and its mirror
// direction, rings of equal polar angle, corners outside the disk left white.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <pugixml.hpp>
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

// The brightness bar shows a grey of value v at the height of its tick v: the bottom black, the
// top white, half-way up the grey 0.5 (linear, as the disk's pixels are shown).
TEST(HemisphereChart, BrightnessBarGoesFromZeroToOneLinearly) {
  const int size = 200;
  Image disk(size, size);
  const Image image = drawHemisphereChart(disk, HemisphereChart{"title", "subtitle"});
  int found = 0;
  for (int x = 60 + size; x < image.width; ++x) {
    // The bar's column: the longest vertical run that gets brighter upward, from black to white.
    int bottom = -1, top = -1;
    for (int y = image.height - 1; y > 0; --y) {
      const float v = image.pixel(x, y)[1];
      if (bottom < 0 && v < 0.02f && image.pixel(x, y - 1)[1] < 0.05f) bottom = y;
      if (bottom >= 0 && v > 0.95f) {
        top = y;
        break;
      }
    }
    if (bottom < 0 || top < 0 || bottom - top < size / 2) continue;
    bool grey = true, rising = true;
    for (int y = top; y <= bottom; ++y) {
      const float* p = image.pixel(x, y);
      grey = grey && std::abs(p[0] - p[1]) < 0.02f && std::abs(p[2] - p[1]) < 0.02f;
      if (y > top) rising = rising && image.pixel(x, y)[1] <= image.pixel(x, y - 1)[1] + 0.01f;
    }
    if (!grey || !rising) continue;
    ++found;
    EXPECT_NEAR(image.pixel(x, (top + bottom) / 2)[1], 0.5f, 0.03f);
    EXPECT_NEAR(image.pixel(x, top + (bottom - top) / 4)[1], 0.75f, 0.03f);
  }
  EXPECT_GT(found, 5);  // the bar is some 18 pixels wide
}

TEST(HemisphereChart, IsWrittenAsPngSvgAndPdf) {
  Image disk(64, 64);
  HemisphereChart chart{"Scatterometer", "light at 30 deg"};
  chart.valueLabel = "luminance";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("columba_hemisphere_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (const char* extension : {".png", ".svg", ".PDF"})
    writeHemisphereChart((dir / (std::string("chart") + extension)).string(), disk, chart);
  const Image png = readPNG((dir / "chart.png").string());
  EXPECT_EQ(png.width, drawHemisphereChart(disk, chart).width);
  pugi::xml_document svg;
  ASSERT_TRUE(svg.load_file((dir / "chart.svg").c_str()));
  EXPECT_STREQ(svg.document_element().name(), "svg");
  EXPECT_NE(std::string(svg.document_element().attribute("width").value()).find("pt"), std::string::npos);
  std::ifstream in(dir / "chart.PDF", std::ios::binary);
  const std::string pdf((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("DejaVuSans"), std::string::npos);  // the labels set in an embedded font
  EXPECT_NE(pdf.find("ToUnicode"), std::string::npos);   // and mapped back to characters: text stays text
  // Nothing left beside the files: each was written under a temporary name and renamed.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 3);
  std::filesystem::remove_all(dir);
}
