#pragma once
// The shape interface. Every shape puts its geometry into Embree (triangles, or user
// geometry with its own exact intersector) and turns Embree's hits into interactions.
#include <embree3/rtcore.h>

#include <functional>
#include <memory>
#include <optional>
#include "bsdfs/bsdf.h"
#include "core/frame.h"
#include "core/ray.h"

namespace columba {

class Emitter;
class Medium;
class Shape;

// What Embree reports for a hit, in the shape's own terms (u, v and primID are whatever the
// shape's geometry wrote; ng is the unnormalised geometric normal in the space of the Embree scene
// holding the geometry, a shapegroup's for a hit through an instance).
struct HitRecord {
  float t = 0.0f;
  unsigned primID = 0;
  float u = 0.0f, v = 0.0f;
  Vec3 ng;
  unsigned geomID = 0;  // the geometry hit in that Embree scene
};

struct SurfaceInteraction {
  Vec3 p;         // world position
  Vec3 ng;        // geometric normal (unit, oriented as the shape defines its front)
  Frame shading;  // shading frame; shading.n is on the same side as ng
  Vec2 uv;
  // Derivatives of the position in u and in v (world space, not normalised), which bump maps
  // need; zero where the shape does not give them.
  Vec3 dpdu, dpdv;
  float t = 0.0f;  // ray distance
  const Shape* shape = nullptr;
  SurfaceAttributes attributes;  // per-point values of the BSDF's parameters (a feather's barbules)
  // On a mesh whose file carries per-vertex or per-face values: them, the triangle hit and the
  // barycentric coordinates there (what mesh_attribute textures read); null elsewhere.
  const MeshAttributes* meshAttributes = nullptr;
  uint32_t triangle = 0;
  Vec2 barycentric;

  // Where textures are looked up at this point.
  TexturePoint texturePoint() const {
    TexturePoint p(uv);
    p.mesh = meshAttributes;
    p.triangle = triangle;
    p.barycentric = barycentric;
    p.attributes = &attributes;
    return p;
  }
  BSDFContext bsdfContext() const { return BSDFContext{texturePoint(), shading.toLocal(dpdu), shading.toLocal(dpdv)}; }

  // A ray leaving the surface without hitting it again (offset along ng to the side of `d`).
  Ray spawnRay(const Vec3& d) const;
  Ray spawnRayTo(const Vec3& target) const;  // tmax stops just short of `target`
};

// A point chosen on a shape, with where textures are looked up there (a textured area light's
// radiance).
struct PositionSample {
  Vec3 p, n;
  TexturePoint point;
  float pdfArea = 0.0f;
  // The point as an interaction to spawn rays from and look textures up at (position, normal
  // and texture point only).
  SurfaceInteraction interaction() const {
    SurfaceInteraction si;
    si.p = p;
    si.ng = n;
    si.shading = Frame::fromNormal(n);
    si.uv = point.uv;
    si.meshAttributes = point.mesh;
    si.triangle = point.triangle;
    si.barycentric = point.barycentric;
    return si;
  }
};

// A point on a shape chosen as seen from a reference point, with the solid-angle density of
// the direction toward it.
struct ReferenceSample {
  Vec3 p, n;
  TexturePoint point;
  float pdf = 0.0f;
};

class Shape : public Object {
 public:
  // Adds this shape's geometry to `scene` (committed) and returns its geometry ID.
  virtual unsigned addToEmbree(RTCDevice device, RTCScene scene) const = 0;
  virtual SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const = 0;
  // Area sampling, for shapes that carry an area emitter. Defaults throw InputError-free
  // std::logic_error: only shapes that support emission override them. `withTexturePoint`: the
  // sample says where textures are looked up there (an emitter with textured radiance); without
  // it the sample's `point` stays empty, which spares every untextured light sample that work
  // (on a sphere or a disk, an atan2 and more).
  virtual float surfaceArea() const;
  virtual PositionSample samplePosition(Vec2 u, bool withTexturePoint) const;
  // Sampling for lighting a point `ref`: by default uniform by area, converted to solid angle;
  // shapes with a better strategy (spheres: the cone they subtend) override both.
  virtual std::optional<ReferenceSample> sampleFrom(const Vec3& ref, Vec2 u, bool withTexturePoint) const;
  virtual float pdfFrom(const Vec3& ref, const SurfaceInteraction& hit) const;
  // Number of Embree primitives (for statistics).
  virtual size_t primitiveCount() const = 0;

  // The medium a ray leaving this surface at a point of geometric normal `ng` toward `d` travels
  // in: for a shape that bounds media, its exterior on the side `ng` points to and its interior
  // on the other (null: none); `current` for a shape that bounds none.
  const Medium* mediumToward(const Vec3& ng, const Vec3& d, const Medium* current) const {
    if (!interior && !exterior) return current;
    return dot(ng, d) > 0.0f ? exterior.get() : interior.get();
  }

  // Whether the BSDF of this shape, or of any shape it places (an instance's group), passes `test`.
  virtual bool anyBSDF(const std::function<bool(const BSDF&)>& test) const { return bsdf && test(*bsdf); }

  std::shared_ptr<BSDF> bsdf;
  std::shared_ptr<Emitter> emitter;            // area emitter, or null
  std::shared_ptr<Medium> interior, exterior;  // the media this shape bounds, or null
};

}  // namespace columba
