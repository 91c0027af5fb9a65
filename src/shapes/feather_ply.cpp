#include "shapes/feather_ply.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace columba {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "binary PLY reading assumes a little-endian host");

namespace {

enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parseScalarType(const std::string& name, ScalarType& type) {
  static const std::pair<const char*, ScalarType> kNames[] = {
      {"char", ScalarType::Int8},     {"int8", ScalarType::Int8},       {"uchar", ScalarType::UInt8},
      {"uint8", ScalarType::UInt8},   {"short", ScalarType::Int16},     {"int16", ScalarType::Int16},
      {"ushort", ScalarType::UInt16}, {"uint16", ScalarType::UInt16},   {"int", ScalarType::Int32},
      {"int32", ScalarType::Int32},   {"uint", ScalarType::UInt32},     {"uint32", ScalarType::UInt32},
      {"float", ScalarType::Float32}, {"float32", ScalarType::Float32}, {"double", ScalarType::Float64},
      {"float64", ScalarType::Float64}};
  for (const auto& [n, t] : kNames)
    if (name == n) { type = t; return true; }
  return false;
}

bool isInteger(ScalarType t) { return t != ScalarType::Float32 && t != ScalarType::Float64; }

struct PlyProperty {
  std::string name;
  ScalarType type = ScalarType::Float32;
  bool isList = false;
  ScalarType countType = ScalarType::UInt8;
};

struct PlyElement {
  std::string name;
  size_t count = 0;
  int line = 0;  // header line that declared it
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  bool binary = false;
  std::vector<PlyElement> elements;
  int endLine = 0;  // line of end_header
};

PlyHeader readHeader(std::istream& in, const std::string& path) {
  PlyHeader header;
  std::string line;
  int lineNo = 0;
  bool sawFormat = false;
  auto fail = [&](const std::string& msg) { throw InputError({path, lineNo}, msg); };
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (lineNo == 1) {
      if (keyword != "ply") fail("not a PLY file (the first line must be 'ply')");
      continue;
    }
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format == "ascii") header.binary = false;
      else if (format == "binary_little_endian") header.binary = true;
      else fail("unsupported PLY format '" + format + "' (ascii or binary_little_endian)");
      sawFormat = true;
    } else if (keyword == "element") {
      PlyElement e;
      long long count = -1;
      words >> e.name >> count;
      if (e.name.empty() || count < 0 || words.fail()) fail("malformed element declaration: '" + line + "'");
      e.count = size_t(count);
      e.line = lineNo;
      header.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("property declared before any element");
      PlyProperty p;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType >> p.name;
        p.isList = true;
        if (!parseScalarType(countType, p.countType) || !isInteger(p.countType))
          fail("list count type must be an integer type, not '" + countType + "'");
        if (!parseScalarType(itemType, p.type)) fail("unknown property type '" + itemType + "'");
      } else {
        words >> p.name;
        if (!parseScalarType(type, p.type)) fail("unknown property type '" + type + "'");
      }
      if (p.name.empty()) fail("property without a name");
      header.elements.back().properties.push_back(p);
    } else if (keyword == "end_header") {
      if (!sawFormat) fail("the header has no 'format' line");
      header.endLine = lineNo;
      return header;
    } else {
      fail("unknown header keyword '" + keyword + "'");
    }
  }
  throw InputError({path, lineNo}, lineNo == 0 ? "empty file" : "the header has no 'end_header' line");
}

// Values of ASCII elements, one element per line.
class AsciiSource {
 public:
  AsciiSource(std::istream& in, std::string path, int headerLines) : in_(in), path_(std::move(path)), line_(headerLines) {}

  void beginElement(const PlyElement& e, size_t index) {
    element_ = &e;
    index_ = index;
    if (!std::getline(in_, text_)) {
      throw InputError({path_, line_ + 1}, "the file ends after " + std::to_string(index) + " of the " +
                                               std::to_string(e.count) + " " + e.name +
                                               " elements the header declares (truncated file?)");
    }
    ++line_;
    if (!text_.empty() && text_.back() == '\r') text_.pop_back();
    pos_ = 0;
  }

  double scalar(ScalarType type) {
    skipSpace();
    if (pos_ >= text_.size()) wrongValueCount();
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    double value = 0;
    std::from_chars_result r;
    if (isInteger(type)) {
      long long i = 0;
      r = std::from_chars(first, last, i);
      value = double(i);
    } else {
      r = std::from_chars(first, last, value);
    }
    if (r.ec != std::errc() || (r.ptr != last && *r.ptr != ' ' && *r.ptr != '\t')) {
      const char* end = first;
      while (end != last && *end != ' ' && *end != '\t') ++end;
      fail("'" + std::string(first, end) + "' is not a valid " + (isInteger(type) ? "integer" : "number"));
    }
    pos_ = size_t(r.ptr - text_.data());
    return value;
  }

  void endElement() {
    skipSpace();
    if (pos_ < text_.size()) wrongValueCount();
  }

