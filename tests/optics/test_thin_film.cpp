#include <gtest/gtest.h>

#include <utility>
#include "core/rng.h"
#include "optics/dispersion.h"
#include "optics/fresnel.h"
#include "optics/melanin.h"
#include "optics/thin_film.h"

using namespace columba;

namespace {
constexpr double kAir = 1.000277;
double keratin(double lambda) { return RefractiveIndex::keratin()(float(lambda)); }
}  // namespace

TEST(ThinFilm, ZeroThicknessIsTheBareInterface) {
  // Without thickness the film disappears: air over a keratin substrate is one Fresnel interface,
  // whatever the film's index.
  for (double filmIndex : {1.33, 1.55, 2.2})
    for (double cosI : {1.0, 0.8, 0.5, 0.2, 0.05}) {
      ThinFilmAmplitudes a = thinFilmAmplitudes(cosI, kAir, filmIndex, 1.56, 0.0, 550.0);
      FresnelAmplitudes f = fresnelAmplitudes(float(cosI), float(1.56 / kAir));
      EXPECT_NEAR(a.rs.real(), f.rs, 1e-6);
      EXPECT_NEAR(a.rp.real(), f.rp, 1e-6);
      EXPECT_NEAR(a.rs.imag(), 0.0, 1e-9);
      EXPECT_NEAR(thinFilmReflectance(cosI, kAir, filmIndex, 1.56, 0.0, 550.0),
                  fresnelDielectric(float(cosI), float(1.56 / kAir)), 1e-6);
    }
  // A free-standing film of zero thickness reflects nothing, in both implementations.
  EXPECT_NEAR(thinFilmReflectance(0.7, kAir, 1.55, kAir, 0.0, 500.0), 0.0, 1e-12);
  FreeStandingFilm film(RefractiveIndex::keratin(), float(kAir), 0.0f, Wavelengths::fixed({400, 500, 600, 700}));
  FreeStandingFilm::Reflectance r = film.reflectance(0.7f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    EXPECT_NEAR(r.s[i], 0.0f, 1e-6f);
    EXPECT_NEAR(r.p[i], 0.0f, 1e-6f);
  }
}

TEST(ThinFilm, NormalIncidenceMatchesTheClosedForm) {
  // R = (r1^2 + r2^2 + 2 r1 r2 cos(delta)) / (1 + r1^2 r2^2 + 2 r1 r2 cos(delta)), delta = 4 pi n2 d / lambda.
  for (double n3 : {1.0, 1.3, 2.0})
    for (double d : {0.1, 0.35, 0.58, 1.2})
      for (double lambda : {380.0, 455.0, 530.0, 610.0, 700.0, 820.0}) {
        double n1 = kAir, n2 = keratin(lambda);
        double r1 = (n1 - n2) / (n1 + n2), r2 = (n2 - n3) / (n2 + n3);
        double cosDelta = std::cos(4.0 * M_PI * n2 * d * 1000.0 / lambda);
        double expected =
            (r1 * r1 + r2 * r2 + 2 * r1 * r2 * cosDelta) / (1 + r1 * r1 * r2 * r2 + 2 * r1 * r2 * cosDelta);
        EXPECT_NEAR(thinFilmReflectance(1.0, n1, n2, n3, d, lambda), expected, 1e-9)
            << "n3 " << n3 << " d " << d << " lambda " << lambda;
      }
}

TEST(ThinFilm, PeakMovesToShorterWavelengthsAsTheAngleGrows) {
  // The green interference order of a 0.58 um keratin film: follow its reflectance maximum from
  // normal incidence to grazing.
  auto reflectance = [](double lambda, double cosI) {
    return thinFilmReflectance(cosI, kAir, keratin(lambda), kAir, 0.58, lambda);
  };
  auto peakNear = [&](double start, double cosI) {
    double best = start, bestValue = -1.0;
    for (double lambda = start - 40.0; lambda <= start + 40.0; lambda += 0.05)
      if (double v = reflectance(lambda, cosI); v > bestValue) {
        bestValue = v;
        best = lambda;
      }
    return best;
  };
  double peak = peakNear(520.0, 1.0);
  EXPECT_GT(peak, 490.0);
  EXPECT_LT(peak, 550.0);
  std::cout << "peak at 0 deg: " << peak << " nm";
  for (double degrees : {20.0, 40.0, 60.0, 75.0}) {
    double next = peakNear(peak, std::cos(degrees * M_PI / 180.0));
    std::cout << ", " << degrees << " deg: " << next << " nm";
    EXPECT_LT(next, peak - 1.0) << degrees << " degrees";
    peak = next;
  }
  std::cout << "\n";
}

