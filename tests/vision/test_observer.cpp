#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <cmath>

#include "support/error_test_support.h"
#include "vision/observer.h"
#include "vision/spectral_grid.h"

using namespace columba;

namespace {
struct Expected {
  double wl;
  std::vector<double> values;
};

// Compares the sensitivities of `definition` on pavo's 300-700 nm grid with values pavo printed.
void expectSensitivities(const ObserverDefinition& definition, const std::vector<Expected>& expected) {
  Observer o = makeObserver(definition, SpectralGrid::span(300.0, 700.0));
  for (const Expected& e : expected)
    for (std::size_t c = 0; c < e.values.size(); ++c) {
      // pavo's record rounds values above 1e-5 to 8 decimal places (1.666e-05), smaller ones to 9
      // significant digits.
      double ours = o.sensitivities[c][std::size_t(e.wl - 300.0)];
      EXPECT_NEAR(ours, e.values[c], std::max(1e-4 * e.values[c], 5e-9))
          << definition.cones[c].lambdaMaxNm << " nm cone at " << e.wl;
    }
}

ObserverDefinition definitionOf(std::vector<ConeClass> cones) {
  ObserverDefinition d;
  d.name = "test";
  d.noise.relativeDensities.assign(cones.size(), 1.0);
  d.cones = std::move(cones);
  return d;
}
}  // namespace

TEST(VisionObserver, ReproducesPavoTemplates) {
  // pavo's own test of sensmodel(c(357, 411, 477, 569)) (Danio aequipinnatus after Govardovskii et al.
  // 2000: beta band on, no oil droplets, area 1 over 300-700 nm) records these values
  // (tests/testthat/_snaps/sensmodel.md, pavo 2.10).
  ObserverDefinition d =
      definitionOf({{"a", 357.0, {}, true}, {"b", 411.0, {}, true}, {"c", 477.0, {}, true}, {"d", 569.0, {}, true}});
  expectSensitivities(d, {{300, {0.0066865, 0.00231014, 0.00122271, 0.00067286}},
                          {350, {0.01344534, 0.00427286, 0.00221092, 0.00161031}},
                          {400, {0.00177836, 0.00972168, 0.00241264, 0.00145984}},
                          {450, {2.89726434e-06, 0.00439898, 0.00676503, 0.00101723}},
                          {500, {1.15850964e-08, 5.355e-05, 0.00684125, 0.00288215}},
                          {550, {1.25660213e-10, 3.20707367e-07, 0.00098716, 0.00616883}},
                          {600, {2.89638226e-12, 4.19567318e-09, 1.666e-05, 0.00525105}},
                          {700, {7.74246186e-15, 4.57898266e-12, 6.54916632e-09, 5.215e-05}}});
}

TEST(VisionObserver, ReproducesPavoOilDroplets) {
  // The same record of sensmodel(c(300, 400, 500), lambdacut = c(350, 450, 550), oiltype = c("C", "Y",
  // "R")): beta band on, droplets from their cut-offs by Hart & Vorobyev's regressions, area 1.
  ObserverDefinition d = definitionOf({{"a", 300.0, oilDropletOfType(OilDropletType::C, 350.0), true},
                                       {"b", 400.0, oilDropletOfType(OilDropletType::Y, 450.0), true},
                                       {"c", 500.0, oilDropletOfType(OilDropletType::R, 550.0), true}});
  expectSensitivities(d, {{350, {0.03717529, 0, 0}},
                          {400, {0.00038923, 0, 0}},
                          {450, {1.27896503e-06, 0.02149807, 0}},
                          {500, {1.23046031e-08, 0.00175685, 0}},
                          {550, {2.74788045e-10, 1.328e-05, 0.0073796}},
                          {600, {1.15631246e-11, 1.96254585e-07, 0.00699587}},
                          {700, {7.95992822e-14, 2.5715909e-10, 2.87469336e-06}}});
}

TEST(VisionObserver, SensitivitiesHaveAreaOne) {
  Observer o = namedObserver("bluetit");
  ASSERT_EQ(o.channels, (std::vector<std::string>{"UVS", "SWS", "MWS", "LWS"}));
  EXPECT_EQ(o.grid.count, 531u);
  for (const std::vector<float>& s : o.sensitivities) EXPECT_NEAR(integrateOnGrid(o.grid, s), 1.0, 1e-5);
  EXPECT_FALSE(o.hasAchromatic());
  // The oil droplets shift each filtered cone's peak sensitivity above its pigment's peak.
  for (std::size_t c = 1; c < 4; ++c) {
    std::size_t at = 0;
    for (std::size_t i = 0; i < o.grid.count; ++i)
      if (o.sensitivities[c][i] > o.sensitivities[c][at]) at = i;
    EXPECT_GT(o.grid.wavelength(at), findObserverDefinition("bluetit")->cones[c].lambdaMaxNm) << o.channels[c];
  }
}