  // Anything but blank lines after the last element means the header's counts are wrong.
  void finish() {
    while (std::getline(in_, text_)) {
      ++line_;
      if (text_.find_first_not_of(" \t\r") != std::string::npos)
        throw InputError({path_, line_}, "data after the last element the header declares");
    }
  }

  [[noreturn]] void fail(const std::string& msg) const {
    throw InputError({path_, line_}, element_->name + " " + std::to_string(index_) + ": " + msg);
  }
  int line() const { return line_; }

 private:
  void skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  [[noreturn]] void wrongValueCount() const {
    std::istringstream words(text_);
    size_t n = 0;
    for (std::string w; words >> w;) ++n;
    fail("the line has " + std::to_string(n) + " values, which does not match the header's properties of '" +
         element_->name + "' (do the header's element counts match the file?)");
  }

  std::istream& in_;
  std::string path_;
  int line_;
  std::string text_;
  size_t pos_ = 0;
  const PlyElement* element_ = nullptr;
  size_t index_ = 0;
};

// Values of binary little-endian elements, read through a large buffer.
class BinarySource {
 public:
  BinarySource(std::istream& in, std::string path) : in_(in), path_(std::move(path)), buffer_(1 << 20) {}

  void beginElement(const PlyElement& e, size_t index) {
    element_ = &e;
    index_ = index;
  }

  double scalar(ScalarType type) {
    switch (type) {
      case ScalarType::Int8: return read<int8_t>();
      case ScalarType::UInt8: return read<uint8_t>();
      case ScalarType::Int16: return read<int16_t>();
      case ScalarType::UInt16: return read<uint16_t>();
      case ScalarType::Int32: return read<int32_t>();
      case ScalarType::UInt32: return read<uint32_t>();
      case ScalarType::Float32: return read<float>();
      case ScalarType::Float64: return read<double>();
    }
    return 0;
  }

  void endElement() {}
  // Trailing bytes are left alone: binary writers sometimes pad.
  void finish() {}

  [[noreturn]] void fail(const std::string& msg) const {
    throw InputError({path_, 0}, element_->name + " " + std::to_string(index_) + ": " + msg);
  }
  int line() const { return 0; }

