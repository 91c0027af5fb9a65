// Smooth spectra for RGB colours: a fit per colour (what a scene's colours and a bitmap's distinct
// texels get) against a lookup in the table of fits (what an environment map's pixels and a grid's
// voxels get), per colour, on the same random colours.
#include <benchmark/benchmark.h>

#include <vector>
#include "core/rgb_spectrum_table.h"
#include "core/rng.h"
#include "core/spectrum.h"

using namespace columba;

namespace {
const std::vector<Vec3>& colours() {
  static const std::vector<Vec3> all = [] {
    std::vector<Vec3> c(1024);
    PCG32 rng(9);
    for (Vec3& x : c) x = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    return c;
  }();
  return all;
}
}  // namespace

static void BM_FitPerColour(benchmark::State& state) {
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(fitRGBSpectrum(colours()[i++ % colours().size()], false));
}
BENCHMARK(BM_FitPerColour);

static void BM_TableLookupPerColour(benchmark::State& state) {
  benchmark::DoNotOptimize(tabulatedRGBSpectrum(Vec3(1, 1, 1)));  // the table is built before timing
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(tabulatedRGBSpectrum(colours()[i++ % colours().size()]));
}
BENCHMARK(BM_TableLookupPerColour);
