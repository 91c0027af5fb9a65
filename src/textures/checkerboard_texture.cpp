/*! plugin texture checkerboard
A checkerboard of two colours, two squares by two over the unit uv square. Where it gives a single value (a roughness, `metallic`, any float parameter) the squares take the colours the other way round, as Mitsuba 3 looks them up, so that Mitsuba's scenes put their rough and smooth squares in the same places.
Mitsuba 3: the same parameters and defaults, and the same swap for single values.
| parameter | type | default | meaning | Mitsuba 3 |
| color0 | spectrum or texture | 0.4 | the first colour | same |
| color1 | spectrum or texture | 0.2 | the second colour | same |
| to_uv | transform | identity | applied to the uv coordinates before the lookup | same |
*/
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

// Mitsuba 3 looks a checkerboard's single values (roughness, metallic, any float parameter) up
// with the colours swapped: its eval_1 tests mask.x != mask.y where eval tests ==. Columba does
// the same, so that a Mitsuba scene's rough and smooth squares fall where Mitsuba puts them.
float CheckerboardTexture::evalFloat(const TexturePoint& p) const {
  return inFirstColour(p.uv) ? color1_.evalFloat(p) : color0_.evalFloat(p);
}

float CheckerboardTexture::evalLuminance(const TexturePoint& p) const {
  return inFirstColour(p.uv) ? color0_.evalLuminance(p) : color1_.evalLuminance(p);
}

float CheckerboardTexture::mean() const { return 0.5f * (color0_.meanValue() + color1_.meanValue()); }

std::shared_ptr<Object> makeCheckerboardTexture(const Properties& props) {
  return std::make_shared<CheckerboardTexture>(readSpectrumParameter(props, "color0", 0.4f, SpectrumUse::Reflectance),
                                               readSpectrumParameter(props, "color1", 0.2f, SpectrumUse::Reflectance),
                                               props.getTransform("to_uv"));
}

}  // namespace columba