 private:
  template <typename T> T read() {
    if (end_ - pos_ < sizeof(T)) refill(sizeof(T));
    T v;
    std::memcpy(&v, buffer_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  void refill(size_t need) {
    std::memmove(buffer_.data(), buffer_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
    in_.read(buffer_.data() + end_, std::streamsize(buffer_.size() - end_));
    end_ += size_t(in_.gcount());
    if (end_ < need) {
      throw InputError({path_, 0}, "the file ends inside " + element_->name + " " + std::to_string(index_) + " of " +
                                       std::to_string(element_->count) + " (truncated file?)");
    }
  }

  std::istream& in_;
  std::string path_;
  std::vector<char> buffer_;
  size_t pos_ = 0, end_ = 0;
  const PlyElement* element_ = nullptr;
  size_t index_ = 0;
};

// What each vertex property is used for.
enum VertexRole { kX, kY, kZ, kNX, kNY, kNZ, kH, kMu, kHeight, kRoleCount, kIgnored = -1 };
const char* const kRoleNames[kRoleCount] = {"x", "y", "z", "normal x", "normal y", "normal z", "H", "mu", "height"};

std::vector<int> vertexRoles(const PlyElement& e, const std::string& path) {
  auto find = [&](const char* name) -> int {
    for (size_t i = 0; i < e.properties.size(); ++i)
      if (e.properties[i].name == name && !e.properties[i].isList) return int(i);
    return -1;
  };
  std::vector<int> roles(e.properties.size(), kIgnored);
  auto assign = [&](const char* name, int role) {
    int i = find(name);
    if (i >= 0) roles[i] = role;
    return i >= 0;
  };
  for (const char* axis : {"x", "y", "z"})
    if (!assign(axis, kX + (axis[0] - 'x')))
      throw InputError({path, e.line}, std::string("element vertex has no float property '") + axis + "'");
  bool out = find("out1") >= 0 && find("out2") >= 0 && find("out3") >= 0;
  bool n = find("nx") >= 0 && find("ny") >= 0 && find("nz") >= 0;
  if (!out && !n)
    throw InputError({path, e.line}, "element vertex has no vane normal (properties out1 out2 out3, or nx ny nz)");
  if (out) {
    assign("out1", kNX); assign("out2", kNY); assign("out3", kNZ);
  } else {
    assign("nx", kNX); assign("ny", kNY); assign("nz", kNZ);
  }
  assign("H", kH);
  assign("mu", kMu);
  assign("height", kHeight);
  return roles;
}

template <typename Source> void skipElement(Source& src, const PlyElement& e) {
  for (size_t i = 0; i < e.count; ++i) {
    src.beginElement(e, i);
    for (const PlyProperty& p : e.properties) {
      size_t n = p.isList ? size_t(src.scalar(p.countType)) : 1;
      for (size_t k = 0; k < n; ++k) src.scalar(p.type);
    }
    src.endElement();
  }
}

template <typename Source> void readVertices(Source& src, const PlyElement& e, FeatherPlyData& out) {
  std::vector<int> roles = vertexRoles(e, out.path);
  auto hasRole = [&](int role) { return std::find(roles.begin(), roles.end(), role) != roles.end(); };
  out.positions.resize(e.count);
  out.normals.resize(e.count);
  if (hasRole(kH)) out.barbuleH.resize(e.count);
  if (hasRole(kMu)) out.barbuleMu.resize(e.count);
  if (hasRole(kHeight)) out.barbuleHeight.resize(e.count);
  for (size_t i = 0; i < e.count; ++i) {
    src.beginElement(e, i);
    float v[kRoleCount] = {};
    for (size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      size_t n = p.isList ? size_t(src.scalar(p.countType)) : 1;
      for (size_t j = 0; j < n; ++j) {
        double value = src.scalar(p.type);
        if (roles[k] == kIgnored) continue;
        v[roles[k]] = float(value);
        if (!std::isfinite(v[roles[k]])) src.fail(std::string("property '") + p.name + "' is not a finite float");
      }
    }
    src.endElement();
    Vec3 normal(v[kNX], v[kNY], v[kNZ]);
    if (!(lengthSquared(normal) > 0.0f)) src.fail("the vane normal is zero");
    out.positions[i] = Vec3(v[kX], v[kY], v[kZ]);
    out.normals[i] = normalize(normal);
    if (!out.barbuleH.empty()) out.barbuleH[i] = v[kH];
    if (!out.barbuleMu.empty()) out.barbuleMu[i] = v[kMu];
    if (!out.barbuleHeight.empty()) out.barbuleHeight[i] = v[kHeight];
  }
}

template <typename Source> void readFaces(Source& src, const PlyElement& e, FeatherPlyData& out) {
  int list = -1;
  for (size_t i = 0; i < e.properties.size(); ++i)
    if (e.properties[i].isList && (e.properties[i].name == "vertex_indices" || e.properties[i].name == "vertex_index"))
      list = int(i);
  if (list < 0) throw InputError({out.path, e.line}, "element face has no list property 'vertex_indices'");
  if (!isInteger(e.properties[list].type))
    throw InputError({out.path, e.line}, "face vertex indices must be integers");
  out.barbIndices.reserve(e.count * kBarbVertices);
  const size_t vertexCount = out.positions.size();
  for (size_t i = 0; i < e.count; ++i) {
    src.beginElement(e, i);
    if (i == 0) out.firstFaceLine = src.line();
    for (size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      size_t n = p.isList ? size_t(src.scalar(p.countType)) : 1;
      if (int(k) == list && n != size_t(kBarbVertices))
        src.fail("has " + std::to_string(n) + " vertex indices; a barb is a polyline of exactly " +
                 std::to_string(kBarbVertices));
      for (size_t j = 0; j < n; ++j) {
        double value = src.scalar(p.type);
        if (int(k) != list) continue;
        if (value < 0 || value >= double(vertexCount))
          src.fail("vertex index " + std::to_string(static_cast<long long>(value)) + " is out of range (the file has " +
                   std::to_string(vertexCount) + " vertices)");
        out.barbIndices.push_back(uint32_t(value));
      }
    }
    src.endElement();
  }
}

template <typename Source> void readBody(Source& src, const PlyHeader& header, FeatherPlyData& out) {
  bool sawVertex = false, sawFace = false;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex" && !sawVertex) {
      readVertices(src, e, out);
      sawVertex = true;
    } else if (e.name == "face" && !sawFace) {
      if (!sawVertex) throw InputError({out.path, e.line}, "element face must come after element vertex");
      readFaces(src, e, out);
      sawFace = true;
    } else {
      skipElement(src, e);
    }
  }
  if (!sawVertex) throw InputError({out.path, header.endLine}, "the file has no element vertex");
  if (!sawFace) throw InputError({out.path, header.endLine}, "the file has no element face (the barbs)");
  src.finish();
}

}  // namespace

SourceLocation FeatherPlyData::faceLocation(size_t i) const {
  return {path, firstFaceLine > 0 ? firstFaceLine + int(i) : 0};
}

bool FeatherPlyData::barbsAreSequential() const {
  if (barbIndices.size() != positions.size()) return false;
  for (size_t i = 0; i < barbIndices.size(); ++i)
    if (barbIndices[i] != i) return false;
  return true;
}

FeatherPlyData readFeatherPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0}, "cannot open the feather PLY file");
  FeatherPlyData data;
  data.path = path;
  PlyHeader header = readHeader(in, path);
  if (header.binary) {
    BinarySource src(in, path);
    readBody(src, header, data);
  } else {
    AsciiSource src(in, path, header.endLine);
    readBody(src, header, data);
  }
  return data;
}

}  // namespace columba
