/*! plugin texture rawconstant
A constant value: one number, the same at every wavelength, or three, which serve only where raw triples are read (a normal map).
Mitsuba 3: —
| parameter | type | default | meaning | Mitsuba 3 |
| value | float or vector | required | the value: a `<float>`, or a `<vector>` or `<point>` of three | — |
*/
#include "textures/raw_constant_texture.h"

namespace columba {

std::shared_ptr<Object> makeRawConstantTexture(const Properties& props) {
  if (!props.has("value")) throw InputError(props.location, "'rawconstant' needs its 'value' (a float or a vector)");
  if (props.isVector("value")) return std::make_shared<RawConstantTexture>(props.getVector("value", Vec3()));
  return std::make_shared<RawConstantTexture>(props.getFloat("value"));
}

}  // namespace columba
