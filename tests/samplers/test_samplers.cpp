#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>
#include "core/properties.h"
#include "samplers/hashed_permutation.h"
#include "samplers/independent_sampler.h"
#include "samplers/low_discrepancy_sampler.h"
#include "samplers/multijitter_sampler.h"
#include "samplers/pixel_sample_state.h"
#include "samplers/sobol.h"
#include "samplers/stratified_sampler.h"
#include "support/chi_square.h"

using namespace columba;

namespace {

const std::vector<std::string> kAllSamplers = {"independent", "stratified", "ldsampler", "multijitter"};
const std::vector<std::string> kStratifiedSamplers = {"stratified", "ldsampler", "multijitter"};

Properties::Value integerValue(int v) {
  Properties::Value value;
  value.kind = Properties::ValueKind::Integer;
  value.number = v;
  return value;
}

Properties::Value booleanValue(bool b) {
  Properties::Value value;
  value.kind = Properties::ValueKind::Boolean;
  value.boolean = b;
  return value;
}

Properties samplerProperties(const std::string& type, int sampleCount) {
  Properties props;
  props.tag = "sampler";
  props.type = type;
  props.set("sample_count", integerValue(sampleCount));
  return props;
}

std::shared_ptr<Object> build(const Properties& props) {
  static const std::map<std::string, std::shared_ptr<Object> (*)(const Properties&)> factories = {
      {"independent", makeIndependentSampler},
      {"stratified", makeStratifiedSampler},
      {"ldsampler", makeLowDiscrepancySampler},
      {"multijitter", makeMultijitterSampler}};
  return factories.at(props.type)(props);
}

std::unique_ptr<Sampler> makeSampler(const std::string& type, int sampleCount) {
  auto sampler = std::dynamic_pointer_cast<Sampler>(build(samplerProperties(type, sampleCount)));
  EXPECT_TRUE(sampler);
  EXPECT_EQ(sampler->sampleCount(), sampleCount) << type;
  return sampler->clone();
}

// Every sampler with `sampleCount` samples, and the low-discrepancy sampler's progressive pattern.
std::vector<std::pair<std::string, std::unique_ptr<Sampler>>> allPatterns(int sampleCount) {
  std::vector<std::pair<std::string, std::unique_ptr<Sampler>>> patterns;
  for (const std::string& type : kAllSamplers) patterns.emplace_back(type, makeSampler(type, sampleCount));
  patterns.emplace_back("ldsampler (progressive)", makeSampler("ldsampler", sampleCount)->withProgressivePattern());
  return patterns;
}

// The first `dimensions` values of one pixel sample, drawing 1D and 2D dimensions alternately.
std::vector<float> drawSample(Sampler& sampler, int px, int py, int index, uint64_t seed, int dimensions) {
  sampler.startPixelSample(px, py, index, seed);
  std::vector<float> values;
  for (int d = 0; d < dimensions; ++d) {
    if (d % 2 == 0) {
      values.push_back(sampler.get1D());
    } else {
      Vec2 u = sampler.get2D();
      values.push_back(u.x);
      values.push_back(u.y);
    }
  }
  return values;
}

// Whether each of the `count` cells gets exactly one of the points.
bool oneInEachCell(const std::vector<int>& cells, int count) {
  std::vector<int> hits(count, 0);
  for (int c : cells) {
    if (c < 0 || c >= count) return false;
    ++hits[c];
  }
  for (int h : hits)
    if (h != 1) return false;
  return true;
}

// The smallest t for which the 2^k `points` put exactly 2^t in every elementary interval of
// 2^(k-t) cells (2^a x 2^(k-t-a) for every a): the t of a (t, k, 2)-net, 0 the best possible.
int netQuality(const std::vector<Vec2>& points) {
  int k = 0;
  while ((size_t(1) << k) < points.size()) ++k;
  for (int t = 0; t < k; ++t) {
    bool all = true;
    for (int a = 0; a <= k - t && all; ++a) {
      const int nx = 1 << a, ny = 1 << (k - t - a);
      std::vector<int> counts(size_t(nx) * ny, 0);
      for (Vec2 u : points) ++counts[size_t(int(u.y * ny)) * nx + int(u.x * nx)];
      for (int c : counts) all = all && c == (1 << t);
    }
    if (all) return t;
  }
  return k;
}

// Point `point` (the point-th 2D request) of samples [begin, begin + count) of a pixel.
std::vector<Vec2> pointOfSamples(Sampler& sampler, int pixel, int point, int begin, int count) {
  std::vector<Vec2> values;
  for (int i = begin; i < begin + count; ++i) {
    sampler.startPixelSample(pixel, 2, i, 9);
    for (int d = 0; d < point; ++d) sampler.get2D();
    values.push_back(sampler.get2D());
  }
  return values;
}

// The low-discrepancy sampler's first four points come from one Sobol sequence; each is a
// (t, 2)-sequence with at most this t for 4 to 512 samples. The later points are padded
// (0, 2)-sequences.
const int kLowDiscrepancyPointQuality[] = {2, 1, 1, 2, 0, 0};

}  // namespace

