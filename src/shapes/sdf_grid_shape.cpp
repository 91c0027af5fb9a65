/*! plugin shape sdfgrid
A signed distance field on a grid: a single-channel grid volume `.vol` file of float32 samples, at least 2 per axis, at the corners of the voxels tiling the unit cube that `to_world` places. Each voxel's trilinear interpolant is intersected exactly, at its first zero along the ray. It has no uv, dp/du or dp/dv and cannot carry an area emitter, as in Mitsuba; a nested BSDF defaults to `diffuse`.
Mitsuba 3: the same parameters and defaults; the `grid` tensor, which Mitsuba 3 takes from Python, cannot be given in a scene file.
uses: media
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the `.vol` grid file | same |
| normals | string | `smooth` | `smooth`: the blend of the eight neighbouring voxels' gradients; `analytic`: the interpolant's own gradient | same |
| to_world | transform | identity | places the unit cube | same |
| flip_normals | boolean | false | turns the normals around | same |
*/
#include "shapes/sdf_grid_shape.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "emitters/emitter.h"
#include "shapes/embree_user_geometry.h"
#include "shapes/triangle_mesh.h"

namespace columba {

namespace {

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto* shape = static_cast<const SDFGridShape*>(args->geometryUserPtr);
  Vec3 lo, hi;
  shape->primitiveBounds(args->primID, lo, hi);
  Vec3 wlo(INFINITY, INFINITY, INFINITY), whi(-INFINITY, -INFINITY, -INFINITY);
  for (int c = 0; c < 8; ++c) {
    Vec3 w = shape->toWorldPoint(Vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z));
    wlo = minv(wlo, w);
    whi = maxv(whi, w);
  }
  // Round-off in the transform and in Embree's box tests must not cut off a hit on the box's edge.
  const float magnitude =
      std::max({std::abs(wlo.x), std::abs(wlo.y), std::abs(wlo.z), std::abs(whi.x), std::abs(whi.y), std::abs(whi.z)});
  const float pad = 8.0f * FLT_EPSILON * magnitude;
  args->bounds_o->lower_x = wlo.x - pad;
  args->bounds_o->lower_y = wlo.y - pad;
  args->bounds_o->lower_z = wlo.z - pad;
  args->bounds_o->upper_x = whi.x + pad;
  args->bounds_o->upper_y = whi.y + pad;
  args->bounds_o->upper_z = whi.z + pad;
}

CellPoint clampToCell(CellPoint q) {
  for (double& x : q) x = std::clamp(x, 0.0, 1.0);
  return q;
}

}  // namespace

SDFGridShape::SDFGridShape(VolumeGrid grid, const Transform& toWorld, Normals normals, bool flipNormals,
                           const std::string& name)
    : resolution_{grid.xres, grid.yres, grid.zres},
      samples_(std::move(grid.values)),
      toWorld_(toWorld),
      toObject_(toWorld.inverse()),
      normals_(normals),
      flip_(flipNormals) {
  if (grid.channels != 1)
    throw InputError({}, name + ": " + std::to_string(grid.channels) + " channels; an SDF grid has 1");
  if (grid.xres < 2 || grid.yres < 2 || grid.zres < 2)
    throw InputError({}, name + ": the resolution " + std::to_string(grid.xres) + " x " + std::to_string(grid.yres) +
                             " x " + std::to_string(grid.zres) + " needs at least 2 samples along each axis");
  // The trilinear interpolant lies between its corners' extremes: the surface can only cross
  // voxels whose corners are not all of one sign.
  for (int z = 0; z + 1 < grid.zres; ++z)
    for (int y = 0; y + 1 < grid.yres; ++y)
      for (int x = 0; x + 1 < grid.xres; ++x) {
        bool nonNegative = false, nonPositive = false;
        for (int c = 0; c < 8; ++c) {
          double f = sample(x + (c & 1), y + ((c >> 1) & 1), z + (c >> 2));
          nonNegative |= f >= 0.0;
          nonPositive |= f <= 0.0;
        }
        if (nonNegative && nonPositive) voxels_.push_back({x, y, z});
      }
  if (voxels_.empty()) throw InputError({}, name + ": every value has the same sign: the grid holds no surface");
  if (voxels_.size() > std::numeric_limits<unsigned>::max())
    throw InputError({},
                     name + ": " + std::to_string(voxels_.size()) + " voxels hold the surface, more than Embree takes");
}

