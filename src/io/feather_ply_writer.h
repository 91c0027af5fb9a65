#pragma once
// Streams barbs into a feather PLY (the format the `feather` shape reads, see
// io/feather_ply.h): vertices go straight to disk as they come, and the faces, which
// just number the vertices in order, are written at the end. Nothing is kept in memory, so
// files of any size can be written. The file appears under its name only when complete: it is
// written beside it under a temporary name and renamed by commit().
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>
#include "core/vector.h"
#include "io/feather_ply.h"

namespace columba {

struct BarbVertex {
  Vec3 position;
  Vec3 normal;  // vane normal
  // In the file's convention (shapes/feather_barbule_values.h), not the model's.
  float fileH = 0.0f, fileMu = 0.0f, height = 0.0f;
  uint8_t stack = 0;  // the barbule BSDF's layer stack
};

// Which optional vertex properties a file has: H, mu and height (all three), and stack.
struct FeatherPlyVertexProperties {
  bool barbuleValues = true;
  bool layerStack = false;
};

class FeatherPlyWriter {
 public:
  // Throws std::runtime_error if the temporary file cannot be created. `barbWidth` is recorded
  // in the header (`comment barbwidth W`) for the feather shape to use when the scene sets none.
  FeatherPlyWriter(const std::string& path, bool binary, size_t barbCount, std::optional<float> barbWidth,
                   FeatherPlyVertexProperties properties = {});
  ~FeatherPlyWriter();
  FeatherPlyWriter(const FeatherPlyWriter&) = delete;
  FeatherPlyWriter& operator=(const FeatherPlyWriter&) = delete;

  // One barb, kBarbVertices vertices from base to tip.
  void writeBarb(const BarbVertex* vertices);
  // Writes the faces and moves the file into place; throws unless exactly the announced number
  // of barbs was written and every write succeeded.
  void commit();

 private:
  void put(const char* data, size_t size);

  std::string path_, tempPath_;
  bool binary_;
  FeatherPlyVertexProperties properties_;
  size_t barbCount_, written_ = 0;
  std::FILE* file_ = nullptr;
  std::vector<char> buffer_;
};

}  // namespace columba