TEST(SamplerFactories, RoundSampleCountsAsMitsubaDoes) {
  const std::map<std::string, int> rounded = {
      {"independent", 5}, {"stratified", 9}, {"ldsampler", 8}, {"multijitter", 6}};
  for (const auto& [type, expected] : rounded) {
    auto sampler = std::dynamic_pointer_cast<Sampler>(build(samplerProperties(type, 5)));
    EXPECT_EQ(sampler->sampleCount(), expected) << type;
  }
  for (const std::string& type : kAllSamplers)
    EXPECT_EQ(std::dynamic_pointer_cast<Sampler>(build(samplerProperties(type, 16)))->sampleCount(), 16) << type;
}

// A render of another sample count than the scene's gets the sampler the scene would have made
// for that count: the same values, rounded the same way, not the first samples of the scene's
// pattern (which are not stratified among themselves).
TEST(SamplerFactories, ASampleCountOverrideIsTheSamplerMadeForThatCount) {
  for (const std::string& type : kAllSamplers) {
    for (int count : {5, 16}) {
      auto scenes = std::dynamic_pointer_cast<Sampler>(build(samplerProperties(type, 64)));
      auto made = std::dynamic_pointer_cast<Sampler>(build(samplerProperties(type, count)));
      std::unique_ptr<Sampler> overridden = scenes->withSampleCount(count);
      EXPECT_EQ(overridden->sampleCount(), made->sampleCount()) << type << " " << count;
      std::unique_ptr<Sampler> reference = made->clone();
      for (int index = 0; index < count; ++index)
        EXPECT_EQ(drawSample(*overridden, 3, 5, index, 11, 6), drawSample(*reference, 3, 5, index, 11, 6))
            << type << " " << count << " sample " << index;
    }
  }
}

TEST(SamplerFactories, ReadTheirParametersAndRejectBadCounts) {
  for (const std::string& type : kAllSamplers) {
    Properties props = samplerProperties(type, 16);
    props.set("seed", integerValue(7));
    if (type == "stratified" || type == "multijitter") props.set("jitter", booleanValue(false));
    build(props);
    EXPECT_NO_THROW(props.checkAllUsed()) << type;
    EXPECT_THROW(build(samplerProperties(type, 0)), InputError) << type;
    Properties defaults;
    defaults.type = type;
    EXPECT_EQ(std::dynamic_pointer_cast<Sampler>(build(defaults))->sampleCount(), 4) << type;
  }
}

TEST(SamplerValues, StayInTheUnitInterval) {
  for (const std::string& type : kAllSamplers) {
    auto sampler = makeSampler(type, 16);
    for (int p = 0; p < 64; ++p)
      for (int i = 0; i < 32; ++i)  // past sampleCount too
        for (float v : drawSample(*sampler, p % 8, p / 8, i, 3, 12)) {
          ASSERT_GE(v, 0.0f) << type;
          ASSERT_LT(v, 1.0f) << type;
        }
  }
}

TEST(SamplerValues, UnjitteredStrataUseTheirCentres) {
  for (const char* type : {"stratified", "multijitter"}) {
    Properties props = samplerProperties(type, 4);
    props.set("jitter", booleanValue(false));
    auto sampler = std::dynamic_pointer_cast<Sampler>(build(props));
    std::set<float> values;
    for (int i = 0; i < 4; ++i) {
      sampler->startPixelSample(1, 2, i, 0);
      values.insert(sampler->get1D());
    }
    EXPECT_EQ(values, (std::set<float>{0.125f, 0.375f, 0.625f, 0.875f})) << type;
  }
}

