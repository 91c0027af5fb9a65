#include "textures/mesh_attribute_texture.h"

#include "core/error.h"

namespace columba {

const MeshAttributes::Attribute& MeshAttributeTexture::attributeAt(const TexturePoint& p) const {
  const MeshAttributes::Attribute* a = p.mesh ? p.mesh->find(key_) : nullptr;
  if (!a)
    throw InputError(where_, "mesh_attribute '" + name_ + "' was looked up on a shape without it (" +
                                 (p.mesh ? "its attributes: " + p.mesh->names()
                                         : std::string("not a mesh with per-vertex or per-face values")) +
                                 ")");
  return *a;
}

// Each lookup finds its attribute (or throws) before it touches the mesh, which may be absent.
Spectrum MeshAttributeTexture::evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const {
  const MeshAttributes::Attribute& a = attributeAt(p);
  return p.mesh->evalSpectrum(a, p.triangle, p.barycentric, wl) * scale_;
}

float MeshAttributeTexture::evalFloat(const TexturePoint& p) const {
  const MeshAttributes::Attribute& a = attributeAt(p);
  return p.mesh->evalFloat(a, p.triangle, p.barycentric) * scale_;
}

Vec3 MeshAttributeTexture::evalTriple(const TexturePoint& p) const {
  const MeshAttributes::Attribute& a = attributeAt(p);
  return p.mesh->evalTriple(a, p.triangle, p.barycentric) * scale_;
}

std::shared_ptr<Object> makeMeshAttributeTexture(const Properties& props) {
  const std::string name = props.getString("name");
  if (name.rfind("vertex_", 0) != 0 && name.rfind("face_", 0) != 0)
    throw props.error("name", "a mesh attribute's name starts with vertex_ or face_, not '" + name + "'");
  return std::make_shared<MeshAttributeTexture>(name, props.getFloat("scale", 1.0f), props.location);
}

}  // namespace columba