TEST(ThinFilm, ReflectanceAndTransmittanceStayInTheUnitInterval) {
  PCG32 rng(3);
  for (int i = 0; i < 20000; ++i) {
    double cosI = rng.nextDouble(), lambda = 360.0 + 470.0 * rng.nextDouble(), d = 2.0 * rng.nextDouble();
    double n1 = 1.0 + rng.nextDouble(), n2 = 1.0 + 1.5 * rng.nextDouble(), n3 = 1.0 + 1.5 * rng.nextDouble();
    double R = thinFilmReflectance(cosI, n1, n2, n3, d, lambda), T = thinFilmTransmittance(cosI, n1, n2, n3, d, lambda);
    ASSERT_GE(R, 0.0);
    ASSERT_LE(R, 1.0 + 1e-12);
    ASSERT_GE(T, 0.0);
    ASSERT_LE(T, 1.0 + 1e-12);
  }
}

TEST(ThinFilm, LosslessFilmConservesEnergy) {
  // R + T = 1 per polarisation, with T = (n3 cos theta3) / (n1 cos theta1) |t|^2: a free-standing
  // film (n3 = n1), a film on a substrate, and beyond the substrate's critical angle (T = 0).
  PCG32 rng(5);
  for (int i = 0; i < 5000; ++i) {
    double cosI = 0.01 + 0.99 * rng.nextDouble(), lambda = 360.0 + 470.0 * rng.nextDouble(), d = 1.5 * rng.nextDouble();
    double n1 = 1.0 + 0.6 * rng.nextDouble(), n2 = 1.0 + 1.5 * rng.nextDouble();
    for (double n3 : {n1, 1.0 + 1.5 * rng.nextDouble()}) {
      ThinFilmAmplitudes a = thinFilmAmplitudes(cosI, n1, n2, n3, d, lambda);
      ASSERT_NEAR(std::norm(a.rs) + a.transmittanceFactor * std::norm(a.ts), 1.0, 1e-9);
      ASSERT_NEAR(std::norm(a.rp) + a.transmittanceFactor * std::norm(a.tp), 1.0, 1e-9);
    }
  }
  ThinFilmAmplitudes tir = thinFilmAmplitudes(0.3, 1.5, 1.4, 1.0, 0.3, 500.0);
  EXPECT_EQ(tir.transmittanceFactor, 0.0);
  EXPECT_NEAR(std::norm(tir.rs), 1.0, 1e-9);
  EXPECT_NEAR(std::norm(tir.rp), 1.0, 1e-9);
}

TEST(ThinFilm, FreeStandingFilmMatchesTheAirySum) {
  // The real-arithmetic film of the barbule BSDF against the general complex evaluation.
  PCG32 rng(9);
  for (int i = 0; i < 2000; ++i) {
    std::array<float, kSpectrumSamples> lambdas;
    for (float& l : lambdas) l = 360.0f + 470.0f * rng.nextFloat();
    float height = 1.2f * rng.nextFloat(), cosI = rng.nextFloat();
    Wavelengths wl = Wavelengths::fixed(lambdas);
    FreeStandingFilm film(RefractiveIndex::keratin(), float(kAir), height, wl);
    FreeStandingFilm::Reflectance r = film.reflectance(cosI);
    // Near grazing incidence the film's reflectance changes by ~1e-5 per float ulp of the cosine.
    double tolerance = cosI > 0.05f ? 2e-5 : 5e-4;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      ThinFilmAmplitudes a = thinFilmAmplitudes(std::max(cosI, 1e-4f), kAir, keratin(wl[k]), kAir, height, wl[k]);
      ASSERT_NEAR(r.s[k], std::norm(a.rs), tolerance) << "cos " << cosI << " lambda " << wl[k] << " d " << height;
      ASSERT_NEAR(r.p[k], std::norm(a.rp), tolerance) << "cos " << cosI << " lambda " << wl[k] << " d " << height;
      // Its transmittance 1 - R is the film transmission |t|^2 of the Airy sum.
      ASSERT_NEAR(1.0f - r.s[k], std::norm(a.ts), tolerance);
    }
  }
}

