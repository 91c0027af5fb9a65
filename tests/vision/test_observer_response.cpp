// What a film with a bird's observer records: the wavelengths it draws follow the density it
// reports (chi-square), and its estimate of each cone's catch is the integral of radiance times
// sensitivity (closed forms for an equal-quantum and a D65 spectrum).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/illuminant.h"
#include "core/rng.h"
#include "support/chi_square.h"
#include "vision/observer_response.h"

using namespace columba;

TEST(ObserverResponse, WavelengthsFollowTheDensityTheyReport) {
  // Chi-square of 50,000 x 4 wavelengths over 106 bins of 5 nm against the reported pdf integrated
  // over each bin; the table spans 300-830 nm, and its density is 9/10 the cones' mean sensitivity
  // and 1/10 uniform (within the 1/1024 segments it is drawn from).
  const ObserverResponse response(namedObserver("bluetit"), Adaptation::D65);
  const WavelengthTable& table = response.wavelengths();
  EXPECT_EQ(table.first(), 300.0f);
  EXPECT_EQ(table.last(), 830.0f);
  constexpr int kBins = 106;
  const float width = 5.0f;
  std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
  PCG32 rng(3);
  const int n = 50000;
  for (int i = 0; i < n; ++i) {
    const Wavelengths wl = Wavelengths::sample(rng.nextFloat(), table);
    for (int k = 0; k < kSpectrumSamples; ++k) {
      observed[std::clamp(int((wl[k] - 300.0f) / width), 0, kBins - 1)] += 1.0;
      EXPECT_NEAR(wl.pdf[k], table.pdf(wl[k]), 0.02f * wl.pdf[k]) << wl[k];
    }
  }
  for (int b = 0; b < kBins; ++b)
    for (int j = 0; j < 200; ++j)
      expected[b] += table.pdf(300.0f + (b + (j + 0.5f) / 200) * width) * width / 200 * (n * kSpectrumSamples);
  const columba::testing::ChiSquareResult r = columba::testing::chiSquareTest(observed, expected);
  EXPECT_GT(r.pValue, 1e-3) << r.message;
  // The density is the one intended: at the LWS cone's peak and in the far red, where only the
  // uniform part is left.
  const Observer& o = response.observer();
  auto intended = [&](float lambda) {
    double mean = 0.0;
    for (size_t c = 0; c < o.channels.size(); ++c) mean += response.sensitivity(c, lambda) / 4.0;
    return 0.9 * mean + 0.1 / 530.0;
  };
  for (float lambda : {380.0f, 450.0f, 560.0f, 600.0f, 820.0f})
    EXPECT_NEAR(table.pdf(lambda), intended(lambda), 0.05 * intended(lambda)) << lambda;
}

TEST(ObserverResponse, EstimatesEachConesCatchOfTheRadiance) {
  // Monte Carlo over 200,000 x 4 wavelengths: an equal-quantum radiance of 2 (per nm) catches 2 in
  // every cone without adaptation (each sensitivity has area 1); D65 of luminance 1 catches 1 in
  // every cone adapted to D65.
  for (Adaptation adaptation : {Adaptation::None, Adaptation::D65}) {
    const ObserverResponse response(namedObserver("bluetit"), adaptation);
    const size_t channels = response.channels().size();
    ASSERT_EQ(channels, 4u);
    std::vector<double> sum(channels, 0.0), sumSquares(channels, 0.0);
    PCG32 rng(11);
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const Wavelengths wl = Wavelengths::sample(rng.nextFloat(), response.wavelengths());
      const Spectrum L = adaptation == Adaptation::None ? Spectrum(2.0f) : d65(wl);
      std::vector<float> values(channels, 0.0f);
      response.accumulate(L, wl, 1.0f, values.data());
      for (size_t c = 0; c < channels; ++c) {
        sum[c] += values[c];
        sumSquares[c] += double(values[c]) * values[c];
      }
    }
    const double expected = adaptation == Adaptation::None ? 2.0 : 1.0;
    for (size_t c = 0; c < channels; ++c) {
      const double mean = sum[c] / n, sigma = std::sqrt((sumSquares[c] / n - mean * mean) / n);
      EXPECT_NEAR(mean, expected, 4.0 * sigma + 2e-3 * expected) << response.channels()[c];
    }
  }
}

TEST(ObserverResponse, NamesAreCheckedAndTheImageSaysWhatItsChannelsHold) {
  EXPECT_EQ(adaptationNamed("d65"), Adaptation::D65);
  EXPECT_EQ(adaptationNamed("none"), Adaptation::None);
  EXPECT_THROW(adaptationNamed("D50"), std::invalid_argument);
  const std::string text = describeObserver(ObserverResponse(namedObserver("bluetit"), Adaptation::D65));
  for (const char* part : {"bluetit", "UVS, SWS, MWS, LWS", "D65", "von Kries", "red (2 LWS + UVS) / 3"})
    EXPECT_NE(text.find(part), std::string::npos) << text;
}
