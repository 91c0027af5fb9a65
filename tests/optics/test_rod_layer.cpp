// Rows of rods (melanosomes) as effective layers (optics/rod_layer.h) and the layer text that
// writes them (optics/film_layer_text.h): the slices hold the cylinders' volume exactly, rods of
// the matrix's own index are the matrix, each slice's permittivity is the volume average, and the
// reflectance of a stack of rows has converged at the default slicing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include "core/math.h"
#include "optics/film_layer_text.h"
#include "optics/multilayer.h"
#include "optics/rod_layer.h"

using namespace columba;

namespace {

// `layers` between air above and below, at one wavelength.
LayerStack inAir(const std::vector<FilmLayer>& layers, float lambdaNm) {
  LayerStack stack;
  for (const FilmLayer& layer : layers) stack.layers.push_back({layer.index(lambdaNm), layer.thicknessUm});
  return stack;
}

// Every layer of `stack`, its repeats written out (each run's layers taken its count of times).
std::vector<FilmLayer> expanded(const FilmStack& stack) {
  if (stack.runs.empty()) return stack.layers;
  std::vector<FilmLayer> all;
  auto first = stack.layers.begin();
  for (const LayerRun& run : stack.runs) {
    for (int k = 0; k < run.times; ++k) all.insert(all.end(), first, first + std::ptrdiff_t(run.count));
    first += std::ptrdiff_t(run.count);
  }
  return all;
}

double reflectance(const std::vector<FilmLayer>& layers, float lambdaNm, double theta) {
  const MultilayerResponse r = multilayerResponse(inAir(layers, lambdaNm), theta, lambdaNm);
  return 0.5 * (r.rs + r.rp);
}

// Nine rows of melanin rods with keratin between (dimensions chosen for this test, not measured on
// a bird), written out in full with `slices` slices a row.
std::vector<FilmLayer> nineRows(int slices) {
  std::vector<FilmLayer> layers;
  FilmLayer gap;
  gap.material.n = RefractiveIndex::keratin();
  gap.thicknessUm = 0.04f;
  for (int row = 0; row < 9; ++row) {
    const std::vector<FilmLayer> rods =
        rodRow(melanin(), LayerMaterial{RefractiveIndex::keratin()}, 0.11f, 0.15f, slices);
    layers.insert(layers.end(), rods.begin(), rods.end());
    layers.push_back(gap);
  }
  return layers;
}

}  // namespace

TEST(RodRow, ItsSlicesHoldTheCylindersVolume) {
  for (double diameter : {0.05, 0.11, 0.3})
    for (double spacing : {diameter, 1.4 * diameter, 4.0 * diameter})
      for (int slices : {1, 3, 16, 101}) {
        const std::vector<FilmLayer> row = rodRow(melanin(), LayerMaterial{}, float(diameter), float(spacing), slices);
        ASSERT_EQ(row.size(), size_t(slices));
        double volume = 0.0, thickness = 0.0;
        for (const FilmLayer& slice : row) {
          EXPECT_GE(slice.fraction, 0.0f);
          EXPECT_LE(slice.fraction, float(diameter / spacing) * (1.0f + 1e-6f));
          volume += double(slice.fraction) * slice.thicknessUm;
          thickness += slice.thicknessUm;
        }
        // Per unit length of the row: the cylinder's cross-section over its spacing.
        EXPECT_NEAR(volume, kPiDouble * diameter * diameter / (4.0 * spacing), 2e-6 * diameter);
        EXPECT_NEAR(thickness, diameter, 1e-6 * diameter);
      }
  // The middle of a touching row is all rod, its top and bottom edges all matrix.
  EXPECT_NEAR(rodRowFraction(0.1, 0.1, 0.049999, 0.050001), 1.0, 1e-6);
  EXPECT_NEAR(rodRowFraction(0.1, 0.1, 0.0, 1e-9), 0.0, 1e-3);
}

TEST(RodRow, RodsOfTheMatrixIndexAreTheMatrix) {
  const LayerMaterial keratin{RefractiveIndex::keratin()};
  std::vector<FilmLayer> homogeneous(1);
  homogeneous[0].material = keratin;
  homogeneous[0].thicknessUm = 0.13f;
  const std::vector<FilmLayer> row = rodRow(keratin, keratin, 0.13f, 0.2f);
  for (float lambda : {320.0f, 550.0f, 800.0f})
    for (double theta : {0.0, 0.6, 1.2})
      EXPECT_NEAR(reflectance(row, lambda, theta), reflectance(homogeneous, lambda, theta), 1e-7)
          << lambda << " nm, " << theta;
}

