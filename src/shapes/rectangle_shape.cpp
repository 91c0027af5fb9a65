#include "shapes/rectangle_shape.h"

#include "shapes/triangle_mesh.h"

namespace columba {

std::shared_ptr<Object> makeRectangleShape(const Properties& props) {
  auto shape = std::make_shared<RectangleShape>(props.getTransform("to_world"), props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
