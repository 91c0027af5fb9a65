#include "core/illuminant.h"

#include <algorithm>
#include <array>
#include "core/fast_math.h"
#include "core/spectrum.h"

namespace columba {

namespace {
// CIE standard illuminant D65, relative spectral power at 5 nm steps from 300 to 830 nm
// (CIE 15:2004, Colorimetry, Table T.1; 100 at 560 nm).
constexpr float kFirstNm = 300.0f, kStepNm = 5.0f;
constexpr std::array<float, 107> kD65 = {
    0.0341f,  1.6643f,  3.2945f,  11.7652f, 20.236f,  28.6447f, 37.0535f, 38.5011f, 39.9488f, 42.4302f,  // 300-345
    44.9117f, 45.775f,  46.6383f, 49.3637f, 52.0891f, 51.0323f, 49.9755f, 52.3118f, 54.6482f, 68.7015f,  // 350-395
    82.7549f, 87.1204f, 91.486f,  92.4589f, 93.4318f, 90.057f,  86.6823f, 95.7736f, 104.865f, 110.936f,  // 400-445
    117.008f, 117.41f,  117.812f, 116.336f, 114.861f, 115.392f, 115.923f, 112.367f, 108.811f, 109.082f,  // 450-495
    109.354f, 108.578f, 107.802f, 106.296f, 104.79f,  106.239f, 107.689f, 106.047f, 104.405f, 104.225f,  // 500-545
    104.046f, 102.023f, 100.0f,   98.1671f, 96.3342f, 96.0611f, 95.788f,  92.2368f, 88.6856f, 89.3459f,  // 550-595
    90.0062f, 89.8026f, 89.5991f, 88.6489f, 87.6987f, 85.4936f, 83.2886f, 83.4939f, 83.6992f, 81.863f,   // 600-645
    80.0268f, 80.1207f, 80.2146f, 81.2462f, 82.2778f, 80.281f,  78.2842f, 74.0027f, 69.7213f, 70.6652f,  // 650-695
    71.6091f, 72.979f,  74.349f,  67.9765f, 61.604f,  65.7448f, 69.8856f, 72.4863f, 75.087f,  69.3398f,  // 700-745
    63.5927f, 55.0054f, 46.4182f, 56.6118f, 66.8054f, 65.0941f, 63.3828f, 63.8434f, 64.304f,  61.8779f,  // 750-795
    59.4519f, 55.7054f, 51.959f,  54.6998f, 57.4406f, 58.8765f, 60.3125f};                               // 800-830

// Linear interpolation of the table at four wavelengths, one per lane.
FloatLanes relativeD65(FloatLanes lambda) {
  const FloatLanes x = clampLanes((lambda - kFirstNm) / kStepNm, 0.0f, float(kD65.size() - 1));
  FloatLanes below, above, f;
  for (int k = 0; k < kLaneCount; ++k) {
    int i = std::min(int(x[k]), int(kD65.size()) - 2);
    below[k] = kD65[i];
    above[k] = kD65[i + 1];
    f[k] = x[k] - float(i);
  }
  return below * (1.0f - f) + above * f;
}
float relativeD65(float lambda) { return relativeD65(lambda + FloatLanes{})[0]; }

// 1 / luminance of the tabulated D65, on the 1 nm grid the colour matching functions are integrated on.
float inverseLuminance() {
  static const float scale = [] {
    double y = 0.0, yBar = 0.0;
    for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) {
      y += double(relativeD65(l)) * cieXYZ(l).y;
      yBar += cieXYZ(l).y;
    }
    return float(yBar / y);
  }();
  return scale;
}
}  // namespace

float d65(float lambda) { return relativeD65(lambda) * inverseLuminance(); }

Spectrum d65(const Wavelengths& wl) {
  return Spectrum(relativeD65(FloatLanes{wl[0], wl[1], wl[2], wl[3]}) * inverseLuminance());
}

}  // namespace columba
