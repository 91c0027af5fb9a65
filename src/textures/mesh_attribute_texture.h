#pragma once
// Mitsuba's `mesh_attribute`: the values a mesh file carries per vertex ("vertex_<name>",
// interpolated across each triangle) or per face ("face_<name>"), times `scale`. A 3-channel
// attribute is a colour: each vertex's or face's colour becomes a smooth spectrum when the mesh is
// loaded, and a lookup blends the spectra of the triangle's vertices, as bitmaps blend texels'.
// On a shape that gives BSDF parameters per point (a feather: H, mu and height, in the model's
// terms), "vertex_<parameter>" reads that value at the hit. Looked up on a shape that does not
// have the attribute, it stops the render with an error that names the texture's line and the
// attributes the mesh has, as Mitsuba does.
#include <memory>
#include <optional>
#include <string>
#include "core/properties.h"
#include "textures/mesh_attributes.h"
#include "textures/texture.h"

namespace columba {

class MeshAttributeTexture : public Texture {
 public:
  MeshAttributeTexture(std::string name, float scale, SourceLocation where);
  Spectrum evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const override;
  float evalFloat(const TexturePoint& p) const override;
  bool givesTriples() const override { return true; }
  Vec3 evalTriple(const TexturePoint& p) const override;
  // The mean is the mesh's, which a texture shared between shapes does not know when it is built;
  // half the scale stands in for it where a BSDF weighs its lobes by it (that changes noise only).
  float mean() const override { return 0.5f * scale_; }

 private:
  // The mesh's attribute at `p`, or null where the shape gives the value per point instead (its
  // value then in `shapeValue`); throws where there is neither.
  const MeshAttributes::Attribute* attributeAt(const TexturePoint& p, float& shapeValue) const;

  MeshAttributeKey key_;  // what each lookup finds the attribute by
  // A "vertex_" name's rest, where some shape gives a BSDF parameter of that name per point.
  std::optional<SurfaceAttributeKey> shapeKey_;
  std::string name_;  // for messages
  float scale_;
  SourceLocation where_;
};

// <texture type="mesh_attribute">: its parameters are in docs/reference/textures.md.
std::shared_ptr<Object> makeMeshAttributeTexture(const Properties& props);

}  // namespace columba
