#include <gtest/gtest.h>

#include "plot/canvas.h"
#include "plot/contact_sheet.h"

using namespace columba;

TEST(ContactSheet, ResizeAveragesSourcePixels) {
  Image img(4, 2);
  for (int x = 0; x < 4; ++x)
    for (int c = 0; c < 3; ++c) {
      img.pixel(x, 0)[c] = float(x);
      img.pixel(x, 1)[c] = float(x) + 4.0f;
    }
  Image small = resizeImage(img, 2, 1);
  EXPECT_FLOAT_EQ(small.pixel(0, 0)[0], (0 + 1 + 4 + 5) / 4.0f);
  EXPECT_FLOAT_EQ(small.pixel(1, 0)[1], (2 + 3 + 6 + 7) / 4.0f);
}

TEST(ContactSheet, TilesAreLaidOutInRowsWithTheirContent) {
  Image red(10, 10), blue(20, 10);
  for (size_t i = 0; i < red.rgb.size(); i += 3) red.rgb[i] = 1.0f;
  for (size_t i = 2; i < blue.rgb.size(); i += 3) blue.rgb[i] = 1.0f;
  Image sheet = makeContactSheet({{red, "r"}, {blue, "b"}, {red, "r2"}}, 2, 40, "");  // one-line labels
  // Two columns of 40-pixel tiles with 12-pixel margins; tiles are 40 high (the tallest).
  EXPECT_EQ(sheet.width, 12 + 2 * (40 + 12));
  EXPECT_GT(sheet.height, 2 * 40);
  EXPECT_FLOAT_EQ(sheet.pixel(12 + 20, 12 + 20)[0], 1.0f);       // first tile: red
  EXPECT_FLOAT_EQ(sheet.pixel(12 + 52 + 20, 12 + 10)[2], 1.0f);  // second tile: blue
  // Third tile, second row: below the first row's tiles and their one-line labels.
  const int labels = 12 + int(Canvas::textHeight(2)) + 4;
  EXPECT_FLOAT_EQ(sheet.pixel(12 + 20, 12 + 40 + labels + 12 + 20)[0], 1.0f);
}

TEST(ContactSheet, FewerImagesThanColumnsMakeARowOfTheirWidth) {
  Image grey(10, 10);
  Image two = makeContactSheet({{grey, "a"}, {grey, "b"}}, 4, 40, "");
  EXPECT_EQ(two.width, 12 + 2 * (40 + 12));
  Image four = makeContactSheet({{grey, "a"}, {grey, "b"}, {grey, "c"}, {grey, "d"}, {grey, "e"}}, 4, 40, "");
  EXPECT_EQ(four.width, 12 + 4 * (40 + 12));
}
