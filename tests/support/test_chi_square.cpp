#include <gtest/gtest.h>

#include "core/sampling.h"
#include "support/chi_square.h"

using namespace columba;
using namespace columba::testing;

TEST(ChiSquare, GammaQMatchesKnownValues) {
  // Chi-square survival function: P(X > 3.841) = 0.05 for 1 dof; P(X > 18.307) = 0.05 for 10 dof.
  EXPECT_NEAR(regularizedGammaQ(0.5, 3.841459 / 2), 0.05, 1e-5);
  EXPECT_NEAR(regularizedGammaQ(5.0, 18.307038 / 2), 0.05, 1e-5);
  EXPECT_NEAR(regularizedGammaQ(1.0, 2.0), std::exp(-2.0), 1e-12);
}

TEST(ChiSquare, AcceptsCosineHemisphereAgainstItsPdf) {
  auto result = chiSquareDirectionTest(
      [](PCG32& rng) -> std::optional<Vec3> { return sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat())); },
      [](const Vec3& w) { return double(cosineHemispherePdf(w.z)); }, 500000);
  std::cout << result.message << "\n";
  EXPECT_GT(result.pValue, 0.01);
}

TEST(ChiSquare, RejectsAMismatchedPdf) {
  // Uniform hemisphere samples tested against the cosine density must fail.
  auto result = chiSquareDirectionTest(
      [](PCG32& rng) -> std::optional<Vec3> {
        Vec3 w = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
        return Vec3(w.x, w.y, std::abs(w.z));
      },
      [](const Vec3& w) { return double(cosineHemispherePdf(w.z)); }, 200000);
  EXPECT_LT(result.pValue, 1e-6);
}

TEST(ChiSquare, RejectsSamplesWhereThePdfIsZero) {
  auto result = chiSquareDirectionTest(
      [](PCG32& rng) -> std::optional<Vec3> { return sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat())); },
      [](const Vec3& w) { return w.z > 0 ? double(cosineHemispherePdf(w.z)) : 0.0; }, 100000);
  EXPECT_LT(result.pValue, 1e-12);
}