TEST(SamplerDeterminism, DependsOnlyOnPixelSampleIndexAndSeed) {
  for (const std::string& type : kAllSamplers) {
    auto a = makeSampler(type, 16);
    auto b = a->clone();
    // a visits pixels row by row, b in reverse order with its sample indices interleaved.
    std::map<std::tuple<int, int, int>, std::vector<float>> first;
    for (int py = 0; py < 4; ++py)
      for (int px = 0; px < 4; ++px)
        for (int i = 0; i < 16; ++i) first[{px, py, i}] = drawSample(*a, px, py, i, 42, 8);
    for (int i = 15; i >= 0; --i)
      for (int p = 15; p >= 0; --p)
        EXPECT_EQ(drawSample(*b, p % 4, p / 4, i, 42, 8), (first[{p % 4, p / 4, i}])) << type;
    // The sequence does change with the pixel, the sample index and the seed.
    EXPECT_NE(drawSample(*b, 1, 0, 0, 42, 8), (first[{0, 0, 0}])) << type;
    EXPECT_NE(drawSample(*b, 0, 1, 0, 42, 8), (first[{0, 0, 0}])) << type;
    EXPECT_NE(drawSample(*b, 0, 0, 1, 42, 8), (first[{0, 0, 0}])) << type;
    EXPECT_NE(drawSample(*b, 0, 0, 0, 43, 8), (first[{0, 0, 0}])) << type;
    // Past sampleCount a fresh pattern starts.
    EXPECT_NE(drawSample(*b, 0, 0, 16, 42, 8), (first[{0, 0, 0}])) << type;
  }
}

TEST(SamplerDeterminism, SceneSeedChangesTheSequence) {
  for (const std::string& type : kAllSamplers) {
    Properties seeded = samplerProperties(type, 16);
    seeded.set("seed", integerValue(1));
    auto a = std::dynamic_pointer_cast<Sampler>(build(samplerProperties(type, 16)));
    auto b = std::dynamic_pointer_cast<Sampler>(build(seeded));
    EXPECT_NE(drawSample(*a, 3, 4, 5, 0, 6), drawSample(*b, 3, 4, 5, 0, 6)) << type;
  }
}

TEST(SamplerStratification, EveryOneDimensionalStratumGetsOneSample) {
  for (const std::string& type : kStratifiedSamplers)
    for (int n : {16, 64}) {
      auto sampler = makeSampler(type, n);
      for (int pixel = 0; pixel < 20; ++pixel)
        for (int round = 0; round < 2; ++round) {
          // Dimension 0, and a later 1D dimension after a 2D one.
          std::vector<int> first, later;
          for (int i = 0; i < n; ++i) {
            sampler->startPixelSample(pixel, 7, round * n + i, 5);
            first.push_back(int(sampler->get1D() * n));
            sampler->get2D();
            later.push_back(int(sampler->get1D() * n));
          }
          EXPECT_TRUE(oneInEachCell(first, n)) << type << " n=" << n << " pixel " << pixel;
          EXPECT_TRUE(oneInEachCell(later, n)) << type << " n=" << n << " pixel " << pixel;
        }
    }
}

// The fifth 2D point of a sample: for ldsampler a padded one (its first four are nets of lower
// quality, tested below).
TEST(SamplerStratification, TwoDimensionalGridCellsGetOneSampleEach) {
  for (const std::string& type : kStratifiedSamplers)
    for (int n : {16, 64}) {
      const int res = int(std::lround(std::sqrt(n)));
      auto sampler = makeSampler(type, n);
      for (int pixel = 0; pixel < 20; ++pixel) {
        std::vector<int> cells;
        for (int i = 0; i < n; ++i) {
          sampler->startPixelSample(pixel, 1, i, 0);
          for (int skipped = 0; skipped < 4; ++skipped) sampler->get2D();
          Vec2 u = sampler->get2D();
          cells.push_back(int(u.y * res) * res + int(u.x * res));
        }
        EXPECT_TRUE(oneInEachCell(cells, n)) << type << " n=" << n << " pixel " << pixel;
      }
    }
}