double SDFGridShape::sample(int x, int y, int z) const {
  return samples_[(size_t(z) * size_t(resolution_[1]) + size_t(y)) * size_t(resolution_[0]) + size_t(x)];
}

TrilinearCell SDFGridShape::cell(const Voxel& v) const {
  std::array<double, 8> corners;
  for (int c = 0; c < 8; ++c) corners[c] = sample(v[0] + (c & 1), v[1] + ((c >> 1) & 1), v[2] + (c >> 2));
  return TrilinearCell(corners);
}

CellPoint SDFGridShape::toGrid(const Vec3& v) const {
  return {double(v.x) * (resolution_[0] - 1), double(v.y) * (resolution_[1] - 1), double(v.z) * (resolution_[2] - 1)};
}

CellPoint SDFGridShape::inVoxel(const Voxel& voxel, const CellPoint& gridPoint) const {
  return clampToCell({gridPoint[0] - voxel[0], gridPoint[1] - voxel[1], gridPoint[2] - voxel[2]});
}

Vec3 SDFGridShape::objectGradient(const CellPoint& gridGradient) const {
  return Vec3(float(gridGradient[0] * (resolution_[0] - 1)), float(gridGradient[1] * (resolution_[1] - 1)),
              float(gridGradient[2] * (resolution_[2] - 1)));
}

unsigned SDFGridShape::addToEmbree(RTCDevice device, RTCScene scene) const {
  return attachUserGeometry(device, scene, unsigned(voxels_.size()), this, boundsCallback,
                            userGeometryIntersect<SDFGridShape>, userGeometryOccluded<SDFGridShape>);
}

void SDFGridShape::primitiveBounds(unsigned primID, Vec3& lo, Vec3& hi) const {
  // The surface's extent along an axis begins and ends where a slice across that axis first or
  // last holds a zero; a slice's bilinear interpolant takes its extremes at its corners, on the
  // voxel's edges along that axis. So the zero corners and the zeros on the twelve edges bound it
  // (Hansson-Söderlund and Akenine-Möller 2023).
  const Voxel& v = voxels_[primID];
  const TrilinearCell c = cell(v);
  CellPoint boxLo{1, 1, 1}, boxHi{0, 0, 0};
  auto include = [&](const CellPoint& q) {
    for (int a = 0; a < 3; ++a) {
      boxLo[a] = std::min(boxLo[a], q[a]);
      boxHi[a] = std::max(boxHi[a], q[a]);
    }
  };
  auto corner = [](int i) { return CellPoint{double(i & 1), double((i >> 1) & 1), double(i >> 2)}; };
  for (int i = 0; i < 8; ++i) {
    const double fi = c.value(corner(i));
    if (fi == 0.0) include(corner(i));
    for (int axis = 0; axis < 3; ++axis) {
      if (i & (1 << axis)) continue;
      const double fj = c.value(corner(i | (1 << axis)));
      if (fi * fj > 0.0 || fi == fj) continue;
      CellPoint q = corner(i);
      q[axis] = fi / (fi - fj);
      include(q);
    }
  }
  // A thousandth of a voxel more, for the round-off of the edge zeros.
  for (int a = 0; a < 3; ++a) {
    boxLo[a] = (v[a] + boxLo[a] - 1e-3) / (resolution_[a] - 1);
    boxHi[a] = (v[a] + boxHi[a] + 1e-3) / (resolution_[a] - 1);
  }
  lo = Vec3(float(boxLo[0]), float(boxLo[1]), float(boxLo[2]));
  hi = Vec3(float(boxHi[0]), float(boxHi[1]), float(boxHi[2]));
}

