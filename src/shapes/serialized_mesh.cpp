/*! plugin shape serialized
A triangle mesh from a Mitsuba serialized file (zlib-compressed meshes, format versions 3 and 4), with a nested BSDF (default: `diffuse`) and optionally an `area` emitter. A mesh the file marks as face-normal is shaded flat.
Mitsuba 3: the same parameters and defaults.
uses: mesh, media
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the serialized file | same |
| shape_index | integer | 0 | which mesh of the file; 0 or more | same |
| to_world | transform | identity | places the mesh | same |
*/
#include "shapes/serialized_mesh.h"

#include <zlib.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

namespace columba {

namespace {

constexpr uint16_t kSerializedMagic = 0x041C;
enum SerializedFlag : uint32_t {
  kHasNormals = 0x0001,
  kHasTexcoords = 0x0002,
  kHasColors = 0x0008,
  kFaceNormals = 0x0010,
  kDoublePrecision = 0x2000,
};
// zlib's DEFLATE expands at most about 1032:1; a count needing more than this many bytes per
// compressed byte cannot be in the file.
constexpr double kMaxInflateRatio = 1100.0;

template <typename T>
T readLittleEndian(const unsigned char* p) {
  T value = 0;
  for (size_t i = 0; i < sizeof(T); ++i) value |= T(p[i]) << (8 * i);
  return value;
}

// The zlib stream of one mesh, inflated on demand as the fields are read.
class InflatingReader {
 public:
  InflatingReader(const unsigned char* data, size_t size, std::string where) : where_(std::move(where)) {
    stream_.next_in = const_cast<unsigned char*>(data);
    stream_.avail_in = unsigned(std::min<size_t>(size, std::numeric_limits<unsigned>::max()));
    if (inflateInit(&stream_) != Z_OK) throw InputError({}, where_ + ": cannot start zlib decompression");
  }
  ~InflatingReader() { inflateEnd(&stream_); }
  InflatingReader(const InflatingReader&) = delete;
  InflatingReader& operator=(const InflatingReader&) = delete;

  void read(void* out, size_t bytes, const char* what) {
    stream_.next_out = static_cast<unsigned char*>(out);
    while (bytes > 0) {
      unsigned chunk = unsigned(std::min<size_t>(bytes, 1u << 30));
      stream_.avail_out = chunk;
      int status = inflate(&stream_, Z_NO_FLUSH);
      size_t produced = chunk - stream_.avail_out;
      bytes -= produced;
      if (bytes == 0) break;
      if (status == Z_STREAM_END || (status == Z_BUF_ERROR && stream_.avail_in == 0))
        throw InputError({}, where_ + ": the compressed data ends inside the " + what);
      if (status != Z_OK)
        throw InputError({}, where_ + ": corrupt compressed data in the " + what +
                                 " (zlib: " + (stream_.msg ? stream_.msg : "error " + std::to_string(status)) + ")");
    }
  }
  template <typename T>
  T read(const char* what) {
    unsigned char raw[sizeof(T)];
    read(raw, sizeof(T), what);
    return readLittleEndian<T>(raw);
  }
  // `count` numbers stored as float or double, as floats.
  std::vector<float> readReals(size_t count, bool doublePrecision, const char* what) {
    std::vector<float> out(count);
    if (doublePrecision) {
      for (size_t i = 0; i < count; ++i) {
        uint64_t bits = read<uint64_t>(what);
        double v;
        std::memcpy(&v, &bits, sizeof v);
        out[i] = float(v);
      }
    } else {
      read(out.data(), count * sizeof(float), what);  // x86-64 and the file are little endian
    }
    for (size_t i = 0; i < count; ++i)
      if (!std::isfinite(out[i]))
        throw InputError({}, where_ + ": " + what + " value " + std::to_string(i) + " is not a finite number");
    return out;
  }

