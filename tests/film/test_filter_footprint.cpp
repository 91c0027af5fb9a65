// What a camera sample adds to the pixels around it: the weights against the filter, the pixels
// reached, and the filter's mass over pixels, which normalises the image, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>
#include "core/math.h"
#include "core/rng.h"
#include "film/box_filter.h"
#include "film/filter_footprint.h"
#include "film/gaussian_filter.h"
#include "film/tent_filter.h"

using namespace columba;

namespace {

std::vector<std::shared_ptr<ReconstructionFilter>> allFilters() {
  return {std::make_shared<BoxFilter>(), std::make_shared<GaussianFilter>(0.5f), std::make_shared<GaussianFilter>(1.2f),
          std::make_shared<TentFilter>(1.0f), std::make_shared<TentFilter>(2.5f)};
}

// The mass of Mitsuba's windowed Gaussian of `stddev`, exp(-x^2 / (2 stddev^2)) - exp(-8) within
// 4 stddev, normalised, over offsets of at least `from`.
double gaussianMassFrom(double stddev, double from) {
  const double r = 4.0 * stddev, bias = std::exp(-8.0);
  auto integral = [&](double x) {  // over [-r, x]
    return stddev * std::sqrt(kPiDouble / 2.0) *
               (std::erf(x / (stddev * std::sqrt(2.0))) + std::erf(2.0 * std::sqrt(2.0))) -
           bias * (x + r);
  };
  const double at = std::max(-r, std::min(r, from));
  return (integral(r) - integral(at)) / integral(r);
}

}  // namespace

TEST(FilterFootprint, ReachesThePixelsWhoseCentresLieWithinTheRadius) {
  for (const auto& filter : allFilters()) {
    const FilterFootprint footprint(*filter);
    const float r = filter->radius();
    EXPECT_EQ(footprint.reach(), int(std::ceil(r - 0.5f))) << "radius " << r;
    PCG32 rng(5);
    for (int i = 0; i < 20000; ++i) {
      const int pixel = 40;
      const float position = float(pixel) + rng.nextFloat();
      const FilterFootprint::AxisWeights axis = footprint.axisWeights(pixel, position);
      for (int c = pixel - footprint.reach() - 2; c <= pixel + footprint.reach() + 2; ++c) {
        const float offset = position - (float(c) + 0.5f);
        const bool inside = c >= axis.first && c < axis.first + axis.count;
        if (filter->eval(offset) > 0.0f && offset > -r && offset < r) {
          ASSERT_TRUE(inside) << "radius " << r << ", position " << position << ", pixel " << c;
        }
        if (inside) {
          ASSERT_LE(std::abs(c - pixel), footprint.reach());
        }
      }
    }
  }
}

TEST(FilterFootprint, WeightsFollowTheFilter) {
  // Linear between nodes 1/256 pixel apart: exact for the box and these tents, whose kinks are nodes;
  // for the Gaussian within (1/256)^2 / 8 of its second derivative, about 1e-5 of its peak.
  for (const auto& filter : allFilters()) {
    const FilterFootprint footprint(*filter);
    const double peak = filter->eval(0.0f);
    double worst = 0.0;
    PCG32 rng(9);
    for (int i = 0; i < 20000; ++i) {
      const float position = 7.0f + rng.nextFloat();
      const FilterFootprint::AxisWeights axis = footprint.axisWeights(7, position);
      for (int k = 0; k < axis.count; ++k) {
        const float offset = position - (float(axis.first + k) + 0.5f);
        worst = std::max(worst, std::abs(double(axis.weights[k]) - filter->eval(offset)) / peak);
      }
    }
    EXPECT_LT(worst, 2e-5) << "radius " << filter->radius();
  }
  const BoxFilter box;
  const FilterFootprint boxFootprint(box);
  for (float u : {0.0f, 0.25f, 0.5f, 0.999f}) {
    const FilterFootprint::AxisWeights axis = boxFootprint.axisWeights(3, 3.0f + u);
    ASSERT_EQ(axis.first, 3);
    ASSERT_EQ(axis.count, 1);
    EXPECT_EQ(axis.weights[0], 1.0) << "position 3 + " << u;
  }
}

TEST(FilterFootprint, MassOverPixelsIsOneInsideAndTheCutMassAtTheEdges) {
  for (const auto& filter : allFilters()) {
    const FilterFootprint footprint(*filter);
    EXPECT_NEAR(footprint.massWithin(20, 41), 1.0, 1e-6) << "radius " << filter->radius();
    // A pixel at the edge keeps its own square and those on one side.
    if (footprint.reach() == 0) {
      EXPECT_NEAR(footprint.massWithin(0, 1), 1.0, 1e-6);
    }
  }
  // Gaussian, stddev 0.5: from the first pixel's centre the film starts at offset -1/2; from the
  // second's at -3/2.
  const GaussianFilter gaussian(0.5f);
  const FilterFootprint footprint(gaussian);
  EXPECT_NEAR(footprint.massWithin(0, 100), gaussianMassFrom(0.5, -0.5), 1e-5);
  EXPECT_NEAR(footprint.massWithin(1, 100), gaussianMassFrom(0.5, -1.5), 1e-5);
  EXPECT_NEAR(footprint.massWithin(99, 100), gaussianMassFrom(0.5, -0.5), 1e-5);
  // A film one pixel wide keeps the middle square only: [-1/2, 1/2].
  EXPECT_NEAR(footprint.massWithin(0, 1), gaussianMassFrom(0.5, -0.5) - gaussianMassFrom(0.5, 0.5), 1e-5);
  // The tent of radius 1: 3/4 on the pixel's own square, 1/8 on each neighbour's.
  const TentFilter tent(1.0f);
  const FilterFootprint tentFootprint(tent);
  EXPECT_NEAR(tentFootprint.massWithin(0, 1), 0.75, 1e-6);
  EXPECT_NEAR(tentFootprint.massWithin(0, 2), 0.875, 1e-6);
}

TEST(FilterFootprint, FiltersWiderThanSixteenPixelsAreRefused) {
  EXPECT_NO_THROW(FilterFootprint(TentFilter(16.5f)));
  EXPECT_THROW(FilterFootprint(TentFilter(17.0f)), std::invalid_argument);
}
