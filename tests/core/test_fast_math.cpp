// Every fast function of core/fast_math.h (and the compile-time helpers of core/math.h) against the
// standard library in double, in dense sweeps over its whole stated domain, with the largest
// error asserted. Each bound is a named constant a little above the measured maximum (in its
// comment).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include "core/fast_math.h"

using namespace columba;

namespace {

// asinLanes on [-1, 1], absolute: the polynomial's 2e-8 plus the rounding of pi/2 - sqrt(1 - |x|) P,
// whose terms are near pi/2. Measured 3.7e-7.
constexpr double kAsinMaxAbsError = 4e-7;
// sincAndCosWithinQuarterTurn and sinCosWithinQuarterTurn on [-pi/2, pi/2], absolute. Measured
// sin(x)/x 1.5e-7, cos 1.0e-7, sin 2.5e-7.
constexpr double kQuarterTurnMaxAbsError = 3e-7;
// cosSinOfSmallAngle on [-kSmallAngleLimit, kSmallAngleLimit], absolute: the truncation x^4 / 24
// of the cosine dominates. Measured cos 1.74e-6, sin 3.3e-8.
constexpr double kSmallAngleCosMaxAbsError = 2e-6, kSmallAngleSinMaxAbsError = 6e-8;
// sinSqr on [0, kSinSqrLimit], absolute: the range reduction's rounding of x / pi grows with x.
// Measured 2.2e-5 (four lanes), 1.0e-5 (eight lanes, with fused multiply-adds).
constexpr double kSinSqrMaxAbsError = 3e-5;
// constexprSqrt, constexprSin, constexprCos, relative to the library's double results. Measured
// 2.2e-16, 6.7e-16, 4.4e-16.
constexpr double kConstexprMaxRelError = 1e-15;

// count + 1 evenly spaced floats of [lo, hi], then every float of the `tailUlps` ulps below hi.
std::vector<float> sweep(double lo, double hi, int count, int tailUlps = 0) {
  std::vector<float> x;
  x.reserve(size_t(count) + size_t(tailUlps) + 1);
  for (int i = 0; i <= count; ++i) x.push_back(float(lo + (hi - lo) * i / count));
  float f = float(hi);
  for (int i = 0; i < tailUlps; ++i) x.push_back(f = std::nextafter(f, float(lo)));
  return x;
}

// The sweep four lanes at a time (a last partial group repeats its first value).
template <typename F>
void forEachLaneGroup(const std::vector<float>& x, F&& f) {
  for (size_t i = 0; i < x.size(); i += kLaneCount) {
    FloatLanes v;
    for (int k = 0; k < kLaneCount; ++k) v[k] = x[std::min(i + size_t(k), x.size() - 1)];
    f(v);
  }
}

struct MaxError {
  double value = 0.0, at = 0.0;
  void add(double error, double x) {
    if (error > value) value = error, at = x;
  }
};

// Eight-lane versions, compiled for AVX2 as the thin film's eight-lane path is.
__attribute__((target("avx2,fma"))) void sinSqrEight(const float* x, float* out) {
  FloatLanes8 v;
  for (int k = 0; k < 8; ++k) v[k] = x[k];
  v = sinSqr(v);
  for (int k = 0; k < 8; ++k) out[k] = v[k];
}
__attribute__((target("avx2,fma"))) void sqrtEight(const float* x, float* out) {
  FloatLanes8 v = joinLanes(FloatLanes{x[0], x[1], x[2], x[3]}, FloatLanes{x[4], x[5], x[6], x[7]});
  v = sqrtLanes(v);
  FloatLanes low = lowLanes(v), high = highLanes(v);
  for (int k = 0; k < 4; ++k) out[k] = low[k], out[k + 4] = high[k];
}

}  // namespace