TEST(VisionObserver, UnknownNamesAreErrors) {
  EXPECT_EQ(findObserverDefinition("cie1931"), nullptr);  // the renderer's own observer, not a cone model
  try {
    namedObserver("pigeon");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bluetit"), std::string::npos);
  }
  ObserverDefinition d = definitionOf({{"a", 400.0, {}, true}, {"b", 500.0, {}, true}});
  d.noise.relativeDensities = {1.0};
  EXPECT_THROW(makeObserver(d), std::invalid_argument);
}

// A Weber fraction of 0 made every distance infinite, NaN or inf every distance NaN or 0, a density
// of inf a noise of NaN: each is refused, naming the observer, the parameter and its value.
TEST(VisionObserver, ReceptorNoiseOutsideItsRangesIsRefusedNamingTheParameter) {
  const double nan = std::nan(""), inf = INFINITY;
  auto error = [](const ReceptorNoise& noise) {
    ObserverDefinition d = definitionOf({{"SWS", 450.0, {}, true}, {"LWS", 560.0, {}, true}});
    d.noise = noise;
    try {
      makeObserver(d);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  for (double w : {0.0, nan, inf, -0.1, 11.0})
    columba::testing::expectContains(error({{1, 1}, w, 1, 0.1}),
                                     {"observer 'test'", "weber", fmt::format("{:g}", w).c_str(), "[1e-06, 10]"});
  for (double density : {1e-300, inf, 0.0, nan})
    columba::testing::expectContains(error({{1, density}, 0.1, 1, 0.1}),
                                     {"densities[1]", fmt::format("{:g}", density).c_str(), "[1e-06, 1e+06]"});
  columba::testing::expectContains(error({{1, 1}, 0.1, 2, 0.1}), {"weber_cone 2 names no cone: give 0 to 1"});
  columba::testing::expectContains(error({{1, 1}, 0.1, 1, 0.0}), {"the achromatic Weber fraction 0"});
  EXPECT_EQ(error({{1e-6, 1e6}, 10.0, 0, 1e-6}), "");  // the ranges' ends are taken
}

TEST(VisionObserver, ReadsEndlerMielkeLayout) {
  // Three header lines, then a wavelength and eight sensitivities times 100 (UV eye, then V eye).
  std::istringstream table(
      "Online Appendix\nValues * 100\nWAVELN UVS+T SWS+C MWS+Y LWS+R UVS+T SWS+C MWS+Y LWS+R\n"
      " 300.0 10 20 30 40 50 60 70 80\n 301.0 1 2 3 4 5 6 7 8\n 302.0 0 0 0 0 0 0 0 100\n");
  std::vector<Observer> observers = readEndlerMielkeObservers(table);
  ASSERT_EQ(observers.size(), 2u);
  EXPECT_EQ(observers[0].name, "avg.uv");
  EXPECT_EQ(observers[1].name, "avg.v");
  EXPECT_EQ(observers[1].channels, (std::vector<std::string>{"VS", "SWS", "MWS", "LWS"}));
  EXPECT_EQ(observers[0].grid.count, 3u);
  EXPECT_FLOAT_EQ(observers[0].sensitivities[1][0], 0.2f);
  EXPECT_FLOAT_EQ(observers[1].sensitivities[3][2], 1.0f);
  EXPECT_EQ(observers[0].noise.relativeDensities, (std::vector<double>{1, 2, 2, 4}));
  std::istringstream ragged("a\nb\nc\n300 1 2 3\n");
  EXPECT_THROW(readEndlerMielkeObservers(ragged), std::invalid_argument);
}

TEST(VisionObserver, PavosAveragesAreBuiltInFromEndlerAndMielke) {
  // The compiled-in appendix of Endler & Mielke (2005): each curve of area 1 over 300-700 nm, zero
  // beyond on the 300-830 nm grid; the cones peak in the order their names say, the UV eye's first
  // cone below 400 nm and the violet eye's above it.
  for (const char* name : {"avg.uv", "avg.v"}) {
    ASSERT_TRUE(isBuiltinObserver(name));
    const Observer o = namedObserver(name);
    EXPECT_EQ(o.grid.count, 531u);
    ASSERT_EQ(o.sensitivities.size(), 4u);
    double previousPeak = 0.0;
    for (const std::vector<float>& s : o.sensitivities) {
      EXPECT_NEAR(integrateOnGrid(o.grid, s), 1.0, 1e-5) << name;
      EXPECT_EQ(s[size_t(750 - 300)], 0.0f) << name;
      const double peak = o.grid.wavelength(size_t(std::max_element(s.begin(), s.end()) - s.begin()));
      EXPECT_GT(peak, previousPeak) << name;
      previousPeak = peak;
    }
    const double shortest = o.grid.wavelength(
        size_t(std::max_element(o.sensitivities[0].begin(), o.sensitivities[0].end()) - o.sensitivities[0].begin()));
    EXPECT_EQ(shortest < 400.0, std::string(name) == "avg.uv") << name << " " << shortest;
  }
  EXPECT_EQ(namedObserver("avg.v").channels, (std::vector<std::string>{"VS", "SWS", "MWS", "LWS"}));
  EXPECT_NE(builtinObserverNames().find("bluetit, avg.uv, avg.v"), std::string::npos) << builtinObserverNames();
}