TEST(RodRow, ASlicesPermittivityIsTheVolumeAverage) {
  FilmLayer layer;
  layer.material = melanin();
  layer.matrix.n = RefractiveIndex::constant(1.0f);  // air
  layer.fraction = 0.3f;
  for (float lambda : {350.0f, 600.0f}) {
    const std::complex<double> a = melanin().index(lambda);
    const std::complex<double> n = layer.index(lambda);
    const std::complex<double> expected = 0.3 * a * a + 0.7 * 1.0;
    EXPECT_NEAR(std::abs(n * n - expected), 0.0, 1e-6 * std::abs(expected));
    EXPECT_GT(n.real(), 0.0);
    EXPECT_GE(n.imag(), 0.0);  // absorbing, not amplifying
  }
  // A whole layer of one material is that material, bit for bit.
  layer.fraction = 1.0f;
  EXPECT_EQ(layer.index(450.0f), melanin().index(450.0f));
}

TEST(RodRow, TheDefaultSlicingHasConverged) {
  const std::vector<FilmLayer> fine = nineRows(1024), coarse = nineRows(kRodRowSlices);
  double largest = 0.0;
  for (float lambda = 300.0f; lambda <= 830.0f; lambda += 10.0f)
    for (double theta : {0.0, 0.5, 1.0, 1.4})
      largest = std::max(largest, std::abs(reflectance(coarse, lambda, theta) - reflectance(fine, lambda, theta)));
  // Measured 1.9e-3 at 16 slices (7.4e-3 at 8, 8.7e-4 at 24: about 0.47 / slices^2).
  EXPECT_LT(largest, 2.5e-3) << "largest difference in R over 300-830 nm and four angles";
  // A stack of rows reflects strongly somewhere in the visible: it is no homogeneous film.
  double peak = 0.0;
  for (float lambda = 380.0f; lambda <= 700.0f; lambda += 2.0f) peak = std::max(peak, reflectance(coarse, lambda, 0.0));
  EXPECT_GT(peak, 0.2);  // measured 0.28
}

TEST(FilmLayerText, RepeatsAndRowsExpandToTheirLayers) {
  const std::vector<FilmLayer> repeated = expanded(parseFilmLayers("[melanin:0.2, keratin:0.15] x 3, air:0.1"));
  const std::vector<FilmLayer> written =
      parseFilmLayers("melanin:0.2, keratin:0.15, melanin:0.2, keratin:0.15, melanin:0.2, keratin:0.15, air:0.1")
          .layers;
  ASSERT_EQ(repeated.size(), written.size());
  for (size_t i = 0; i < written.size(); ++i) {
    EXPECT_EQ(repeated[i].thicknessUm, written[i].thicknessUm);
    EXPECT_EQ(repeated[i].index(500.0f), written[i].index(500.0f)) << i;
  }
  const std::vector<FilmLayer> rows = expanded(parseFilmLayers("[rods(melanin, 0.11, 0.15), keratin:0.04] x 9"));
  const std::vector<FilmLayer> direct = nineRows(kRodRowSlices);
  ASSERT_EQ(rows.size(), direct.size());
  for (size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i].index(430.0f), direct[i].index(430.0f)) << i;
  // Repeats within repeats.
  const std::vector<FilmLayer> nested = expanded(parseFilmLayers("[[melanin:0.2, air:0.05] x 2, keratin:0.1] x 3"));
  const std::vector<FilmLayer> out =
      parseFilmLayers(
          "melanin:0.2, air:0.05, melanin:0.2, air:0.05, keratin:0.1, melanin:0.2, air:0.05, melanin:0.2, air:0.05, "
          "keratin:0.1, melanin:0.2, air:0.05, melanin:0.2, air:0.05, keratin:0.1")
          .layers;
  ASSERT_EQ(nested.size(), out.size());
  for (size_t i = 0; i < out.size(); ++i) EXPECT_EQ(nested[i].index(500.0f), out[i].index(500.0f)) << i;
  // A stack without repeats keeps no runs; one with them lists each repeated part once.
  EXPECT_TRUE(parseFilmLayers("melanin:0.2, air:0.05").runs.empty());
  const FilmStack rowsStack = parseFilmLayers("[rods(melanin, 0.11, 0.15), keratin:0.04] x 9");
  EXPECT_EQ(rowsStack.layers.size(), size_t(kRodRowSlices + 1));
  ASSERT_EQ(rowsStack.runs.size(), 1u);
  EXPECT_EQ(rowsStack.runs[0].times, 9);
  const FilmStack twice = parseFilmLayers("[[melanin:0.2, air:0.05] x 2] x 3");  // one run of six
  ASSERT_EQ(twice.runs.size(), 1u);
  EXPECT_EQ(twice.runs[0].times, 6);
  EXPECT_EQ(parseFilmLayers(" keratin:0.1\n,\tair:0.2\r\n").layers.size(), 2u);  // any white space
  // A matrix of its own: air channels in melanin.
  const std::vector<FilmLayer> channels = parseFilmLayers("rods(air, 0.05, 0.1, melanin)").layers;
  ASSERT_EQ(channels.size(), size_t(kRodRowSlices));
  EXPECT_EQ(channels[0].matrix.index(500.0f), melanin().index(500.0f));
}