// Two 1D requests of a sample, with 2D ones between them, are the two coordinates of one point:
// jointly stratified as that point is (point 0 and point 2 here).
TEST(SamplerStratification, LowDiscrepancyPairsOneDimensionalRequests) {
  const int log2n = 6, n = 1 << log2n;
  auto sampler = makeSampler("ldsampler", n);
  for (int pixel = 0; pixel < 20; ++pixel) {
    std::vector<Vec2> first, second, firstAsPoint, secondAsPoint;
    for (int i = 0; i < n; ++i) {
      sampler->startPixelSample(pixel, 4, i, 3);
      float a = sampler->get1D();
      sampler->get2D();
      float b = sampler->get1D();
      float c = sampler->get1D();
      sampler->get2D();
      float d = sampler->get1D();
      first.emplace_back(a, b);
      second.emplace_back(c, d);
      sampler->startPixelSample(pixel, 4, i, 3);
      firstAsPoint.push_back(sampler->get2D());
      sampler->get2D();
      secondAsPoint.push_back(sampler->get2D());
    }
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(first[i].x, firstAsPoint[i].x);
      ASSERT_EQ(first[i].y, firstAsPoint[i].y);
      ASSERT_EQ(second[i].x, secondAsPoint[i].x);
      ASSERT_EQ(second[i].y, secondAsPoint[i].y);
    }
    EXPECT_LE(netQuality(first), kLowDiscrepancyPointQuality[0]) << "pixel " << pixel;
    EXPECT_LE(netQuality(second), kLowDiscrepancyPointQuality[2]) << "pixel " << pixel;
  }
}

// Every point of the scene's pattern and of the progressive one, over all of a pixel's samples
// and over every aligned block of 2^k of them, is a net of its point's quality.
TEST(SamplerStratification, LowDiscrepancyPointsAreNetsOfTheirQuality) {
  for (int log2n = 2; log2n <= 9; ++log2n) {
    const int n = 1 << log2n;
    auto shuffled = makeSampler("ldsampler", n);
    auto progressive = shuffled->withProgressivePattern();
    for (int pixel = 0; pixel < 6; ++pixel)
      for (int point = 0; point < 6; ++point) {
        std::vector<Vec2> all = pointOfSamples(*shuffled, pixel, point, 0, n);
        EXPECT_LE(netQuality(all), kLowDiscrepancyPointQuality[point]) << "n " << n << ", point " << point;
        for (int k = 2; k <= log2n; ++k)
          for (int begin = 0; begin < n; begin += 1 << k)
            EXPECT_LE(netQuality(pointOfSamples(*progressive, pixel, point, begin, 1 << k)),
                      kLowDiscrepancyPointQuality[point])
                << "progressive, samples [" << begin << ", " << begin + (1 << k) << "), point " << point;
      }
  }
}

// The first four points are stratified together: any coordinate of one and any of another form a
// (t, 2)-net with t <= 3 at 256 samples. The padded points' coordinates are paired at random,
// which is a far worse net.
TEST(SamplerStratification, LowDiscrepancyFirstPointsAreStratifiedTogether) {
  const int n = 256;
  auto sampler = makeSampler("ldsampler", n);
  for (int pixel = 0; pixel < 4; ++pixel) {
    std::vector<std::vector<Vec2>> points;
    for (int point = 0; point < 6; ++point) points.push_back(pointOfSamples(*sampler, pixel, point, 0, n));
    auto coordinate = [&](int point, int axis, int i) { return axis == 0 ? points[point][i].x : points[point][i].y; };
    auto pairQuality = [&](int p, int a, int q, int b) {
      std::vector<Vec2> pairs;
      for (int i = 0; i < n; ++i) pairs.emplace_back(coordinate(p, a, i), coordinate(q, b, i));
      return netQuality(pairs);
    };
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b)
            EXPECT_LE(pairQuality(p, a, q, b), 3) << "points " << p << ", " << q << ", pixel " << pixel;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) EXPECT_GE(pairQuality(4, a, 5, b), 5) << "padded points, pixel " << pixel;
  }
}