bool SDFGridShape::intersectPrimitive(unsigned primID, const Vec3& worldO, const Vec3& worldD, float tmin, float tmax,
                                      float& t) const {
  // The map to grid coordinates is affine, so t is the world ray's parameter throughout.
  const CellPoint o = toGrid(toObject_.point(worldO)), d = toGrid(toObject_.vector(worldD));
  const Voxel& voxel = voxels_[primID];
  // The slabs of the voxel. Entry and exit distances are computed from the face's coordinate
  // alone, so a voxel's exit and its neighbour's entry are the same number.
  CellPoint enter, leave;
  double tBegin = tmin, tEnd = INFINITY;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < voxel[a] || o[a] > voxel[a] + 1) return false;
      enter[a] = -INFINITY;
      leave[a] = INFINITY;
      continue;
    }
    const double near = d[a] > 0.0 ? voxel[a] : voxel[a] + 1, far = d[a] > 0.0 ? voxel[a] + 1 : voxel[a];
    enter[a] = (near - o[a]) / d[a];
    leave[a] = (far - o[a]) / d[a];
    tBegin = std::max(tBegin, enter[a]);
    tEnd = std::min(tEnd, leave[a]);
  }
  if (!(tBegin < tEnd) || !std::isfinite(tEnd)) return false;
  // Where the ray crosses a face, that coordinate is set to the face's: both voxels sharing the
  // face then evaluate the same field there, and a surface close to it is found by one of them.
  CellPoint start, end;
  for (int a = 0; a < 3; ++a) {
    start[a] = enter[a] == tBegin ? (d[a] > 0.0 ? 0.0 : 1.0) : o[a] + d[a] * tBegin - voxel[a];
    end[a] = leave[a] == tEnd ? (d[a] > 0.0 ? 1.0 : 0.0) : o[a] + d[a] * tEnd - voxel[a];
  }
  start = clampToCell(start);
  end = clampToCell(end);
  const TrilinearCell c = cell(voxel);
  double along;
  if (!c.firstZero(start, d, tEnd - tBegin, c.value(start), c.value(end), along)) return false;
  const float hit = float(tBegin + along);
  if (!(hit > tmin && hit < tmax)) return false;
  t = hit;
  return true;
}

Vec3 SDFGridShape::worldNormal(const Vec3& objectGradient, const Vec3& fallback) const {
  Vec3 n = toWorld_.normal(objectGradient);  // the inverse transpose, as normals go
  if (!(lengthSquared(n) > 0.0f)) return fallback;
  n = normalize(n);
  return flip_ ? -n : n;
}

Vec3 SDFGridShape::primitiveNormal(unsigned primID, const Vec3& worldPoint) const {
  const Voxel& voxel = voxels_[primID];
  const CellPoint q = inVoxel(voxel, toGrid(toObject_.point(worldPoint)));
  // A gradient that vanishes on the surface (a voxel of zeros) leaves no direction: +z then.
  return worldNormal(objectGradient(cell(voxel).gradient(q)), Vec3(0, 0, 1));
}

