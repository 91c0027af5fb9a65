// Micro-benchmarks of the barbule BSDF: eval, pdf and sample calls per second with the reference
// scenes' parameters, and the thin-film evaluation they are built on. This file holds the
// benchmark binary's main().
#include <benchmark/benchmark.h>

#include <vector>
#include "bsdfs/barbulearms.h"
#include "bsdfs/barbulebsdf.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "optics/thin_film.h"

using namespace columba;

namespace {

struct Query {
  Vec3 wi, wo;
  Wavelengths wl;
  float uComponent;
  Vec2 u;
};

// Directions above the vane, cosine-distributed, and wavelengths as a path draws them.
const std::vector<Query>& queries() {
  static const std::vector<Query> all = [] {
    std::vector<Query> q(4096);
    PCG32 rng(42);
    for (Query& x : q) {
      x.wi = sampleCosineHemisphere({rng.nextFloat(), rng.nextFloat()});
      x.wo = sampleCosineHemisphere({rng.nextFloat(), rng.nextFloat()});
      x.wl = Wavelengths::sample(rng.nextFloat(), WavelengthDensity::RGBMatching);
      x.uComponent = rng.nextFloat();
      x.u = {rng.nextFloat(), rng.nextFloat()};
    }
    return q;
  }();
  return all;
}

// The reference scenes' barbule; `exponent` above 2 makes its cross-section a superellipse.
BarbuleBSDF referenceBSDF(BarbuleBSDF::Role role, float exponent = 2.0f) {
  BarbuleParameters p;
  p.height = 0.58f;
  p.profileExponent = exponent;
  return BarbuleBSDF(p, role);
}

// eval, and sample, on the queries in turn.
void timeEval(benchmark::State& state, const BSDF& bsdf, const BSDFContext& ctx = {}) {
  const std::vector<Query>& q = queries();
  size_t i = 0;
  for (auto _ : state) {
    const Query& x = q[i++ & 4095];
    benchmark::DoNotOptimize(bsdf.eval(ctx, x.wi, x.wo, x.wl));
  }
  state.SetItemsProcessed(state.iterations());
}
void timeSample(benchmark::State& state, const BSDF& bsdf) {
  const std::vector<Query>& q = queries();
  BSDFContext ctx;
  size_t i = 0;
  for (auto _ : state) {
    const Query& x = q[i++ & 4095];
    benchmark::DoNotOptimize(bsdf.sample(ctx, x.wi, x.wl, x.uComponent, x.u));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_BarbuleEval(benchmark::State& state) { timeEval(state, referenceBSDF(BarbuleBSDF::Role(state.range(0)))); }
BENCHMARK(BM_BarbuleEval)->Arg(int(BarbuleBSDF::Role::CameraIncident))->Arg(int(BarbuleBSDF::Role::LightIncident));

void BM_BarbulePdf(benchmark::State& state) {
  BarbuleBSDF bsdf = referenceBSDF(BarbuleBSDF::Role::CameraIncident);
  const std::vector<Query>& q = queries();
  BSDFContext ctx;
  size_t i = 0;
  for (auto _ : state) {
    const Query& x = q[i++ & 4095];
    benchmark::DoNotOptimize(bsdf.pdf(ctx, x.wi, x.wo, x.wl));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BarbulePdf);

void BM_BarbuleSample(benchmark::State& state) { timeSample(state, referenceBSDF(BarbuleBSDF::Role::CameraIncident)); }
BENCHMARK(BM_BarbuleSample);

// Evaluation and sampling with a superellipse cross-section of exponent state.range(0) (2: the
// ellipse's closed forms), whose ray points and masking tangents are solved numerically.
void BM_BarbuleEvalProfile(benchmark::State& state) {
  timeEval(state, referenceBSDF(BarbuleBSDF::Role::CameraIncident, float(state.range(0))));
}
BENCHMARK(BM_BarbuleEvalProfile)->Arg(2)->Arg(4)->Arg(8);

void BM_BarbuleSampleProfile(benchmark::State& state) {
  timeSample(state, referenceBSDF(BarbuleBSDF::Role::CameraIncident, float(state.range(0))));
}
BENCHMARK(BM_BarbuleSampleProfile)->Arg(2)->Arg(4)->Arg(8);

// Evaluation with per-point overrides, as on a feather with per-vertex H, mu and height.
void BM_BarbuleEvalOverrides(benchmark::State& state) {
  BarbuleBSDF bsdf = referenceBSDF(BarbuleBSDF::Role::CameraIncident);
  SurfaceAttributes point;
  point.set(kBarbuleSpacingAttribute, 1.4f);
  point.set(kBarbuleTiltAttribute, -0.3f);
  point.set(kCortexThicknessAttribute, 0.62f);
  timeEval(state, bsdf, BSDFContext{TexturePoint(Vec2(), &point), Vec3(), Vec3()});
}
BENCHMARK(BM_BarbuleEvalOverrides);

// Barbules of three arms (a roof at the parotia's angles, semi-axis 0.1, exponent 4), packed at
// contact or (sample's argument) spaced H apart, so that light also passes between them: eval,
// sample, and the pass-through, which follows lines across a period.
BarbuleArmsBSDF roofBSDF(double H = 0.0) {
  BarbuleParameters film;
  film.height = 0.58f;
  film.profileExponent = 4.0f;
  const double degree = kPiDouble / 180.0;
  return BarbuleArmsBSDF(ArmedCrossSection({-30.0 * degree, 0.0, 30.0 * degree}, 0.1, 4.0, 0.0, H), film);
}
void BM_BarbuleArmsEval(benchmark::State& state) { timeEval(state, roofBSDF()); }
BENCHMARK(BM_BarbuleArmsEval);
void BM_BarbuleArmsSample(benchmark::State& state) { timeSample(state, roofBSDF(double(state.range(0)))); }
BENCHMARK(BM_BarbuleArmsSample)->Arg(0)->Arg(7);
void BM_BarbuleArmsPassThrough(benchmark::State& state) {
  const BarbuleArmsBSDF bsdf = roofBSDF();
  const std::vector<Query>& q = queries();
  size_t i = 0;
  for (auto _ : state) {
    const Query& x = q[i++ & 4095];
    benchmark::DoNotOptimize(bsdf.passThrough({}, x.wi, x.wl));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BarbuleArmsPassThrough);

void BM_FreeStandingFilm(benchmark::State& state) {
  const std::vector<Query>& q = queries();
  FreeStandingFilm film(RefractiveIndex::keratin(), 1.000277f, 0.58f, q[0].wl);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(film.reflectance(q[i++ & 4095].wi.z));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FreeStandingFilm);

}  // namespace

BENCHMARK_MAIN();
