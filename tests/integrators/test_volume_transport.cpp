// Ratio tracking through a grid medium is unbiased: its mean is the closed-form transmittance of a
// linear ramp of extinction, for one wavelength and for four whose extinctions differ.
#include <gtest/gtest.h>

#include <cmath>

#include "integrators/volume_transport.h"
#include "media/grid_volume.h"
#include "media/heterogeneous_medium.h"
#include "media/isotropic_phase.h"

using namespace columba;

namespace {

// A grid of `n` voxels along x whose extinction rises linearly, `slope` times x at the voxels'
// centres (one voxel across y and z).
std::shared_ptr<GridVolume> ramp(int n, float slope) {
  VolumeGrid grid;
  grid.xres = n;
  grid.yres = grid.zres = grid.channels = 1;
  for (int i = 0; i < n; ++i) grid.values.push_back(slope * (float(i) + 0.5f) / float(n));
  return std::make_shared<GridVolume>(grid, GridVolume::Filter::Trilinear, GridVolume::Wrap::Clamp, Transform());
}

// The optical depth of that ramp from x = 0 to x = 1, times `scale`: linear between the centres,
// constant beyond the outer ones (the grid's edge values hold).
double rampDepth(int n, float slope, double scale) {
  const double h = 1.0 / n, first = slope * 0.5 * h, last = slope * (1.0 - 0.5 * h);
  return scale * (first * 0.5 * h + 0.5 * (first + last) * (1.0 - h) + last * 0.5 * h);
}

// Mean and standard error of T / mean(rL), ratio tracking's estimate, along the ramp's x axis.
struct Estimate {
  Spectrum mean, error;
};
Estimate meanRatioTracking(const Medium& medium, const Wavelengths& wl, int runs) {
  PCG32 rng(17);
  const Ray ray{Vec3(-1.0f, 0.5f, 0.5f), Vec3(3.0f, 0.0f, 0.0f), 0.0f, 1.0f};  // through x = 0 .. 1, d not unit
  Spectrum sum(0.0f), sumSquares(0.0f);
  for (int i = 0; i < runs; ++i) {
    TrackedTransmittance tr;
    ratioTrack(medium, ray, wl, rng, tr);
    const Spectrum estimate = tr.T / tr.rL.average();
    sum += estimate;
    sumSquares += estimate * estimate;
  }
  Estimate e;
  e.mean = sum / float(runs);
  const Spectrum variance = sumSquares / float(runs) - e.mean * e.mean;
  for (int k = 0; k < kSpectrumSamples; ++k) e.error[k] = std::sqrt(std::max(variance[k], 0.0f) / float(runs));
  return e;
}

}  // namespace

TEST(RatioTracking, IsUnbiasedThroughALinearRampOfExtinction) {
  const int n = 32;
  const float slope = 4.0f, scale = 1.5f;
  HeterogeneousMedium medium(ramp(n, slope), ramp(n, 1.0f), scale, std::make_shared<IsotropicPhase>());
  const Estimate e = meanRatioTracking(medium, Wavelengths::fixed({500, 550, 600, 650}), 100000);
  const double expected = std::exp(-rampDepth(n, slope, scale));  // about exp(-3)
  for (int k = 0; k < kSpectrumSamples; ++k) {
    EXPECT_NEAR(e.mean[k], expected, 4.0 * e.error[k] + 1e-4) << k;
    EXPECT_LT(e.error[k], 0.02 * expected);
  }
}

TEST(RatioTracking, IsUnbiasedInEveryLaneWhereExtinctionVariesWithTheWavelength) {
  // A three-channel grid whose colour gives each wavelength another extinction.
  const int n = 16;
  VolumeGrid grid;
  grid.xres = n;
  grid.yres = grid.zres = 1;
  grid.channels = 3;
  for (int i = 0; i < n; ++i)
    for (float c : {2.0f, 0.5f, 1.0f}) grid.values.push_back(c * (float(i) + 0.5f) / float(n));
  auto sigmaT = std::make_shared<GridVolume>(grid, GridVolume::Filter::Trilinear, GridVolume::Wrap::Clamp, Transform());
  HeterogeneousMedium medium(sigmaT, sigmaT, 1.0f, std::make_shared<IsotropicPhase>());
  const Wavelengths wl = Wavelengths::fixed({450, 520, 610, 680});
  const Estimate e = meanRatioTracking(medium, wl, 100000);
  for (int k = 0; k < kSpectrumSamples; ++k) {
    // Each voxel's spectrum at this wavelength, interpolated linearly as a ramp is.
    const float top = fitRGBSpectrum(Vec3(2.0f, 0.5f, 1.0f) * (float(n) - 0.5f) / float(n), true).eval(wl[k]);
    const double expected = std::exp(-rampDepth(n, top / ((float(n) - 0.5f) / float(n)), 1.0));
    EXPECT_NEAR(e.mean[k], expected, 4.0 * e.error[k] + 1e-4) << "lane " << k << " at " << wl[k] << " nm";
  }
}

// One voxel of 1e30 in an otherwise thin grid raises the majorant only in the cells it reaches: a
// ray through the thin voxels alone is tracked at their own majorant (it used to walk some 1e30
// null collisions, cut after kMostTentativeCollisions), and one into the dense voxel ends there.
TEST(RatioTracking, AHugeVoxelRaisesTheMajorantOnlyNearItself) {
  VolumeGrid grid;
  grid.xres = 4;
  grid.yres = grid.zres = grid.channels = 1;
  grid.values = {0.1f, 0.1f, 0.1f, 1e30f};
  auto sigmaT = std::make_shared<GridVolume>(grid, GridVolume::Filter::Nearest, GridVolume::Wrap::Clamp, Transform());
  HeterogeneousMedium medium(sigmaT, sigmaT, 1.0f, std::make_shared<IsotropicPhase>());
  PCG32 rng(3);
  // Through the thin voxels only (x from 0 to 0.7): transmittance exp(-0.07).
  const Wavelengths wl = Wavelengths::fixed({500, 550, 600, 650});
  double sum = 0.0;
  const int runs = 10000;
  for (int i = 0; i < runs; ++i) {
    TrackedTransmittance tr;
    ratioTrack(medium, Ray{Vec3(-1.0f, 0.5f, 0.5f), Vec3(1.0f, 0.0f, 0.0f), 1.0f, 1.7f}, wl, rng, tr);
    sum += tr.T[0] / tr.rL.average();
  }
  EXPECT_NEAR(sum / runs, std::exp(-0.07), 0.005);
  TrackedTransmittance through;
  ratioTrack(medium, Ray{Vec3(-1.0f, 0.5f, 0.5f), Vec3(1.0f, 0.0f, 0.0f), 1.0f, 2.9f}, wl, rng, through);
  EXPECT_TRUE(through.T.isZero());
}
