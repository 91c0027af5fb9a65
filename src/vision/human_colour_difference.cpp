#include "vision/human_colour_difference.h"

#include <lcms2.h>

#include <stdexcept>

#include "core/spectrum.h"

namespace columba {

namespace {
cmsCIELab toLcms(const CIELab& c) { return {c.L, c.a, c.b}; }
}  // namespace

CIELab labFromXYZ(const Vec3& xyz, const Vec3& white) {
  const cmsCIEXYZ colour{xyz.x, xyz.y, xyz.z}, reference{white.x, white.y, white.z};
  cmsCIELab lab;
  cmsXYZ2Lab(&reference, &lab, &colour);
  return {lab.L, lab.a, lab.b};
}

Vec3 reflectanceXYZ(const SpectralGrid& grid, const std::vector<float>& reflectance,
                    const std::vector<float>& illuminant) {
  double x = 0.0, y = 0.0, z = 0.0, white = 0.0;
  for (size_t i = 0; i < grid.count; ++i) {
    const Vec3 cmf = cieXYZ(float(grid.wavelength(i)));
    const double e = illuminant[i], re = double(reflectance[i]) * e;
    x += re * cmf.x, y += re * cmf.y, z += re * cmf.z;
    white += e * cmf.y;
  }
  if (!(white > 0.0))
    throw std::invalid_argument("the illuminant has no light the CIE 1931 observer sees (a white's Y under it is 0)");
  return Vec3(float(x / white), float(y / white), float(z / white));
}

CIELab labFromLinearRGB(const Vec3& rgb) {
  static const Vec3 white = linearRGBToXYZ(Vec3(1, 1, 1));
  return labFromXYZ(linearRGBToXYZ(rgb), white);
}

double deltaE2000(const CIELab& x, const CIELab& y) {
  const cmsCIELab a = toLcms(x), b = toLcms(y);
  return cmsCIE2000DeltaE(&a, &b, 1.0, 1.0, 1.0);
}

double deltaE1976(const CIELab& x, const CIELab& y) {
  const cmsCIELab a = toLcms(x), b = toLcms(y);
  return cmsDeltaE(&a, &b);
}

}  // namespace columba
