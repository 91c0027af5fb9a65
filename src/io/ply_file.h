#pragma once
// Generic PLY reading: the header's elements and properties, then the elements' records streamed
// in file order with every value converted to double (exact for all PLY scalar types).
//
// ASCII (one record per line) and binary_little_endian. Every problem is an InputError naming
// the file and the line (header, ASCII records) or the record's element and index (binary).
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>
#include "core/error.h"

namespace columba {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool isIntegerType(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the value, or of a list's items
  bool isList = false;
  PlyType countType = PlyType::UInt8;
};

// Where record values come from: ASCII text or little-endian binary (defined in ply_file.cpp).
class PlySource;

struct PlyElement {
  std::string name;
  size_t count = 0;
  int line = 0;  // header line that declared it
  std::vector<PlyProperty> properties;

  // Index of the scalar (non-list) property called `name`, or -1.
  int findScalar(const std::string& name) const;
};

// A `comment` line of the header: its text after the keyword, and its line.
struct PlyComment {
  std::string text;
  int line = 0;
};

class PlyReader {
 public:
  // Opens `path` and reads its header; `description` names the file in "cannot open" errors.
  // Element counts that the rest of the file is too short to hold are an error here.
  PlyReader(const std::string& path, const std::string& description);
  ~PlyReader();
  PlyReader(const PlyReader&) = delete;  // the source reads from in_
  PlyReader& operator=(const PlyReader&) = delete;

  const std::string& path() const { return path_; }
  const std::vector<PlyElement>& elements() const { return elements_; }
  int endHeaderLine() const { return endHeaderLine_; }
  const std::vector<PlyComment>& comments() const { return comments_; }
  // An error about element `e` as the header declares it.
  InputError headerError(const PlyElement& e, const std::string& message) const;

  // Reads the next record. Records come in header order: every record of one element, then
  // those of the next; the caller reads exactly as many as the header declares.
  void next();
  const PlyElement& element() const { return elements_[element_]; }
  size_t index() const { return index_; }  // of the current record within its element
  int line() const;                        // of the current record (ASCII), or 0 (binary)
  // Values of the current record's property `property` (an index into element().properties).
  double scalar(size_t property) const { return values_[property][0]; }
  const std::vector<double>& list(size_t property) const { return values_[property]; }
  // Throws an InputError about the current record ("face 12: ...") at its line or index.
  [[noreturn]] void fail(const std::string& message) const;
  // Checks that nothing but blank lines follow the last record (ASCII: otherwise the header's
  // counts are wrong; binary files may be padded and are not checked).
  void finish();

  // The PLY convention for faces: the index of `face`'s integer list property
  // `vertex_indices` (or `vertex_index`); a header error if there is none.
  int vertexIndexList(const PlyElement& face) const;
  // One entry of such a list as a vertex index, checked against `vertexCount`.
  uint32_t vertexIndex(double value, size_t vertexCount) const;

 private:
  // Throws a header error for an element whose declared records cannot fit in the rest of the
  // file, so that the counts are safe to allocate for.
  void checkCountsFit(bool binary);

  std::string path_;
  std::ifstream in_;
  std::vector<PlyElement> elements_;
  std::vector<PlyComment> comments_;
  int endHeaderLine_ = 0;
  std::unique_ptr<PlySource> source_;
  size_t element_ = 0, index_ = 0;
  bool started_ = false;
  std::vector<std::vector<double>> values_;  // per property of the current record
};

}  // namespace columba
