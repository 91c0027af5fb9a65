#include "textures/textured_parameter.h"

namespace columba {

namespace {
std::shared_ptr<const Texture> textureOf(const Properties& props, const std::string& name) {
  std::shared_ptr<const Texture> texture = props.namedChild<Texture>(name);
  if (texture && props.has(name)) throw props.error(name, "'" + name + "' is given both as a value and as a texture");
  return texture;
}
}  // namespace

SpectrumParameter readSpectrumParameter(const Properties& props, const std::string& name, float def, SpectrumUse use) {
  if (auto texture = textureOf(props, name)) {
    if (!texture->givesSpectra())
      throw props.error(name, "the texture for '" + name +
                                  "' holds raw numbers, not colours (it was read with raw=true): it cannot give a "
                                  "spectrum");
    return SpectrumParameter(texture);
  }
  return SpectrumParameter(props.getSpectrum(name, def, use));
}

FloatParameter readFloatParameter(const Properties& props, const std::string& name, float def) {
  if (auto texture = textureOf(props, name)) {
    if (!texture->givesNumbers())
      throw props.error(name, "the texture for '" + name + "' holds three numbers (a vector), not one");
    return FloatParameter(texture);
  }
  return FloatParameter(props.getFloat(name, def));
}

}  // namespace columba