TEST(FastMath, LaneHelpersAreExact) {
  // Square roots over every binade, absolute values, clamps, the pairwise lane sums.
  std::vector<float> x = sweep(0.0, 4.0, 1 << 16);
  for (float t = 1e-38f; t < 1e38f; t *= 1.37f) x.push_back(t);
  forEachLaneGroup(x, [&](FloatLanes v) {
    FloatLanes signed_ = v * FloatLanes{1.0f, -1.0f, 1.0f, -1.0f};
    FloatLanes root = sqrtLanes(v), magnitude = absLanes(signed_), clamped = clampLanes(signed_, -1.0f, 2.0f);
    for (int k = 0; k < kLaneCount; ++k) {
      ASSERT_EQ(root[k], std::sqrt(v[k]));
      ASSERT_EQ(magnitude[k], std::abs(signed_[k]));
      ASSERT_EQ(clamped[k], std::clamp(signed_[k], -1.0f, 2.0f));
    }
    FloatLanes rows[4] = {v, signed_, v * 3.0f, v + 1.0f};
    FloatLanes sums = laneSums(rows[0], rows[1], rows[2], rows[3]);
    for (int r = 0; r < 4; ++r) ASSERT_EQ(sums[r], (rows[r][0] + rows[r][2]) + (rows[r][1] + rows[r][3]));
  });
  if (!hasAvx2()) GTEST_SKIP() << "no AVX2: the eight-lane square root is not run";
  for (size_t i = 0; i + 8 <= x.size(); i += 8) {
    float root[8];
    sqrtEight(&x[i], root);
    for (int k = 0; k < 8; ++k) ASSERT_EQ(root[k], std::sqrt(x[i + k]));
  }
}

TEST(FastMath, LaneGroupsArePaddedWithZeros) {
  std::vector<FloatLanes> groups = laneGroups({0.5, 0.25, 0.125, 1.0, 2.0});
  ASSERT_EQ(groups.size(), 2u);
  const float first[kLaneCount] = {0.5f, 0.25f, 0.125f, 1.0f};
  for (int k = 0; k < kLaneCount; ++k) EXPECT_EQ(groups[0][k], first[k]);
  for (int k = 0; k < kLaneCount; ++k) EXPECT_EQ(groups[1][k], k == 0 ? 2.0f : 0.0f);
  EXPECT_TRUE(laneGroups({}).empty());
}

TEST(FastMath, AsinLanesOverItsWholeDomain) {
  std::vector<float> x = sweep(-1.0, 1.0, 1 << 23, 1 << 16);
  for (float t = 1e-30f; t < 1e-3f; t *= 1.5f) x.push_back(t);
  MaxError e;
  forEachLaneGroup(x, [&](FloatLanes v) {
    FloatLanes a = asinLanes(v);
    for (int k = 0; k < kLaneCount; ++k) e.add(std::abs(a[k] - std::asin(double(v[k]))), v[k]);
  });
  // Clamped beyond the domain.
  FloatLanes beyond = asinLanes(FloatLanes{1.5f, -1.5f, 1.0f, -1.0f});
  for (int k = 0; k < kLaneCount; ++k) EXPECT_NEAR(std::abs(beyond[k]), kPiDouble / 2, kAsinMaxAbsError);
  std::printf("asinLanes: max abs error %.2e at %.9g\n", e.value, e.at);
  EXPECT_LT(e.value, kAsinMaxAbsError) << e.at;
}

TEST(FastMath, SinAndCosWithinAQuarterTurn) {
  std::vector<float> x = sweep(-kPiDouble / 2, kPiDouble / 2, 1 << 23, 1 << 12);
  for (float t = 1e-30f; t < 1e-3f; t *= 1.5f) x.push_back(t);
  MaxError sinc, cosine, sine;
  forEachLaneGroup(x, [&](FloatLanes v) {
    FloatLanes sincLanes, cosLanes, sinLanes, cos2;
    sincAndCosWithinQuarterTurn(v, sincLanes, cosLanes);
    sinCosWithinQuarterTurn(v, sinLanes, cos2);
    for (int k = 0; k < kLaneCount; ++k) {
      double t = v[k];
      float scalarSinc, scalarCos;
      sincAndCosWithinQuarterTurn(v[k], scalarSinc, scalarCos);  // the same arithmetic in floats
      ASSERT_EQ(scalarSinc, sincLanes[k]);
      ASSERT_EQ(scalarCos, cosLanes[k]);
      ASSERT_EQ(cos2[k], cosLanes[k]);
      sinc.add(std::abs(sincLanes[k] - (t == 0.0 ? 1.0 : std::sin(t) / t)), t);
      cosine.add(std::abs(cosLanes[k] - std::cos(t)), t);
      sine.add(std::abs(sinLanes[k] - std::sin(t)), t);
    }
  });
  std::printf("quarter turn: max abs error sin(x)/x %.2e at %.9g, cos %.2e at %.9g, sin %.2e at %.9g\n", sinc.value,
              sinc.at, cosine.value, cosine.at, sine.value, sine.at);
  EXPECT_LT(sinc.value, kQuarterTurnMaxAbsError) << sinc.at;
  EXPECT_LT(cosine.value, kQuarterTurnMaxAbsError) << cosine.at;
  EXPECT_LT(sine.value, kQuarterTurnMaxAbsError) << sine.at;
}

