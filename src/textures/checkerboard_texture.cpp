#include "textures/checkerboard_texture.h"

#include <cmath>

namespace columba {

bool CheckerboardTexture::inFirstColour(Vec2 uv) const {
  const Vec2 st = applyToUV(toUV_, uv);
  const bool upperU = st.x - std::floor(st.x) > 0.5f, upperV = st.y - std::floor(st.y) > 0.5f;
  return upperU == upperV;
}

Spectrum CheckerboardTexture::evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const {
  return inFirstColour(p.uv) ? color0_.eval(p, wl) : color1_.eval(p, wl);
}

float CheckerboardTexture::evalFloat(const TexturePoint& p) const {
  return inFirstColour(p.uv) ? color0_.evalFloat(p) : color1_.evalFloat(p);
}

float CheckerboardTexture::mean() const { return 0.5f * (color0_.meanValue() + color1_.meanValue()); }

std::shared_ptr<Object> makeCheckerboardTexture(const Properties& props) {
  return std::make_shared<CheckerboardTexture>(readSpectrumParameter(props, "color0", 0.4f, SpectrumUse::Reflectance),
                                               readSpectrumParameter(props, "color1", 0.2f, SpectrumUse::Reflectance),
                                               props.getTransform("to_uv"));
}

}  // namespace columba
