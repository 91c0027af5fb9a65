/*! plugin shape feather
Feathers: barbs read from a feather PLY file (the [feather PLY format](../feather-ply.md); `columba feather` writes them), each segment a cylindrical strip intersected exactly. `to_world` is applied to the vertices and normals when the file is loaded; the widths are in the file's units and scale with the cube root of to_world's determinant. The strip radius is (barbwidth / 2) / sin(cover), and barbs taper toward their tips. Per-vertex barbule values in the file (H, mu, height) and layer stacks (stack, the nearer vertex's) are given to the nested BSDF (default: `diffuse`). A feather takes no emitter.
Mitsuba 3: not in Mitsuba 3.
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the feather PLY file | not in Mitsuba 3 |
| barbwidth | float | the file's, or 0.015 | a barb's width at its base; positive | not in Mitsuba 3 |
| ramuswidth | float | 0.00063 | the width of the ramus along the middle of each barb, 0 to `barbwidth` | not in Mitsuba 3 |
| cover | float | 0.78 | the half-angle in radians, in (0, π/2), that the strip spans around its normal at the barb's base | not in Mitsuba 3 |
| span | float | 0.45 | the angle in radians, in (−π/2, π/2), of the barbules from the barb axis toward the tip | not in Mitsuba 3 |
| to_world | transform | identity | places the feathers | not in Mitsuba 3 |
*/
// The scene-file entry point of the feather shape, apart from the shape itself so that code
// using FeatherShape directly does not depend on the plug-in registry.
#include "bsdfs/diffuse.h"
#include "shapes/feather_shape.h"

namespace columba {

namespace {

// The feather PLY named by `filename`; a missing file's error says how to make one.
FeatherPlyData readNamedFeatherPly(const Properties& props) {
  std::string path;
  try {
    path = props.getPath("filename");
  } catch (const InputError& e) {
    const std::string prefix = e.location.str() + ": ";
    std::string message = e.what();
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    throw InputError(e.location, message +
                                     "; generate feathers with `columba feather --neck -o FILE.ply` (a neck) "
                                     "or `columba feather --single -o FILE.ply` (one feather)");
  }
  return readFeatherPly(path);
}

}  // namespace

std::shared_ptr<Object> makeFeatherShape(const Properties& props) {
  FeatherPlyData ply = readNamedFeatherPly(props);
  FeatherShapeParams params;
  // The scene's barbwidth wins; otherwise the one the file was laid out for, if it records one.
  params.barbWidth = props.getFloat("barbwidth", ply.barbWidth.value_or(params.barbWidth));
  params.ramusWidth = props.getFloat("ramuswidth", params.ramusWidth);
  params.cover = props.getFloat("cover", params.cover);
  params.span = props.getFloat("span", params.span);
  params.toWorld = props.getTransform("to_world");
  if (!(params.barbWidth > 0.0f)) throw props.error("barbwidth", "must be positive");
  if (!(params.ramusWidth >= 0.0f && params.ramusWidth <= params.barbWidth))
    throw props.error("ramuswidth", "must be between 0 and barbwidth");
  if (!(params.cover > 0.0f && params.cover < kHalfPi)) throw props.error("cover", "must be in (0, pi/2) radians");
  if (!(std::abs(params.span) < kHalfPi)) throw props.error("span", "must be in (-pi/2, pi/2) radians");

  auto shape = std::make_shared<FeatherShape>(std::move(ply), params);
  shape->bsdf = props.child<BSDF>();
  // Mitsuba's default material when none is nested.
  if (!shape->bsdf) shape->bsdf = makeDefaultPlugin<BSDF>(makeDiffuseBSDF, "bsdf", "diffuse", props.location);
  shape->bsdf->noteValuesGivenByShape(shape->givenValues("the feather '" + props.getString("filename") + "'"));
  return shape;
}

}  // namespace columba