TEST(FastMath, CosSinOfSmallAngles) {
  std::vector<float> x = sweep(-kSmallAngleLimit, kSmallAngleLimit, 1 << 22);
  MaxError cosine, sine;
  forEachLaneGroup(x, [&](FloatLanes v) {
    FloatLanes c, s;
    cosSinOfSmallAngle(v, c, s);
    for (int k = 0; k < kLaneCount; ++k) {
      float scalarCos, scalarSin;
      cosSinOfSmallAngle(v[k], scalarCos, scalarSin);
      ASSERT_EQ(scalarCos, c[k]);
      ASSERT_EQ(scalarSin, s[k]);
      cosine.add(std::abs(c[k] - std::cos(double(v[k]))), v[k]);
      sine.add(std::abs(s[k] - std::sin(double(v[k]))), v[k]);
    }
  });
  std::printf("small angles: max abs error cos %.2e at %.9g, sin %.2e at %.9g\n", cosine.value, cosine.at, sine.value,
              sine.at);
  EXPECT_LT(cosine.value, kSmallAngleCosMaxAbsError) << cosine.at;
  EXPECT_LT(sine.value, kSmallAngleSinMaxAbsError) << sine.at;
}

TEST(FastMath, SinSqrOverItsWholeDomain) {
  std::vector<float> x = sweep(0.0, kSinSqrLimit, 1 << 24);
  MaxError four, eight;
  forEachLaneGroup(x, [&](FloatLanes v) {
    FloatLanes s = sinSqr(v);
    for (int k = 0; k < kLaneCount; ++k) {
      double exact = std::sin(double(v[k]));
      four.add(std::abs(s[k] - exact * exact), v[k]);
    }
  });
  std::printf("sinSqr: max abs error %.2e at %.9g\n", four.value, four.at);
  EXPECT_LT(four.value, kSinSqrMaxAbsError) << four.at;
  if (!hasAvx2()) GTEST_SKIP() << "no AVX2: the eight-lane sinSqr is not run";
  for (size_t i = 0; i + 8 <= x.size(); i += 8) {
    float s[8];
    sinSqrEight(&x[i], s);
    for (int k = 0; k < 8; ++k) {
      double exact = std::sin(double(x[i + k]));
      eight.add(std::abs(s[k] - exact * exact), x[i + k]);
    }
  }
  std::printf("sinSqr, eight lanes: max abs error %.2e at %.9g\n", eight.value, eight.at);
  EXPECT_LT(eight.value, kSinSqrMaxAbsError) << eight.at;
}

TEST(FastMath, CompileTimeSqrtSinAndCos) {
  MaxError root, sine, cosine;
  for (double x = 1e-12; x < 1e18; x *= 1.001) root.add(std::abs(constexprSqrt(x) / std::sqrt(x) - 1.0), x);
  for (double x : sweep(-kPiDouble / 4, kPiDouble / 4, 1 << 18)) {
    sine.add(x == 0.0 ? 0.0 : std::abs(constexprSin(x) / std::sin(x) - 1.0), x);
    cosine.add(std::abs(constexprCos(x) / std::cos(x) - 1.0), x);
  }
  std::printf("compile-time: max relative error sqrt %.2e, sin %.2e, cos %.2e\n", root.value, sine.value, cosine.value);
  EXPECT_LE(root.value, kConstexprMaxRelError) << root.at;
  EXPECT_LE(sine.value, kConstexprMaxRelError) << sine.at;
  EXPECT_LE(cosine.value, kConstexprMaxRelError) << cosine.at;
}
