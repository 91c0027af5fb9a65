#include "textures/raw_constant_texture.h"

namespace columba {

std::shared_ptr<Object> makeRawConstantTexture(const Properties& props) {
  if (!props.has("value")) throw InputError(props.location, "'rawconstant' needs its 'value' (a float or a vector)");
  if (props.isVector("value")) return std::make_shared<RawConstantTexture>(props.getVector("value", Vec3()));
  return std::make_shared<RawConstantTexture>(props.getFloat("value"));
}

}  // namespace columba