// The low-discrepancy sampler fills a pixel's first dimensions for all its samples at once; every
// value must be the one computed for its sample alone, whatever order pixels, samples and
// dimension kinds come in.
TEST(SamplerDeterminism, LowDiscrepancyTablesMatchPointByPointValues) {
  for (bool progressive : {false, true})
    for (int n : {1, 4, 16, 64}) {
      auto sampler = makeSampler("ldsampler", n);
      if (progressive) sampler = sampler->withProgressivePattern();
      const uint64_t seed = 7;
      int checked = 0;
      // Pixels revisited, sample indices past the pattern (a second round), and dimensions drawn
      // as 1D by some samples and as 2D by others. A 1D request takes x of a new point, the next
      // one its y.
      for (int pass = 0; pass < 2; ++pass)
        for (int pixel : {3, 5, 3})
          for (int i = 0; i < 2 * n; ++i) {
            sampler->startPixelSample(pixel, 1, i, seed);
            PixelSampleState reference;
            reference.start(pixel, 1, i, hashCombine(seed, 0), uint32_t(n));
            std::optional<float> pendingY;
            uint32_t point = 0;
            for (int d = 0; d < 12; ++d) {
              if ((d + i + pass) % 3 != 0 && pendingY) {
                ASSERT_EQ(sampler->get1D(), *pendingY) << "n " << n << ", pixel " << pixel << ", sample " << i;
                pendingY.reset();
                ++checked;
                continue;
              }
              Vec2 expected = LowDiscrepancySampler::point2D(point++, reference.index, uint32_t(n),
                                                             reference.nextDimensionHash(), progressive);
              if ((d + i + pass) % 3 == 0) {
                Vec2 got = sampler->get2D();
                ASSERT_EQ(got.x, expected.x) << "n " << n << ", pixel " << pixel << ", sample " << i << ", dim " << d;
                ASSERT_EQ(got.y, expected.y) << "n " << n << ", pixel " << pixel << ", sample " << i << ", dim " << d;
              } else {
                ASSERT_EQ(sampler->get1D(), expected.x) << "n " << n << ", pixel " << pixel << ", sample " << i;
                pendingY = expected.y;
              }
              ++checked;
            }
          }
      EXPECT_EQ(checked, 2 * 3 * 2 * n * 12);
    }
}

// The progressive pattern of the padded points (from the fifth on): every aligned block of 2^k
// sample indices (a power-of-two prefix among them) fills all elementary intervals of 2^k cells.
// The scene's own pattern does so only for the whole pattern: its prefixes are random subsets of
// it.
TEST(SamplerStratification, ProgressiveLowDiscrepancyBlocksFillAllElementaryIntervals) {
  const int log2n = 6, n = 1 << log2n;
  auto progressive = makeSampler("ldsampler", n)->withProgressivePattern();
  auto shuffled = makeSampler("ldsampler", n);
  int shuffledPrefixesStratified = 0, shuffledPrefixes = 0;
  for (int pixel = 0; pixel < 20; ++pixel)
    for (int point = int(LowDiscrepancySampler::kSobolPoints); point < 7; ++point) {
      const std::vector<Vec2> p = pointOfSamples(*progressive, pixel, point, 0, n),
                              q = pointOfSamples(*shuffled, pixel, point, 0, n);
      auto fills = [](const std::vector<Vec2>& values, int begin, int k) {
        return netQuality(std::vector<Vec2>(values.begin() + begin, values.begin() + begin + (1 << k))) == 0;
      };
      for (int k = 1; k <= log2n; ++k) {
        for (int begin = 0; begin < n; begin += 1 << k)
          EXPECT_TRUE(fills(p, begin, k))
              << "block [" << begin << ", " << begin + (1 << k) << "), pixel " << pixel << ", point " << point;
        if (k >= 2 && k < log2n) {
          ++shuffledPrefixes;
          shuffledPrefixesStratified += fills(q, 0, k);
        }
      }
      EXPECT_TRUE(fills(q, 0, log2n));
    }
  // A random subset of 4 to 32 of the 64 points is rarely stratified.
  EXPECT_LT(shuffledPrefixesStratified, shuffledPrefixes / 10)
      << shuffledPrefixesStratified << " of " << shuffledPrefixes;
}

