/*! plugin texture mesh_attribute
A PLY mesh's own values: per-vertex values interpolated across each triangle, or per-face values. Colours become spectra when the mesh is loaded and are blended as bitmaps blend texels. Looked up on a shape without the attribute, the render stops with an error naming the texture's line and the attributes the mesh has.
Mitsuba 3: the same parameters and defaults.
| parameter | type | default | meaning | Mitsuba 3 |
| name | string | required | the attribute, `vertex_...` or `face_...` (see `ply`) | same |
| scale | float | 1 | a factor on the values | same |
*/
#include "textures/mesh_attribute_texture.h"

#include "core/error.h"

namespace columba {

namespace {
constexpr const char* kVertexPrefix = "vertex_";
}  // namespace

MeshAttributeTexture::MeshAttributeTexture(std::string name, float scale, SourceLocation where)
    : key_(name), name_(std::move(name)), scale_(scale), where_(std::move(where)) {
  if (name_.rfind(kVertexPrefix, 0) == 0)
    shapeKey_ = SurfaceAttributeKey::find(std::string_view(name_).substr(std::string_view(kVertexPrefix).size()));
}

const MeshAttributes::Attribute* MeshAttributeTexture::attributeAt(const TexturePoint& p, float& shapeValue) const {
  if (const MeshAttributes::Attribute* a = p.mesh ? p.mesh->find(key_) : nullptr) return a;
  if (std::optional<float> v = shapeKey_ && p.attributes ? p.attributes->find(*shapeKey_) : std::nullopt) {
    shapeValue = *v;
    return nullptr;
  }
  std::string has =
      p.mesh ? "its attributes: " + p.mesh->names() : std::string("not a mesh with per-vertex or per-face values");
  if (p.attributes && !p.attributes->empty()) has = "its per-point values: " + p.attributes->names(kVertexPrefix);
  throw InputError(where_, "mesh_attribute '" + name_ + "' was looked up on a shape without it (" + has + ")");
}

// Each lookup finds its attribute (or throws) before it touches the mesh, which may be absent.
Spectrum MeshAttributeTexture::evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const {
  float v = 0.0f;
  const MeshAttributes::Attribute* a = attributeAt(p, v);
  return a ? p.mesh->evalSpectrum(*a, p.triangle, p.barycentric, wl) * scale_ : Spectrum(v * scale_);
}

float MeshAttributeTexture::evalFloat(const TexturePoint& p) const {
  float v = 0.0f;
  const MeshAttributes::Attribute* a = attributeAt(p, v);
  return (a ? p.mesh->evalFloat(*a, p.triangle, p.barycentric) : v) * scale_;
}

Vec3 MeshAttributeTexture::evalTriple(const TexturePoint& p) const {
  float v = 0.0f;
  const MeshAttributes::Attribute* a = attributeAt(p, v);
  return a ? p.mesh->evalTriple(*a, p.triangle, p.barycentric) * scale_ : Vec3(v, v, v) * scale_;
}

std::shared_ptr<Object> makeMeshAttributeTexture(const Properties& props) {
  const std::string name = props.getString("name");
  if (name.rfind(kVertexPrefix, 0) != 0 && name.rfind("face_", 0) != 0)
    throw props.error("name", "a mesh attribute's name starts with vertex_ or face_, not '" + name + "'");
  return std::make_shared<MeshAttributeTexture>(name, props.getFloat("scale", 1.0f), props.location);
}

}  // namespace columba
