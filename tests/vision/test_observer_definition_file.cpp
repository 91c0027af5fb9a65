// Observers defined by their cones' published parameters in a file: the blue tit's numbers give the
// built-in blue tit exactly, a double cone and Weber fractions are taken where given, an oil droplet
// moves a cone's peak to longer wavelengths, and mistakes are refused naming the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "core/error.h"
#include "support/error_test_support.h"
#include "support/temp_dir_test.h"
#include "vision/observer_definition_file.h"
#include "vision/observer_table.h"

using namespace columba;
using columba::testing::TempDirTest;

namespace {
// The blue tit as observer.cpp builds it in (Hart et al. 2000, no beta band).
const char* kBlueTit =
    "# Hart, Partridge, Cuthill & Bennett (2000)\n"
    "cone, lambda_max, droplet, lambda_cut, beta\n"
    "UVS, 371, T, NA, no\n"
    "SWS, 448, C, 413, no\n"
    "MWS, 502, Y, 507, no\n"
    "LWS, 563, R, 572, no\n";

std::string errorOf(const std::string& text) {
  std::istringstream in(text);
  try {
    readObserverDefinition(in, "bird.csv", "bird");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

size_t peakIndex(const std::vector<float>& s) { return size_t(std::max_element(s.begin(), s.end()) - s.begin()); }
}  // namespace

class ObserverDefinitionFile : public TempDirTest {};

TEST_F(ObserverDefinitionFile, TheBlueTitsNumbersGiveTheBuiltInBlueTit) {
  const Observer fromFile = readObserverTableFile(write("tit.csv", kBlueTit));
  const Observer builtIn = namedObserver("bluetit");
  EXPECT_EQ(fromFile.name, "tit");
  EXPECT_EQ(fromFile.channels, builtIn.channels);
  ASSERT_EQ(fromFile.sensitivities.size(), builtIn.sensitivities.size());
  for (size_t c = 0; c < builtIn.sensitivities.size(); ++c)
    EXPECT_EQ(fromFile.sensitivities[c], builtIn.sensitivities[c]);
  EXPECT_EQ(fromFile.noise.relativeDensities, builtIn.noise.relativeDensities);
  EXPECT_EQ(fromFile.noise.weberReference, builtIn.noise.weberReference);
  EXPECT_EQ(fromFile.noise.weberFraction, builtIn.noise.weberFraction);
  EXPECT_FALSE(fromFile.hasAchromatic());
}

TEST(ObserverDefinitionExample, TheShippedBlueTitFileGivesTheBuiltInBlueTit) {
  const Observer o = readObserverTableFile(COLUMBA_SOURCE_DIR "/examples/observers/bluetit_parameters.csv");
  const Observer builtIn = namedObserver("bluetit");
  EXPECT_EQ(o.channels, builtIn.channels);
  EXPECT_EQ(o.sensitivities, builtIn.sensitivities);
  EXPECT_EQ(o.noise.relativeDensities, builtIn.noise.relativeDensities);
  EXPECT_EQ(o.noise.weberReference, builtIn.noise.weberReference);
}

TEST_F(ObserverDefinitionFile, DoubleConeDensitiesAndWeberFractionsAreTaken) {
  const Observer o = readObserverTableFile(write("bird.csv",
                                                 "cone\tlambda_max\tdroplet\tlambda_cut\tlambda_mid\tdensity\tweber\n"
                                                 "LWS\t570\tR\t570\t-\t2.1\t0.05\n"  // any order: sorted by cone
                                                 "VS\t420\tT\t-\t-\t1\t-\n"
                                                 "SWS\t455\tC\t440\t460\t1.9\t-\n"
                                                 "MWS\t510\tY\t500\t-\t2.2\t-\n"
                                                 "DBL\t570\tP\t480\t-\t-\t0.2\n"));
  EXPECT_EQ(o.channels, (std::vector<std::string>{"VS", "SWS", "MWS", "LWS"}));
  EXPECT_EQ(o.noise.relativeDensities, (std::vector<double>{1.0, 1.9, 2.2, 2.1}));
  EXPECT_EQ(o.noise.weberReference, 3u);
  EXPECT_DOUBLE_EQ(o.noise.weberFraction, 0.05);
  EXPECT_DOUBLE_EQ(o.noise.achromaticWeberFraction, 0.2);
  ASSERT_TRUE(o.hasAchromatic());
  EXPECT_EQ(o.achromaticChannel, "DBL");
  // Test values, not a species. A droplet cuts the short wavelengths away: the SWS cone (pigment at
  // 455 nm, droplet half-way up at 460 nm) peaks above 462 nm; the transparent VS droplet leaves its
  // peak at 420 nm.
  EXPECT_GT(o.grid.wavelength(peakIndex(o.sensitivities[1])), 462.0);
  EXPECT_NEAR(o.grid.wavelength(peakIndex(o.sensitivities[0])), 420.0, 1.0);
}

TEST(ObserverDefinitionFileErrors, MistakesAreRefusedNamingTheLine) {
  using columba::testing::expectContains;
  const std::string header = "cone,lambda_max,droplet,lambda_cut\n";
  expectContains(errorOf(header + "VS,409,T,NA\nSWS,453,Q,420\n"), {"bird.csv:3", "droplet 'Q'"});
  expectContains(errorOf(header + "VS,409,T,NA\nSWS,453,C,NA\n"), {"bird.csv:3", "needs its lambda_cut"});
  expectContains(errorOf(header + "VS,250,T,NA\nSWS,453,C,420\n"), {"bird.csv:2", "250 lies outside [300, 700]"});
  expectContains(errorOf(header + "VS,409,T,NA\nSWS,453,C\n"), {"bird.csv:3", "a row of 3 values"});
  expectContains(errorOf(header + "VS,409,T,NA\nUVS,370,T,NA\n"), {"UVS or a VS cone, not both"});
  expectContains(errorOf(header + "VS,409,T,NA\nVS,453,C,420\n"), {"bird.csv:3", "'VS' is given twice"});
  expectContains(errorOf(header + "VS,409,T,NA\n"), {"fewer than two chromatic cones"});
  expectContains(errorOf(header + "VS,409,T,400\nSWS,453,C,420\n"), {"bird.csv:2", "belong to C, Y, R and P"});
  expectContains(errorOf("cone,lambda_max,droplet,weber\nVS,409,T,0.1\nSWS,453,NA,0.1\n"),
                 {"bird.csv:3", "second chromatic cone"});
  expectContains(errorOf("cone,lambda_max,colour\n"), {"bird.csv:1", "column 'colour'"});
  expectContains(errorOf("cone,lambda_max\n"), {"bird.csv:1", "no column 'droplet'"});
  expectContains(errorOf("cone,lambda_max,droplet,beta\nVS,409,T,maybe\n"), {"bird.csv:2", "'maybe' is not yes or no"});
}