TEST(SamplerStratification, MultijitterProjectionsAreStratifiedInBothAxes) {
  const int n = 64;
  auto sampler = makeSampler("multijitter", n);
  for (int pixel = 0; pixel < 20; ++pixel) {
    std::vector<int> xs, ys;
    for (int i = 0; i < n; ++i) {
      sampler->startPixelSample(pixel, 3, i, 0);
      sampler->get1D();
      Vec2 u = sampler->get2D();
      xs.push_back(int(u.x * n));
      ys.push_back(int(u.y * n));
    }
    EXPECT_TRUE(oneInEachCell(xs, n)) << "pixel " << pixel;
    EXPECT_TRUE(oneInEachCell(ys, n)) << "pixel " << pixel;
  }
}

TEST(SamplerStratification, DimensionsAreNotCorrelated) {
  for (auto& [type, sampler] : allPatterns(16)) {
    // Two 1D requests (for ldsampler one point's x and y) and the x of two separate 2D dimensions.
    for (bool separate : {false, true}) {
      double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
      int count = 0;
      for (int pixel = 0; pixel < 500; ++pixel)
        for (int i = 0; i < 16; ++i) {
          sampler->startPixelSample(pixel, 0, i, 0);
          double x = separate ? sampler->get2D().x : sampler->get1D();
          double y = separate ? sampler->get2D().x : sampler->get1D();
          sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
          ++count;
        }
      double cov = sxy / count - sx / count * sy / count;
      double r = cov / std::sqrt((sxx / count - sqr(sx / count)) * (syy / count - sqr(sy / count)));
      EXPECT_LT(std::abs(r), 0.05) << type << (separate ? ", separate dimensions" : "");
    }
  }
}

TEST(SamplerUniformity, ChiSquareAgainstUniform) {
  const int bins = 12;  // not aligned with any stratum
  for (auto& [type, sampler] : allPatterns(16)) {
    std::vector<double> observed(bins * bins, 0.0);
    int count = 0;
    for (int pixel = 0; pixel < 4000; ++pixel)
      for (int i = 0; i < 16; ++i) {
        sampler->startPixelSample(pixel % 64, pixel / 64, i, 11);
        sampler->get1D();
        Vec2 u = sampler->get2D();
        observed[int(u.y * bins) * bins + int(u.x * bins)] += 1.0;
        ++count;
      }
    std::vector<double> expected(observed.size(), double(count) / observed.size());
    auto result = columba::testing::chiSquareTest(observed, expected);
    EXPECT_GT(result.pValue, 0.01) << type << ": " << result.message;
  }
}

namespace {
// The bump exp(-a (u - c)^2) and its integral over [0, 1], in closed form.
double bump(double u, double a, double c) { return std::exp(-a * sqr(u - c)); }
double bumpIntegral(double a, double c) {
  return 0.5 * std::sqrt(M_PI / a) * (std::erf(std::sqrt(a) * (1.0 - c)) + std::erf(std::sqrt(a) * c));
}
}  // namespace

TEST(SamplerIntegration, LowDiscrepancyBeatsIndependent) {
  // A smooth bump whose integral over the unit square is known in closed form.
  const double a = 4.0, cx = 0.3, cy = 0.6;
  auto f = [&](Vec2 u) { return bump(u.x, a, cx) * bump(u.y, a, cy); };
  const double exact = bumpIntegral(a, cx) * bumpIntegral(a, cy);
  const int n = 256, pixels = 200;
  std::map<std::string, double> rmsError;
  for (const std::string& type : kAllSamplers) {
    auto sampler = makeSampler(type, n);
    double squaredError = 0;
    for (int pixel = 0; pixel < pixels; ++pixel) {
      double sum = 0;
      for (int i = 0; i < n; ++i) {
        sampler->startPixelSample(pixel, 0, i, 0);
        sum += f(sampler->get2D());
      }
      squaredError += sqr(sum / n - exact);
    }
    rmsError[type] = std::sqrt(squaredError / pixels);
  }
  for (const std::string& type : kStratifiedSamplers)
    EXPECT_LT(rmsError[type], 0.2 * rmsError["independent"])
        << type << " " << rmsError[type] << " vs independent " << rmsError["independent"];
  // Independent sampling itself is unbiased with the expected O(1/sqrt(n)) error.
  EXPECT_LT(rmsError["independent"], 0.05);
}

