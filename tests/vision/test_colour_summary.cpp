// pavo's colour summary variables (summary.rspec, after Montgomerie 2006) against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "vision/colour_summary.h"

using namespace columba;

namespace {
std::vector<float> grid(float first, float last) {
  std::vector<float> l;
  for (float x = first; x <= last; x += 1.0f) l.push_back(x);
  return l;
}
}  // namespace

// A ramp from 0 at 300 nm to 1 at 700 nm: B1 = sum of k / 400 for k = 0 .. 400 = 200.5, B2 = 0.5,
// S8 = (1 - 0) / 0.5 = 2, H1 = 700; the values beyond 700 nm (up to 830) are left out.
TEST(ColourSummary, ARampHasTheClosedFormsBrightnessChromaAndHue) {
  const std::vector<float> lambdas = grid(300.0f, 830.0f);
  std::vector<float> values;
  for (float l : lambdas) values.push_back((l - 300.0f) / 400.0f);
  const ColourSummary s = colourSummary(lambdas, values);
  EXPECT_NEAR(s.B1, 200.5, 1e-3);
  EXPECT_NEAR(s.B2, 0.5, 1e-6);
  EXPECT_NEAR(s.S8, 2.0, 1e-5);
  EXPECT_EQ(s.H1, 700.0);
}

// A flat spectrum with two equal maxima: H1 is the first (pavo's which.max), chroma that of the
// bumps over the mean, and a spectrum outside the range or dark everywhere has no summary.
TEST(ColourSummary, HueIsTheFirstLargestValueAndDarknessHasNoChroma) {
  const std::vector<float> lambdas = grid(300.0f, 700.0f);
  std::vector<float> values(lambdas.size(), 0.2f);
  values[150] = values[250] = 0.6f;  // 450 and 550 nm
  const ColourSummary s = colourSummary(lambdas, values);
  EXPECT_EQ(s.H1, 450.0);
  const double mean = (399 * 0.2 + 2 * 0.6) / 401.0;
  EXPECT_NEAR(s.B2, mean, 1e-6);
  EXPECT_NEAR(s.S8, 0.4 / mean, 1e-5);
  EXPECT_THROW(colourSummary(lambdas, std::vector<float>(lambdas.size(), 0.0f)), std::invalid_argument);
  EXPECT_THROW(colourSummary(grid(750.0f, 800.0f), std::vector<float>(51, 0.5f)), std::invalid_argument);
}
