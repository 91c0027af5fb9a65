// Layered films by transfer matrices: a single film is the Airy film, lossless stacks conserve
// energy and lossy ones absorb what is missing, a quarter-wave stack reflects as its closed form
// says, a bare interface is Fresnel's, transmittance is the same from either side, and a run of
// layers raised to its power is the run written out.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <complex>

#include "core/rng.h"
#include "optics/multilayer.h"
#include "optics/thin_film.h"

using namespace columba;

namespace {
double keratin(double lambdaNm) { return 1.532 + 5890.0 / (lambdaNm * lambdaNm); }

LayerStack randomStack(PCG32& rng, bool lossy) {
  LayerStack stack;
  stack.incidentIndex = 1.0 + 0.6 * rng.nextFloat();
  const int count = 1 + int(rng.nextFloat() * 6.0f);
  for (int i = 0; i < count; ++i)
    stack.layers.push_back(
        {{1.0 + 1.2 * rng.nextFloat(), lossy ? 0.3 * rng.nextFloat() : 0.0}, 0.02 + 0.5 * rng.nextFloat()});
  stack.substrateIndex = 1.0 + 0.8 * rng.nextFloat();
  return stack;
}
}  // namespace

TEST(Multilayer, ASingleFilmIsTheAiryFilm) {
  for (double theta : {0.0, 0.3, 0.8, 1.3})
    for (double d : {0.1, 0.51, 0.6, 2.0})
      for (double lambda : {300.0, 410.0, 550.0, 700.0, 830.0}) {
        LayerStack stack{1.000277, {{keratin(lambda), d}}, 1.000277, {}};
        const MultilayerResponse r = multilayerResponse(stack, theta, lambda);
        const double c = std::cos(theta);
        EXPECT_NEAR(r.reflectance(), thinFilmReflectance(c, 1.000277, keratin(lambda), 1.000277, d, lambda), 1e-9)
            << theta << " " << d << " " << lambda;
        EXPECT_NEAR(r.transmittance(), thinFilmTransmittance(c, 1.000277, keratin(lambda), 1.000277, d, lambda), 1e-9);
        // On a substrate of another index too (keratin on melanin's real part).
        LayerStack onSubstrate{1.0, {{keratin(lambda), d}}, 1.7, {}};
        EXPECT_NEAR(multilayerResponse(onSubstrate, theta, lambda).reflectance(),
                    thinFilmReflectance(c, 1.0, keratin(lambda), 1.7, d, lambda), 1e-9);
      }
}

TEST(Multilayer, LosslessStacksConserveEnergyAndLossyOnesAbsorbTheRest) {
  PCG32 rng(5);
  for (int i = 0; i < 200; ++i) {
    const bool lossy = i % 2 == 1;
    const LayerStack stack = randomStack(rng, lossy);
    const double theta = 1.5 * rng.nextFloat(), lambda = 300.0 + 530.0 * rng.nextFloat();
    const MultilayerResponse r = multilayerResponse(stack, theta, lambda);
    if (!lossy) {
      EXPECT_NEAR(r.rs + r.ts, 1.0, 1e-10) << i;
      EXPECT_NEAR(r.rp + r.tp, 1.0, 1e-10) << i;
    } else {
      EXPECT_GE(r.absorptance(), -1e-12) << i;
      EXPECT_LE(r.absorptance(), 1.0) << i;
    }
  }
  // A thick absorbing layer (melanin-like, k = 0.2, 5 um) lets nothing through.
  LayerStack absorber{1.0, {{{1.7, 0.2}, 5.0}}, 1.5, {}};
  EXPECT_LT(multilayerResponse(absorber, 0.2, 500.0).transmittance(), 1e-9);
}

TEST(Multilayer, AQuarterWaveStackReflectsAsItsClosedFormSays) {
  // N pairs of quarter-wave layers (H next to the incident medium) on a substrate: at the design
  // wavelength and normal incidence the stack's admittance is (nH / nL)^(2N) nS, so
  // R = ((n0 - Y) / (n0 + Y))^2.
  const double lambda = 550.0, nH = 1.8, nL = 1.4, n0 = 1.0, nS = 1.52;
  for (int pairs : {1, 2, 5, 8}) {
    LayerStack stack{n0, {}, nS, {}};
    for (int k = 0; k < pairs; ++k) {
      stack.layers.push_back({nH, lambda / (4.0 * nH) / 1000.0});
      stack.layers.push_back({nL, lambda / (4.0 * nL) / 1000.0});
    }
    const double Y = std::pow(nH / nL, 2 * pairs) * nS;
    const double expected = std::pow((n0 - Y) / (n0 + Y), 2);
    const MultilayerResponse r = multilayerResponse(stack, 0.0, lambda);
    EXPECT_NEAR(r.rs, expected, 1e-12) << pairs;
    EXPECT_NEAR(r.rp, expected, 1e-12) << pairs;
    // The design wavelength is the reflection band's peak.
    EXPECT_GT(r.reflectance(), multilayerResponse(stack, 0.0, 500.0).reflectance());
    EXPECT_GT(r.reflectance(), multilayerResponse(stack, 0.0, 600.0).reflectance());
  }
}