// A product of bumps over the four coordinates of two points: the first points, stratified
// together, integrate it with less error than two padded points, each stratified only by itself.
TEST(SamplerIntegration, LowDiscrepancyFirstPointsIntegrateTogether) {
  const double a = 4.0, centres[4] = {0.3, 0.6, 0.45, 0.7};
  auto f = [&](Vec2 u, Vec2 v) {
    return bump(u.x, a, centres[0]) * bump(u.y, a, centres[1]) * bump(v.x, a, centres[2]) * bump(v.y, a, centres[3]);
  };
  double exact = 1.0;
  for (double c : centres) exact *= bumpIntegral(a, c);
  const int n = 256, pixels = 200;
  auto sampler = makeSampler("ldsampler", n);
  auto rmsError = [&](int first, int second) {
    double squaredError = 0;
    for (int pixel = 0; pixel < pixels; ++pixel) {
      std::vector<Vec2> u = pointOfSamples(*sampler, pixel, first, 0, n),
                        v = pointOfSamples(*sampler, pixel, second, 0, n);
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += f(u[i], v[i]);
      squaredError += sqr(sum / n - exact);
    }
    return std::sqrt(squaredError / pixels);
  };
  const double together = rmsError(0, 2), padded = rmsError(4, 5);
  EXPECT_LT(together, 0.5 * padded) << "points 0 and 2: " << together << ", padded points 4 and 5: " << padded;
  EXPECT_LT(padded, 0.01);
}

// Each dimension of the table is a (0, 1)-sequence: the first 2^m points fill the 2^m intervals
// of length 2^-m, one each; dimension 1 agrees with its byte-table form.
TEST(SobolSequence, EveryDimensionIsStratified) {
  for (int dimension = 0; dimension < kSobolDimensions; ++dimension)
    for (int m = 1; m <= 12; ++m) {
      std::vector<int> cells;
      for (uint32_t i = 0; i < (1u << m); ++i)
        cells.push_back(int(reverseBits(sobolReversed(dimension, i)) >> (32 - m)));
      EXPECT_TRUE(oneInEachCell(cells, 1 << m)) << "dimension " << dimension << ", m " << m;
    }
  for (uint32_t index = 0; index < 65536; ++index) ASSERT_EQ(sobolReversed(1, index), sobolDimension1Reversed(index));
}

TEST(SobolSequence, SecondDimensionMatchesItsGeneratorMatrix) {
  // Columns v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1); the point is the xor of the columns of the
  // index's set bits, here compared with its bits reversed.
  uint32_t columns[32];
  columns[0] = 1u << 31;
  for (int k = 1; k < 32; ++k) columns[k] = columns[k - 1] ^ (columns[k - 1] >> 1);
  auto direct = [&](uint32_t index) {
    uint32_t v = 0;
    for (int k = 0; k < 32; ++k)
      if (index >> k & 1u) v ^= columns[k];
    return v;
  };
  for (uint32_t index = 0; index < 4096; ++index) ASSERT_EQ(reverseBits(sobolDimension1Reversed(index)), direct(index));
  uint32_t x = 12345;
  for (int i = 0; i < 100000; ++i) {
    x = x * 1664525u + 1013904223u;
    ASSERT_EQ(reverseBits(sobolDimension1Reversed(x)), direct(x)) << x;
  }
}

TEST(HashedPermutation, PowerOfTwoShortcutIsTheSamePermutation) {
  for (uint32_t n : {1u, 2u, 16u, 64u, 1024u})
    for (uint32_t seed : {0u, 7u, 0x9e3779b9u, 0xdeadbeefu}) {
      std::set<uint32_t> seen;
      for (uint32_t i = 0; i < n; ++i) {
        uint32_t p = permutationElementPowerOfTwo(i, n - 1, seed);
        ASSERT_EQ(p, permutationElement(i, n, seed));
        seen.insert(p);
      }
      EXPECT_EQ(seen.size(), n);
      EXPECT_LT(*seen.rbegin(), n);
    }
}
