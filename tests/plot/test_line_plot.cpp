#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <pugixml.hpp>

#include "io/image.h"
#include "plot/canvas.h"
#include "plot/line_plot.h"

using namespace columba;

TEST(LinePlot, NiceTicksAreRoundAndCoverTheRange) {
  std::vector<float> t = niceTicks(360, 830, 8);
  ASSERT_GE(t.size(), 5u);
  EXPECT_GE(t.front(), 360.0f);
  EXPECT_LE(t.back(), 830.0f);
  EXPECT_LE(t.size(), 16u);
  EXPECT_FLOAT_EQ(t[1] - t[0], 100.0f);  // 1, 2, 2.5 or 5 times a power of ten
  EXPECT_EQ(niceTicks(0, 1, 5), (std::vector<float>{0, 0.2f, 0.4f, 0.6f, 0.8f, 1.0f}));
}

TEST(LinePlot, SeriesAreDrawnInTheirColourInsideThePlotArea) {
  LinePlot plot;
  plot.title = "t";
  plot.xLabel = "x";
  plot.yLabel = "y";
  plot.series.push_back({"diag", {Vec2(0, 0), Vec2(1, 1)}, Vec3(1, 0, 0)});
  Image img = renderLinePlot(plot, 400, 300);
  // The legend stands right of the chart: the plot area ends where the legend's room begins.
  const float right = 400 - 20 - (Canvas::textWidth("diag") + 58);
  // The diagonal runs from the bottom-left (90, 230) to the top-right (right, 80) of the plot area.
  int redPixels = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.pixel(x, y);
      if (p[0] > 0.9f && p[1] < 0.1f && p[2] < 0.1f) ++redPixels;
    }
  EXPECT_GT(redPixels, 300);
  const float* mid = img.pixel(int(0.5f * (90 + right)), 155);  // the diagonal's midpoint
  EXPECT_GT(mid[0], 0.5f);
  EXPECT_LT(mid[1], 0.5f);
  // The legend's swatch, outside the chart at its top: red, on the chart's right.
  const float* swatch = img.pixel(int(right) + 35, 87);
  EXPECT_GT(swatch[0], 0.9f);
  EXPECT_LT(swatch[1], 0.1f);
}

TEST(Canvas, TextMarksPixels) {
  Canvas c(100, 30, Vec3(1, 1, 1));
  c.text(2, 2, "Hello", Vec3(0, 0, 0));
  int dark = 0;
  for (float v : c.image().rgb) dark += v < 0.5f;
  EXPECT_GT(dark, 30);
  EXPECT_GT(Canvas::textWidth("Hello"), Canvas::textWidth("Hi"));
}

TEST(LinePlot, IsWrittenAsPngSvgAndPdf) {
  LinePlot plot;
  plot.title = "Reflectance";
  plot.xLabel = "wavelength (nm)";
  plot.series = {{"measured", {{0.2f, 0.3f}, {0.5f, 0.6f}}, Vec3(1, 0, 0), false, true},
                 {"fitted", {{0.0f, 0.1f}, {1.0f, 0.9f}}, Vec3(0, 0, 1)}};
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("columba_plot_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (const char* extension : {".png", ".svg", ".pdf"})
    writeLinePlot((dir / (std::string("plot") + extension)).string(), plot, 500, 320);
  const Image png = readPNG((dir / "plot.png").string());
  EXPECT_EQ(png.width, 500);
  EXPECT_EQ(png.height, 320);
  pugi::xml_document svg;
  ASSERT_TRUE(svg.load_file((dir / "plot.svg").c_str()));
  EXPECT_STREQ(svg.document_element().name(), "svg");
  EXPECT_STREQ(svg.document_element().attribute("width").value(), "500pt");
  std::ifstream in(dir / "plot.pdf", std::ios::binary);
  const std::string pdf((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
  EXPECT_NE(pdf.find("DejaVuSans"), std::string::npos);  // its text set in an embedded font, not drawn as pixels
  EXPECT_THROW(writeLinePlot((dir / "plot.gif").string(), plot, 500, 320), std::runtime_error);
  std::filesystem::remove_all(dir);
}