Vec3 SDFGridShape::smoothGradient(const CellPoint& p) const {
  // The eight voxels around the sample nearest to p: along each axis the voxels below and above
  // it, blended by p's position between their centres. A voxel outside the grid gets no weight
  // (Mitsuba gives one beyond the upper boundary weight, with that axis's component zero: within
  // half a voxel of that boundary its normals lean away from it).
  // Each voxel's gradient component along an axis is the difference across the voxel of the
  // field's bilinear interpolant on the sample planes, at p's position along the other two axes.
  int nearest[3], cellIndex[3];
  double blend[3], within[3];
  for (int a = 0; a < 3; ++a) {
    const int last = resolution_[a] - 1;
    nearest[a] = std::clamp(int(std::lround(p[a])), 0, last);
    cellIndex[a] = std::clamp(int(std::floor(p[a])), 0, last - 1);
    within[a] = std::clamp(p[a] - cellIndex[a], 0.0, 1.0);
    blend[a] = nearest[a] == 0 ? 1.0 : nearest[a] == last ? 0.0 : std::clamp(p[a] - nearest[a] + 0.5, 0.0, 1.0);
  }
  auto plane = [&](int a, int index) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    double f[4];
    for (int i = 0; i < 4; ++i) {
      int s[3];
      s[a] = index;
      s[b] = cellIndex[b] + (i & 1);
      s[c] = cellIndex[c] + (i >> 1);
      f[i] = sample(s[0], s[1], s[2]);
    }
    const double u = within[b], v = within[c];
    return (1.0 - v) * ((1.0 - u) * f[0] + u * f[1]) + v * ((1.0 - u) * f[2] + u * f[3]);
  };
  double difference[3][2];  // [axis][the voxel below or above the nearest sample]
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const int voxel = nearest[a] - 1 + side;
      difference[a][side] = voxel < 0 || voxel > resolution_[a] - 2 ? 0.0 : plane(a, voxel + 1) - plane(a, voxel);
    }
  Vec3 sum(0, 0, 0);
  for (int i = 0; i < 8; ++i) {
    const int side[3] = {i & 1, (i >> 1) & 1, i >> 2};
    double weight = 1.0;
    for (int a = 0; a < 3; ++a) weight *= side[a] ? blend[a] : 1.0 - blend[a];
    const Vec3 g = objectGradient({difference[0][side[0]], difference[1][side[1]], difference[2][side[2]]});
    if (weight > 0.0 && lengthSquared(g) > 0.0f) sum += normalize(g) * float(weight);
  }
  return sum;
}

SurfaceInteraction SDFGridShape::interaction(const Ray& ray, const HitRecord& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  si.p = ray.at(hit.t);
  const Voxel& voxel = voxels_[hit.primID];
  const CellPoint gridPoint = toGrid(toObject_.point(si.p));
  si.ng = worldNormal(objectGradient(cell(voxel).gradient(inVoxel(voxel, gridPoint))), Vec3(0, 0, 1));
  Vec3 shadingNormal = si.ng;
  if (normals_ == Normals::Smooth) {
    shadingNormal = worldNormal(smoothGradient(gridPoint), si.ng);
    if (dot(shadingNormal, si.ng) < 0.0f) shadingNormal = -shadingNormal;
  }
  // No parameterisation (uv, dp/du and dp/dv stay zero, as in Mitsuba): any frame around the normal.
  si.shading = Frame::fromNormal(shadingNormal);
  return si;
}

std::shared_ptr<Object> makeSDFGridShape(const Properties& props) {
  const std::string mode = props.getString("normals", "smooth");
  if (mode != "smooth" && mode != "analytic")
    throw props.error("normals", "'" + mode + "' is not a normals mode: use 'smooth' or 'analytic'");
  if (auto emitter = props.child<Emitter>())
    throw InputError(props.childLocation(*emitter),
                     "an sdfgrid cannot carry an area emitter (Mitsuba does not support it either)");
  const std::string path = props.getPath("filename");
  const Transform toWorld = props.getTransform("to_world");
  const bool flipNormals = props.getBool("flip_normals", false);
  std::shared_ptr<SDFGridShape> shape;
  try {
    shape = std::make_shared<SDFGridShape>(
        readVolumeGrid(path), toWorld,
        mode == "smooth" ? SDFGridShape::Normals::Smooth : SDFGridShape::Normals::Analytic, flipNormals, path);
  } catch (const InputError& e) {
    throw props.error("filename", e.what());
  }
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