TEST(Multilayer, ABareInterfaceIsFresnels) {
  const double n1 = 1.0, n2 = 1.56;
  for (double theta : {0.0, 0.5, 1.0, 1.4}) {
    const double c1 = std::cos(theta), c2 = std::sqrt(1.0 - std::pow(n1 / n2 * std::sin(theta), 2));
    const double rs = std::pow((n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2), 2);
    const double rp = std::pow((n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2), 2);
    const MultilayerResponse r = multilayerResponse({n1, {}, n2, {}}, theta, 500.0);
    EXPECT_NEAR(r.rs, rs, 1e-12) << theta;
    EXPECT_NEAR(r.rp, rp, 1e-12) << theta;
  }
  // Beyond the critical angle, inside the denser medium, everything is reflected.
  const MultilayerResponse total = multilayerResponse({1.56, {}, 1.0, {}}, 1.0, 500.0);
  EXPECT_NEAR(total.rs, 1.0, 1e-12);
  EXPECT_NEAR(total.rp, 1.0, 1e-12);
  EXPECT_EQ(total.ts, 0.0);
}

TEST(Multilayer, TransmittanceIsTheSameFromEitherSide) {
  // Reciprocity: T from the front equals T from the back at the angle that corresponds by Snell's
  // law, lossy layers included; for lossless stacks R is the same from both sides too.
  PCG32 rng(9);
  for (int i = 0; i < 100; ++i) {
    const bool lossy = i % 2 == 1;
    const LayerStack stack = randomStack(rng, lossy);
    const double theta = 0.6 * rng.nextFloat(), lambda = 300.0 + 530.0 * rng.nextFloat();
    const double sinBack = stack.incidentIndex * std::sin(theta) / stack.substrateIndex.real();
    if (sinBack >= 1.0) continue;
    const MultilayerResponse front = multilayerResponse(stack, theta, lambda);
    const MultilayerResponse back = multilayerResponse(reversed(stack), std::asin(sinBack), lambda);
    EXPECT_NEAR(front.ts, back.ts, 1e-10) << i;
    EXPECT_NEAR(front.tp, back.tp, 1e-10) << i;
    if (!lossy) {
      EXPECT_NEAR(front.reflectance(), back.reflectance(), 1e-10) << i;
    }
  }
}

TEST(Multilayer, BadLayersAreRefused) {
  EXPECT_THROW(multilayerResponse({1.0, {{1.5, -0.1}}, 1.0, {}}, 0.0, 500.0), std::invalid_argument);
  EXPECT_THROW(multilayerResponse({1.0, {{{1.5, -0.1}, 0.1}}, 1.0, {}}, 0.0, 500.0), std::invalid_argument);
  EXPECT_THROW(multilayerResponse({1.0, {}, {0.0, 1.0}, {}}, 0.0, 500.0), std::invalid_argument);
  EXPECT_THROW(reversed({1.0, {}, {1.5, 0.1}, {}}), std::invalid_argument);
}

