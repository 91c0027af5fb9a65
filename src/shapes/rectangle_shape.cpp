/*! plugin shape rectangle
The square [−1, 1]² in the local xy plane, facing +z, with uv = ((x + 1) / 2, (y + 1) / 2); a nested BSDF (default: `diffuse`) and optionally an `area` emitter.
Mitsuba 3: as Mitsuba 3's `rectangle`.
uses: media
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | places and sizes the square | same |
| flip_normals | boolean | false | faces −z instead | same |
*/
#include "shapes/rectangle_shape.h"

#include "shapes/triangle_mesh.h"

namespace columba {

std::shared_ptr<Object> makeRectangleShape(const Properties& props) {
  auto shape = std::make_shared<RectangleShape>(props.getTransform("to_world"), props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
