#pragma once
// `sdfgrid`: Mitsuba 3's signed distance field sampled on a regular grid. The samples of a
// single-channel grid volume file (`filename`, see io/volume_grid_file.h) sit at the corners of the
// voxels that tile the unit cube [0, 1]^3 of object space, which `to_world` places; inside a voxel
// the field is their trilinear interpolant, and the surface is where it vanishes (outward where it
// grows). Each voxel whose corners do not all share a sign is one Embree primitive, intersected
// exactly: its first zero along the ray (a cubic). `normals`: "analytic" shades with the geometric
// normal, the interpolant's gradient; "smooth" (the default, as in Mitsuba) blends the normalised
// gradients of the eight voxels around the nearest sample (Hansson-Söderlund, Evans and
// Akenine-Möller 2022, as Mitsuba computes them). As in Mitsuba there are no texture coordinates
// (uv, dp/du and dp/dv are zero) and no area emission.
#include <array>
#include <vector>

#include "core/properties.h"
#include "core/transform.h"
#include "io/volume_grid_file.h"
#include "shapes/shape.h"
#include "shapes/trilinear_cell.h"

namespace columba {

class SDFGridShape : public Shape {
 public:
  enum class Normals { Analytic, Smooth };
  // `grid` has one channel and at least two samples along each axis; `name` is for messages.
  SDFGridShape(VolumeGrid grid, const Transform& toWorld, Normals normals, bool flipNormals, const std::string& name);

  unsigned addToEmbree(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  size_t primitiveCount() const override { return voxels_.size(); }

  // For the Embree callbacks (embree_user_geometry.h): primitive `primID` is the voxel voxels_[primID].
  bool intersectPrimitive(unsigned primID, const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const;
  Vec3 primitiveNormal(unsigned primID, const Vec3& worldPoint) const;
  // The voxel's bounds in object space: tight around the surface inside it.
  void primitiveBounds(unsigned primID, Vec3& lo, Vec3& hi) const;
  Vec3 toWorldPoint(const Vec3& p) const { return toWorld_.point(p); }

 private:
  using Voxel = std::array<int, 3>;  // the index of its lowest corner sample
  TrilinearCell cell(const Voxel& voxel) const;
  double sample(int x, int y, int z) const;
  // Grid coordinates (a sample per unit) of an object-space point or vector.
  CellPoint toGrid(const Vec3& v) const;
  // The point's coordinates in the voxel, clamped to [0, 1]^3.
  CellPoint inVoxel(const Voxel& voxel, const CellPoint& gridPoint) const;
  // A gradient per grid unit, per object unit.
  Vec3 objectGradient(const CellPoint& gridGradient) const;
  // The unit world normal of an object-space gradient (flipped by flip_normals); `fallback` where
  // it vanishes.
  Vec3 worldNormal(const Vec3& objectGradient, const Vec3& fallback) const;
  // Mitsuba's smooth normal at a grid point, in object space, not normalised.
  Vec3 smoothGradient(const CellPoint& gridPoint) const;

  std::array<int, 3> resolution_;
  std::vector<float> samples_;  // x fastest, then y, then z
  std::vector<Voxel> voxels_;   // the voxels the surface passes through
  Transform toWorld_, toObject_;
  Normals normals_;
  bool flip_;
};

// <shape type="sdfgrid">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makeSDFGridShape(const Properties& props);

}  // namespace columba