// At 90 degrees the p admittance of the incident medium is infinite: R, T and A were NaN there.
// The limit is R = 1, T = 0, which angles just below approach; angles beyond [0, 90] degrees, NaN
// and wavelengths that are not positive and finite are refused, naming the value.
TEST(Multilayer, GrazingIncidenceIsTheLimitAndBadAnglesAndWavelengthsAreRefused) {
  const LayerStack film{1.0, {{{1.56, 0.0}, 0.2}, {{1.7, 0.3}, 0.1}}, {1.33, 0.0}, {}};
  const MultilayerResponse grazing = multilayerResponse(film, M_PI / 2, 500.0);
  EXPECT_EQ(grazing.rs, 1.0);
  EXPECT_EQ(grazing.rp, 1.0);
  EXPECT_EQ(grazing.transmittance(), 0.0);
  EXPECT_EQ(grazing.absorptance(), 0.0);
  const MultilayerResponse near = multilayerResponse(film, M_PI / 2 - 1e-6, 500.0);
  EXPECT_NEAR(near.reflectance(), 1.0, 1e-4);
  EXPECT_NEAR(near.transmittance(), 0.0, 1e-4);
  auto error = [&](double theta, double lambda) {
    try {
      multilayerResponse(film, theta, lambda);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(std::nan(""), 500.0), "the angle of incidence nan degrees lies outside [0, 90]");
  EXPECT_EQ(error(M_PI, 500.0), "the angle of incidence 180 degrees lies outside [0, 90]");
  EXPECT_EQ(error(-0.1, 500.0).substr(0, 25), "the angle of incidence -5");
  for (double lambda : {-500.0, 0.0, std::nan(""), double(INFINITY)})
    EXPECT_EQ(error(0.0, lambda), fmt::format("the wavelength {:g} nm is not positive and finite", lambda));
}

TEST(Multilayer, AThickAbsorberIsASemiInfiniteOne) {
  // 1.7 + 0.1i at normal incidence, 100 um to 10 cm thick: nothing gets through, and the stack
  // reflects as a bare interface with that medium, |(1 - n) / (1 + n)|^2 (once its matrices
  // overflowed into NaN beyond about 500 um).
  const std::complex<double> n(1.7, 0.1);
  const double bare = std::norm((1.0 - n) / (1.0 + n));
  for (double thickness : {100.0, 1000.0, 1e5}) {
    LayerStack stack;
    stack.layers = {{n, thickness}};
    const MultilayerResponse r = multilayerResponse(stack, 0.0, 500.0);
    EXPECT_NEAR(r.reflectance(), bare, 1e-12) << thickness;
    EXPECT_LT(r.transmittance(), 1e-100) << thickness;
    EXPECT_NEAR(r.absorptance(), 1.0 - bare, 1e-12) << thickness;
  }
}

TEST(Multilayer, ARunRaisedToItsPowerIsTheRunWrittenOut) {
  PCG32 rng(11);
  for (int i = 0; i < 200; ++i) {
    const bool lossy = i % 2 == 1;
    // Runs of 1 to 3 layers, each taken 1 to 40 times.
    LayerStack runs = randomStack(rng, lossy), flat = runs;
    runs.layers.clear();
    flat.layers.clear();
    const int runCount = 1 + int(rng.nextFloat() * 4.0f);
    for (int r = 0; r < runCount; ++r) {
      const size_t count = 1 + size_t(rng.nextFloat() * 3.0f);
      const int times = 1 + int(rng.nextFloat() * 40.0f);
      LayerStack part = randomStack(rng, lossy);
      part.layers.resize(std::min(count, part.layers.size()));
      runs.layers.insert(runs.layers.end(), part.layers.begin(), part.layers.end());
      runs.runs.push_back({part.layers.size(), times});
      for (int t = 0; t < times; ++t) flat.layers.insert(flat.layers.end(), part.layers.begin(), part.layers.end());
    }
    for (double theta : {0.0, 0.7, 1.3})
      for (double lambda : {380.0, 610.0}) {
        const MultilayerResponse a = multilayerResponse(runs, theta, lambda),
                                 b = multilayerResponse(flat, theta, lambda);
        EXPECT_NEAR(a.rs, b.rs, 1e-9) << i;
        EXPECT_NEAR(a.rp, b.rp, 1e-9) << i;
        EXPECT_NEAR(a.ts, b.ts, 1e-9) << i;
        EXPECT_NEAR(a.tp, b.tp, 1e-9) << i;
        // T relative to its size (lossy stacks transmit little), and from the other side too.
        EXPECT_NEAR(a.transmittance(), b.transmittance(), 1e-9 * b.transmittance() + 1e-300) << i;
        if (runs.substrateIndex.imag() == 0.0) {
          const MultilayerResponse ra = multilayerResponse(reversed(runs), theta, lambda);
          const MultilayerResponse rb = multilayerResponse(reversed(flat), theta, lambda);
          EXPECT_NEAR(ra.reflectance(), rb.reflectance(), 1e-9) << i;
          EXPECT_NEAR(ra.transmittance(), rb.transmittance(), 1e-9 * rb.transmittance() + 1e-300) << i;
        }
      }
  }
  // Runs must cover the layers, each taken at least once.
  LayerStack bad{1.0, {{1.5, 0.1}, {1.3, 0.2}}, 1.0, {{1, 3}}};
  EXPECT_THROW(multilayerResponse(bad, 0.0, 500.0), std::invalid_argument);
  bad.runs = {{2, 0}};
  EXPECT_THROW(multilayerResponse(bad, 0.0, 500.0), std::invalid_argument);
  bad.runs = {{2, 5}};
  EXPECT_NO_THROW(multilayerResponse(bad, 0.0, 500.0));
}

TEST(Multilayer, DeepStacksStayFiniteAtEveryAngle) {
  // Many periods deep in a band gap at grazing incidence, the matrices' entries grow as a power of
  // the periods (here past 1e308), and thousands of absorbing layers shrink them as one: the
  // products are rescaled, so R stays a number and a lossless stack still conserves energy.
  LayerStack gap{1.0, {{1.0, 1.05}, {1.8, 0.2}}, 1.0, {{2, 3000}}};
  LayerStack absorbers{1.0, {{{1.7, 0.1}, 10.0}}, 1.0, {{1, 4000}}};
  for (double theta : {0.0, 1.0, 1.5607, 1.5697})  // 1.5697: cos 0.001
    for (double lambda : {310.0, 450.0, 820.0}) {
      const MultilayerResponse g = multilayerResponse(gap, theta, lambda);
      EXPECT_TRUE(std::isfinite(g.rs) && std::isfinite(g.rp)) << theta << " " << lambda;
      EXPECT_NEAR(g.reflectance() + g.transmittance(), 1.0, 1e-9) << theta << " " << lambda;
      const MultilayerResponse a = multilayerResponse(absorbers, theta, lambda);
      const MultilayerResponse bare = multilayerResponse({1.0, {{{1.7, 0.1}, 1e5}}, 1.0, {}}, theta, lambda);
      EXPECT_NEAR(a.reflectance(), bare.reflectance(), 1e-9) << theta << " " << lambda;
      EXPECT_EQ(a.transmittance(), 0.0);
    }
}