 private:
  z_stream stream_{};
  std::string where_;
};

// Byte offset of mesh `index` from the dictionary at the end of the file.
size_t meshOffset(const unsigned char* data, size_t size, uint16_t version, int index, const std::string& name) {
  uint32_t count = readLittleEndian<uint32_t>(data + size - 4);
  if (index >= int64_t(count))
    throw InputError({}, name + ": shape_index " + std::to_string(index) + " is out of range: the file holds " +
                             std::to_string(count) + " mesh" + (count == 1 ? "" : "es"));
  size_t entry = version == 4 ? 8 : 4;
  if (size_t(count) * entry + 4 > size)
    throw InputError(
        {}, name + ": the mesh dictionary at the end of the file is truncated (" + std::to_string(count) + " meshes)");
  const unsigned char* at = data + size - 4 - entry * (size_t(count) - size_t(index));
  uint64_t offset = version == 4 ? readLittleEndian<uint64_t>(at) : readLittleEndian<uint32_t>(at);
  if (offset > size || size - offset < 4)  // not offset + 4, which a hostile offset overflows
    throw InputError({}, name + ": mesh " + std::to_string(index) + " starts at byte " + std::to_string(offset) +
                             ", beyond the end of the file");
  return size_t(offset);
}

}  // namespace

SerializedMesh parseSerializedMesh(const std::string& bytes, int shapeIndex, const std::string& name) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t size = bytes.size();
  if (shapeIndex < 0) throw InputError({}, name + ": shape_index must be 0 or more, not " + std::to_string(shapeIndex));
  auto header = [&](size_t at) {
    if (at > size || size - at < 4) throw InputError({}, name + ": too short for a Mitsuba serialized mesh");
    uint16_t magic = readLittleEndian<uint16_t>(data + at), version = readLittleEndian<uint16_t>(data + at + 2);
    if (magic != kSerializedMagic) throw InputError({}, name + ": not a Mitsuba serialized mesh (no 0x041C header)");
    if (version != 3 && version != 4)
      throw InputError(
          {}, name + ": serialized format version " + std::to_string(version) + " is not supported (only 3 and 4)");
    return version;
  };
  uint16_t version = header(0);
  size_t offset = shapeIndex == 0 ? 0 : meshOffset(data, size, version, shapeIndex, name);
  if (offset != 0 && header(offset) != version)
    throw InputError({}, name + ": mesh " + std::to_string(shapeIndex) + " has another format version than the file");

  const std::string where = name + ": mesh " + std::to_string(shapeIndex);
  InflatingReader in(data + offset + 4, size - offset - 4, where);
  uint32_t flags = in.read<uint32_t>("flags");
  if (version == 4)
    for (char c = 1; c != 0;) in.read(&c, 1, "mesh name");
  uint64_t vertexCount = in.read<uint64_t>("vertex count"), triangleCount = in.read<uint64_t>("triangle count");
  if (vertexCount == 0 || triangleCount == 0)
    throw InputError({}, where + ": the mesh has no vertices or no triangles");
  if (vertexCount > std::numeric_limits<uint32_t>::max())
    throw InputError({}, where + ": " + std::to_string(vertexCount) + " vertices; at most 2^32 - 1 are supported");
  const bool doublePrecision = flags & kDoublePrecision;
  const double real = doublePrecision ? 8.0 : 4.0;
  double perVertex = 3.0 + ((flags & kHasNormals) ? 3.0 : 0.0) + ((flags & kHasTexcoords) ? 2.0 : 0.0) +
                     ((flags & kHasColors) ? 3.0 : 0.0);
  double needed = double(vertexCount) * perVertex * real + double(triangleCount) * 12.0;
  if (needed > double(size - offset) * kMaxInflateRatio)
    throw InputError({}, where + ": " + std::to_string(vertexCount) + " vertices and " + std::to_string(triangleCount) +
                             " triangles cannot fit in the file's " + std::to_string(size - offset) +
                             " compressed bytes (corrupt counts)");

  SerializedMesh out;
  out.faceNormals = flags & kFaceNormals;
  MeshData& mesh = out.mesh;
  const size_t n = size_t(vertexCount);
  std::vector<float> p = in.readReals(3 * n, doublePrecision, "vertex positions");
  mesh.positions.resize(n);
  for (size_t i = 0; i < n; ++i) mesh.positions[i] = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  if (flags & kHasNormals) {
    std::vector<float> v = in.readReals(3 * n, doublePrecision, "vertex normals");
    mesh.normals.resize(n);
    for (size_t i = 0; i < n; ++i) mesh.normals[i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  }
  if (flags & kHasTexcoords) {
    std::vector<float> t = in.readReals(2 * n, doublePrecision, "texture coordinates");
    mesh.uvs.resize(n);
    for (size_t i = 0; i < n; ++i) mesh.uvs[i] = Vec2(t[2 * i], t[2 * i + 1]);
  }
  if (flags & kHasColors) in.readReals(3 * n, doublePrecision, "vertex colours");  // not used
  mesh.indices.resize(3 * size_t(triangleCount));
  in.read(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t), "triangle indices");
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= vertexCount)
      throw InputError({}, where + ": triangle " + std::to_string(i / 3) + " refers to vertex " +
                               std::to_string(mesh.indices[i]) + ", but the mesh has " + std::to_string(n) +
                               " vertices");
  return out;
}

SerializedMesh readSerializedMesh(const std::string& path, int shapeIndex) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError({}, path + ": cannot open the serialized mesh");
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw InputError({}, path + ": cannot read the serialized mesh");
  return parseSerializedMesh(bytes, shapeIndex, path);
}

std::shared_ptr<Object> makeSerializedShape(const Properties& props) {
  int shapeIndex = props.getInt("shape_index", 0);
  if (shapeIndex < 0) throw props.error("shape_index", "must be 0 or more");
  SerializedMesh s = readSerializedMesh(props.getPath("filename"), shapeIndex);
  return finishMeshShape(props, std::move(s.mesh), props.getTransform("to_world"), s.faceNormals);
}

}  // namespace columba
