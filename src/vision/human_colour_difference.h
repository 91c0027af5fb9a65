#pragma once
// Colour differences for a human observer: CIELAB (CIE 15:2004) with D65 as the white, and the
// CIEDE2000 difference (CIE 142-2001; Sharma, Wu & Dalal 2005, Color Res Appl 30:21-30), both
// computed by Little CMS. They stand where the receptor-noise model stands for birds; pavo does
// the same for its human observers (docs/vision.md).
#include <vector>

#include "core/vector.h"
#include "vision/spectral_grid.h"

namespace columba {

struct CIELab {
  double L = 0.0, a = 0.0, b = 0.0;
};

// CIE XYZ in CIELAB relative to the reference white `white` (L* = 100 there).
CIELab labFromXYZ(const Vec3& xyz, const Vec3& white);

// The CIE 1931 XYZ of a reflectance spectrum under an illuminant, both on `grid`, scaled so that a
// perfect white reflector has Y = 1: X = sum R E xbar / sum E ybar, and so on. Throws
// std::invalid_argument for an illuminant without light where ybar is positive (Y undefined).
Vec3 reflectanceXYZ(const SpectralGrid& grid, const std::vector<float>& reflectance,
                    const std::vector<float>& illuminant);

// A linear Rec. 709 RGB colour (Columba's RGB: D65 is (1, 1, 1)) in CIELAB with RGB (1, 1, 1)
// as the reference white, L* = 100.
CIELab labFromLinearRGB(const Vec3& rgb);

// The CIEDE2000 difference, parametric factors kL = kC = kH = 1.
double deltaE2000(const CIELab& x, const CIELab& y);
// The CIE 1976 difference: the Euclidean distance in CIELAB.
double deltaE1976(const CIELab& x, const CIELab& y);

// About one just noticeable difference in CIE 1976 units: Mahy, Van Eycken & Oosterlinck (1994,
// Color Res Appl 19:105-121), as cited by Sharma (2003, Digital Color Imaging Handbook).
constexpr double kJustNoticeableDeltaE1976 = 2.3;

}  // namespace columba
