#include "io/feather_ply_writer.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace columba {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "binary PLY writing assumes a little-endian host");

namespace {
constexpr size_t kFlushSize = 1 << 20;
}  // namespace

FeatherPlyWriter::FeatherPlyWriter(const std::string& path, bool binary, size_t barbCount,
                                   std::optional<float> barbWidth, FeatherPlyVertexProperties properties)
    : path_(path),
      tempPath_(path + ".tmp" + std::to_string(getpid())),
      binary_(binary),
      properties_(properties),
      barbCount_(barbCount) {
  file_ = std::fopen(tempPath_.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot create '" + tempPath_ + "': " + std::strerror(errno));
  buffer_.reserve(2 * kFlushSize);
  std::string header = fmt::format(
      "ply\nformat {} 1.0\ncomment Columba procedural feathers: one face per barb, base first\n"
      "{}"
      "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "{}"
      "property float out1\nproperty float out2\nproperty float out3\n"
      "{}"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      binary ? "binary_little_endian" : "ascii",
      barbWidth ? fmt::format("comment {} {}\n", kBarbWidthComment, *barbWidth) : std::string(),
      barbCount * kBarbVertices,
      properties.barbuleValues ? "property float H\nproperty float mu\nproperty float height\n" : "",
      properties.layerStack ? "property uchar stack\n" : "", barbCount);
  put(header.data(), header.size());
}

FeatherPlyWriter::~FeatherPlyWriter() {
  if (file_) {
    std::fclose(file_);
    std::filesystem::remove(tempPath_);
  }
}

void FeatherPlyWriter::put(const char* data, size_t size) {
  buffer_.insert(buffer_.end(), data, data + size);
  if (buffer_.size() < kFlushSize) return;
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
    throw std::runtime_error("cannot write '" + tempPath_ + "': " + std::strerror(errno));
  buffer_.clear();
}

void FeatherPlyWriter::writeBarb(const BarbVertex* vertices) {
  if (written_ == barbCount_) throw std::logic_error("more barbs than announced in the PLY header");
  ++written_;
  for (int i = 0; i < kBarbVertices; ++i) {
    const BarbVertex& v = vertices[i];
    const float values[9] = {v.position.x, v.position.y, v.position.z, v.fileH,   v.fileMu,
                             v.height,     v.normal.x,   v.normal.y,   v.normal.z};
    const float withoutValues[6] = {v.position.x, v.position.y, v.position.z, v.normal.x, v.normal.y, v.normal.z};
    const float* record = properties_.barbuleValues ? values : withoutValues;
    const size_t count = properties_.barbuleValues ? 9 : 6;
    if (binary_) {
      put(reinterpret_cast<const char*>(record), count * sizeof(float));
      if (properties_.layerStack) put(reinterpret_cast<const char*>(&v.stack), 1);
    } else {
      // Shortest representation that reads back to the same float.
      fmt::memory_buffer line;
      for (size_t k = 0; k < count; ++k) fmt::format_to(std::back_inserter(line), k ? " {}" : "{}", record[k]);
      if (properties_.layerStack) fmt::format_to(std::back_inserter(line), " {}", int(v.stack));
      line.push_back('\n');
      put(line.data(), line.size());
    }
  }
}

void FeatherPlyWriter::commit() {
  if (written_ != barbCount_)
    throw std::logic_error(fmt::format("{} barbs written, {} announced", written_, barbCount_));
  for (size_t f = 0; f < barbCount_; ++f) {
    const uint32_t first = uint32_t(f * kBarbVertices);
    if (binary_) {
      char record[1 + 4 * kBarbVertices];
      record[0] = char(kBarbVertices);
      for (uint32_t i = 0; i < uint32_t(kBarbVertices); ++i) {
        int32_t index = int32_t(first + i);
        std::memcpy(record + 1 + 4 * i, &index, 4);
      }
      put(record, sizeof(record));
    } else {
      fmt::memory_buffer line;
      fmt::format_to(std::back_inserter(line), "{}", kBarbVertices);
      for (uint32_t i = 0; i < uint32_t(kBarbVertices); ++i) fmt::format_to(std::back_inserter(line), " {}", first + i);
      line.push_back('\n');
      put(line.data(), line.size());
    }
  }
  bool ok = std::fwrite(buffer_.data(), 1, buffer_.size(), file_) == buffer_.size();
  ok = (std::fclose(file_) == 0) && ok;
  file_ = nullptr;
  if (!ok) {
    std::filesystem::remove(tempPath_);
    throw std::runtime_error("cannot write '" + tempPath_ + "'");
  }
  std::filesystem::rename(tempPath_, path_);
}

}  // namespace columba