TEST(ThinFilm, FreeStandingFilmTransmittanceProductMatchesTheAirySum) {
  // Two crossings of the film (the barbule's TRT lobe) at independent angles.
  PCG32 rng(10);
  for (int i = 0; i < 2000; ++i) {
    std::array<float, kSpectrumSamples> lambdas;
    for (float& l : lambdas) l = 360.0f + 470.0f * rng.nextFloat();
    float height = 1.2f * rng.nextFloat(), cos1 = rng.nextFloat(), cos2 = rng.nextFloat();
    Wavelengths wl = Wavelengths::fixed(lambdas);
    FreeStandingFilm film(RefractiveIndex::keratin(), float(kAir), height, wl);
    Spectrum product = film.transmittanceProduct(cos1, cos2);
    double tolerance = std::min(cos1, cos2) > 0.05f ? 2e-5 : 5e-4;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      ThinFilmAmplitudes a = thinFilmAmplitudes(std::max(cos1, 1e-4f), kAir, keratin(wl[k]), kAir, height, wl[k]);
      ThinFilmAmplitudes b = thinFilmAmplitudes(std::max(cos2, 1e-4f), kAir, keratin(wl[k]), kAir, height, wl[k]);
      double expected = 0.5 * (std::norm(a.ts) * std::norm(b.ts) + std::norm(a.tp) * std::norm(b.tp));
      ASSERT_NEAR(product[k], expected, tolerance) << "cos " << cos1 << ", " << cos2 << " lambda " << wl[k];
    }
  }
}

TEST(Optics, KeratinFollowsCauchysLaw) {
  RefractiveIndex k = RefractiveIndex::keratin();
  EXPECT_NEAR(k(500.0f), 1.532f + 5890.0f / 250000.0f, 1e-6f);
  EXPECT_GT(k(400.0f), k(700.0f));  // normal dispersion
  ASSERT_TRUE(iorFromName("keratin"));
  EXPECT_EQ(iorFromName("keratin")->b, 5890.0f);
  ASSERT_TRUE(iorFromName("air"));
  EXPECT_NEAR((*iorFromName("air"))(550.0f), 1.000277f, 1e-7f);
  ASSERT_TRUE(iorFromName("1.6"));
  EXPECT_NEAR((*iorFromName("1.6"))(400.0f), 1.6f, 1e-7f);
  EXPECT_FALSE(iorFromName("unobtainium"));
  EXPECT_FALSE(iorFromName("-1"));
  EXPECT_FALSE(iorFromName("1.5x"));
}

// The embedded melanin table against the measured reflectance published with the paper's own
// implementation (Huang et al. 2022, github.com/RiverIntheSky/dove_neck,
// resources/data/ior/melanin.r.spd: 105 lines of wavelength nm and intensity reflectance, 249.79
// to 900.06 nm). Spot values across the range, its minimum and maximum, and both ends.
TEST(Optics, MelaninTableMatchesThePublishedMeasurements) {
  const std::pair<double, double> published[] = {
      {249.7909, 0.0300}, {253.6204, 0.0284}, {282.3302, 0.0199}, {331.7368, 0.0412},
      {399.6706, 0.0470}, {460.6789, 0.0487}, {501.3511, 0.0496}, {542.0233, 0.0509},
      {548.8020, 0.0510}, {603.0316, 0.0522}, {670.7238, 0.0551}, {704.7121, 0.0562},
      {799.6139, 0.0584}, {853.8435, 0.0593}, {894.5158, 0.0595}, {900.0620, 0.0593}};
  for (const auto& [lambda, value] : published) EXPECT_NEAR(melaninReflectance(float(lambda)), value, 1e-6) << lambda;
  // Linear between neighbouring measurements.
  EXPECT_NEAR(melaninReflectance(0.5f * (249.7909f + 253.6204f)), 0.5 * (0.0300 + 0.0284), 1e-5);
  EXPECT_NEAR(melaninReflectance(0.5f * (542.0233f + 548.8020f)), 0.5 * (0.0509 + 0.0510), 1e-5);
  EXPECT_NEAR(melaninReflectance(0.25f * 894.5158f + 0.75f * 900.0620f), 0.25 * 0.0595 + 0.75 * 0.0593, 1e-5);
  // The measurements lie between 0.0199 (at 282 nm) and 0.0595 (at 895 nm); so does every value
  // in between.
  for (float lambda = 250.0f; lambda <= 900.0f; lambda += 0.25f) {
    EXPECT_GE(melaninReflectance(lambda), 0.0199f - 1e-6f) << lambda;
    EXPECT_LE(melaninReflectance(lambda), 0.0595f + 1e-6f) << lambda;
  }
  // Constant beyond the measured range.
  EXPECT_NEAR(melaninReflectance(100.0f), 0.0300f, 1e-6f);
  EXPECT_NEAR(melaninReflectance(1500.0f), 0.0593f, 1e-6f);
}