TEST(FilmLayerText, RefusesWhatItCannotRead) {
  for (const char* bad :
       {"rods(melanin, 0.2, 0.1)", "rods(melanin, 0.1)", "rods(melanin, 0.1, 0.2, keratin, 3)",
        "rods(melanin, -0.1, 0.2)", "rods(unobtainium, 0.1, 0.2)", "rods(melanin, 0.1, 0.2", "[melanin:0.1 x 2",
        "melanin:0.1] x 2", "[melanin:0.1] x 0", "[melanin:0.1] x 1001", "[melanin:0.1] 3", "[melanin:0.1] x 2.5", "",
        "melanin:0.1,, keratin:0.1", "1e30:0.1", "1.5+101i:0.1", "rods(1000, 0.1, 0.2)"}) {
    EXPECT_THROW(parseFilmLayers(bad), std::invalid_argument) << bad;
  }
  // Memory stays bounded: a stack may not grow past kMaxFilmLayers, however the repeats nest.
  try {
    parseFilmLayers("[[[keratin:0.1] x 1000] x 1000] x 1000");
    ADD_FAILURE() << "a billion layers were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(kMaxFilmLayers)), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(parseFilmLayers("[[[[[[[[keratin:0.1] x 1] x 1] x 1] x 1] x 1] x 1] x 1] x 1"));  // 8 deep
  EXPECT_THROW(parseFilmLayers("[[[[[[[[[keratin:0.1] x 1] x 1] x 1] x 1] x 1] x 1] x 1] x 1] x 1"),
               std::invalid_argument);  // 9
  // Messages quote at most 60 characters of what they name.
  try {
    parseFilmLayers(std::string(5000, '[') + "keratin:0.1");
  } catch (const std::invalid_argument& e) {
    EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
  }
  EXPECT_EQ(parseFilmLayers("keratin:0.1,").layers.size(), 1u);  // a trailing comma, as before
}

TEST(FilmLayerText, ARepeatingStacksFilmIsItsLayersWrittenOut) {
  // The film of a keratin cortex over a stack that keeps its repeats (the cortex prepended as a
  // run of its own) against the same stack written out layer by layer.
  const Wavelengths wl = Wavelengths::fixed({330.0f, 480.0f, 610.0f, 790.0f});
  for (const char* text : {"[rods(melanin, 0.11, 0.15), keratin:0.04] x 9", "air:0.1, [melanin:0.08, keratin:0.1] x 5",
                           "[[melanin:0.2, air:0.05] x 2, keratin:0.1] x 3, air:0.2"}) {
    const FilmStack repeating = parseFilmLayers(text);
    const FilmStack written{expanded(repeating), {}};
    const LayeredFilm a(RefractiveIndex::keratin(), 1.000277f, 0.6f, repeating, wl);
    const LayeredFilm b(RefractiveIndex::keratin(), 1.000277f, 0.6f, written, wl);
    for (float cosine : {1.0f, 0.6f, 0.1f}) {
      const FreeStandingFilm::Reflectance ra = a.reflectance(cosine), rb = b.reflectance(cosine);
      const Spectrum ta = a.transmittanceProduct(cosine, 0.8f), tb = b.transmittanceProduct(cosine, 0.8f);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        EXPECT_NEAR(ra.s[k], rb.s[k], 1e-6f) << text;
        EXPECT_NEAR(ra.p[k], rb.p[k], 1e-6f) << text;
        EXPECT_NEAR(ta[k], tb[k], 1e-6f * (tb[k] + 1e-30f)) << text;
      }
    }
  }
}