TEST(ThinFilm, FreeStandingFilmWeightedProductsMatchThePairwiseProducts) {
  // The quadrature's entry point against the per-pair transmittanceProduct, in both
  // implementations where the processor runs both.
  const Wavelengths wl = Wavelengths::fixed({405.0f, 498.0f, 577.0f, 689.0f});
  FreeStandingFilm film(RefractiveIndex::keratin(), 1.000277f, 0.58f, wl);
  PCG32 rng(5);
  for (int i = 0; i < 2000; ++i) {
    FloatLanes weight, cos1, cos2;
    for (int j = 0; j < kLaneCount; ++j) {
      weight[j] = rng.nextFloat();
      // Including grazing and slightly negative cosines, which the film clamps.
      cos1[j] = rng.nextFloat() * 1.01f - 0.005f;
      cos2[j] = rng.nextFloat() * 1.01f - 0.005f;
    }
    Spectrum expected;
    for (int j = 0; j < kLaneCount; ++j) expected += weight[j] * film.transmittanceProduct(cos1[j], cos2[j]);
    std::vector<Spectrum> results = {film.weightedTransmittanceProducts(weight, cos1, cos2),
                                     film.weightedTransmittanceProductsPortable(weight, cos1, cos2)};
    if (hasAvx2()) results.push_back(film.weightedTransmittanceProductsAvx2(weight, cos1, cos2));
    for (const Spectrum& r : results)
      for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_NEAR(r[k], expected[k], 2e-5f * (1.0f + expected[k])) << i;
  }
}

TEST(ThinFilm, FreeStandingFilmAveragesOverWavelengthsMatchTheAirySum) {
  // Against the complex Airy amplitudes in double precision: the mean over the wavelengths of
  // (R_s + R_p) / 2 and of w (T_s^2 + T_p^2) / 2, in both implementations where the processor
  // runs both.
  const Wavelengths wl = Wavelengths::fixed({405.0f, 498.0f, 577.0f, 689.0f});
  const float nAir = 1.000277f, thickness = 0.58f;
  const RefractiveIndex keratin = RefractiveIndex::keratin();
  FreeStandingFilm film(keratin, nAir, thickness, wl);
  const Spectrum weight(FloatLanes{0.03f, 0.5f, 1.0f, 0.2f});
  PCG32 rng(9);
  for (int i = 0; i < 500; ++i) {
    FloatLanes cosines;
    for (int j = 0; j < kLaneCount; ++j) cosines[j] = 0.001f + 0.999f * rng.nextFloat();
    std::vector<FreeStandingFilm::Averages> results = {film.averagesOverWavelengths(cosines, weight),
                                                       film.averagesOverWavelengthsPortable(cosines, weight)};
    if (hasAvx2()) results.push_back(film.averagesOverWavelengthsAvx2(cosines, weight));
    for (int j = 0; j < kLaneCount; ++j) {
      double reflectance = 0.0, transmittanceSqr = 0.0;
      for (int k = 0; k < kSpectrumSamples; ++k) {
        ThinFilmAmplitudes a = thinFilmAmplitudes(cosines[j], nAir, keratin(wl[k]), nAir, thickness, wl[k]);
        double ts = a.transmittanceFactor * std::norm(a.ts), tp = a.transmittanceFactor * std::norm(a.tp);
        reflectance += 0.5 * (std::norm(a.rs) + std::norm(a.rp)) / kSpectrumSamples;
        transmittanceSqr += weight[k] * 0.5 * (ts * ts + tp * tp) / kSpectrumSamples;
      }
      for (const FreeStandingFilm::Averages& r : results) {
        ASSERT_NEAR(r.reflectance[j], reflectance, 2e-4) << i << " cos " << cosines[j];
        ASSERT_NEAR(r.weightedTransmittanceSqr[j], transmittanceSqr, 2e-4) << i << " cos " << cosines[j];
      }
    }
  }
}
