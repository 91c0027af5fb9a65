#include "io/ply_file.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace columba {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "binary PLY reading assumes a little-endian host");

bool isIntegerType(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

namespace {

size_t binarySize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 1;
}

// The fewest bytes one record of `e` can take: binary, its scalars and list counts (lists may be
// empty); ASCII, a digit and a separator per value, or the line break of an empty record.
size_t minimumRecordBytes(const PlyElement& e, bool binary) {
  if (!binary) return std::max<size_t>(1, 2 * e.properties.size());
  size_t bytes = 0;
  for (const PlyProperty& p : e.properties) bytes += binarySize(p.isList ? p.countType : p.type);
  return bytes;
}

}  // namespace

int PlyElement::findScalar(const std::string& name) const {
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == name && !properties[i].isList) return int(i);
  return -1;
}

// The values of one record after another, and errors at the current record.
class PlySource {
 public:
  virtual ~PlySource() = default;
  virtual void beginRecord(const PlyElement& e, size_t index) = 0;
  virtual double scalar(PlyType type) = 0;
  virtual void endRecord() = 0;
  virtual void finish() = 0;
  virtual int line() const = 0;
  // An error about the current record: "face 12: ...", at its line (ASCII) or without one.
  virtual InputError recordError(const std::string& msg) const = 0;
  [[noreturn]] void fail(const std::string& msg) const { throw recordError(msg); }
};

namespace {

bool parseType(const std::string& name, PlyType& type) {
  static const std::pair<const char*, PlyType> kNames[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [n, t] : kNames)
    if (name == n) {
      type = t;
      return true;
    }
  return false;
}

// Values of ASCII records, one record per line.
class AsciiSource : public PlySource {
 public:
  AsciiSource(std::istream& in, std::string path, int headerLines)
      : in_(in), path_(std::move(path)), line_(headerLines) {}

  void beginRecord(const PlyElement& e, size_t index) override {
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

  double scalar(PlyType type) override {
    skipSpace();
    if (pos_ >= text_.size()) wrongValueCount();
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    double value = 0;
    std::from_chars_result r;
    if (isIntegerType(type)) {
      long long i = 0;
      r = std::from_chars(first, last, i);
      value = double(i);
    } else {
      r = std::from_chars(first, last, value);
    }
    if (r.ec != std::errc() || (r.ptr != last && *r.ptr != ' ' && *r.ptr != '\t')) {
      const char* end = first;
      while (end != last && *end != ' ' && *end != '\t') ++end;
      fail("'" + std::string(first, end) + "' is not a valid " + (isIntegerType(type) ? "integer" : "number"));
    }
    pos_ = size_t(r.ptr - text_.data());
    return value;
  }

  void endRecord() override {
    skipSpace();
    if (pos_ < text_.size()) wrongValueCount();
  }

  void finish() override {
    while (std::getline(in_, text_)) {
      ++line_;
      if (text_.find_first_not_of(" \t\r") != std::string::npos)
        throw InputError({path_, line_}, "data after the last element the header declares");
    }
  }

  InputError recordError(const std::string& msg) const override {
    return InputError({path_, line_}, element_->name + " " + std::to_string(index_) + ": " + msg);
  }
  int line() const override { return line_; }

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

// Values of binary little-endian records, read through a large buffer.
class BinarySource : public PlySource {
 public:
  BinarySource(std::istream& in, std::string path) : in_(in), path_(std::move(path)), buffer_(1 << 20) {}

  void beginRecord(const PlyElement& e, size_t index) override {
    element_ = &e;
    index_ = index;
  }

  double scalar(PlyType type) override {
    switch (type) {
      case PlyType::Int8:
        return read<int8_t>();
      case PlyType::UInt8:
        return read<uint8_t>();
      case PlyType::Int16:
        return read<int16_t>();
      case PlyType::UInt16:
        return read<uint16_t>();
      case PlyType::Int32:
        return read<int32_t>();
      case PlyType::UInt32:
        return read<uint32_t>();
      case PlyType::Float32:
        return read<float>();
      case PlyType::Float64:
        return read<double>();
    }
    return 0;
  }

  void endRecord() override {}
  // Trailing bytes are left alone: binary writers sometimes pad.
  void finish() override {}

  InputError recordError(const std::string& msg) const override {
    return InputError({path_, 0}, element_->name + " " + std::to_string(index_) + ": " + msg);
  }
  int line() const override { return 0; }

 private:
  template <typename T>
  T read() {
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

}  // namespace

PlyReader::PlyReader(const std::string& path, const std::string& description)
    : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw InputError({path, 0}, "cannot open the " + description);
  std::string line;
  int lineNo = 0;
  bool sawFormat = false, binary = false;
  auto fail = [&](const std::string& msg) { throw InputError({path, lineNo}, msg); };
  while (std::getline(in_, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (lineNo == 1) {
      if (keyword != "ply") fail("not a PLY file (the first line must be 'ply')");
      continue;
    }
    if (keyword == "comment") {
      std::string text;
      std::getline(words >> std::ws, text);
      comments_.push_back({text, lineNo});
      continue;
    }
    if (keyword.empty() || keyword == "obj_info") continue;
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format == "ascii")
        binary = false;
      else if (format == "binary_little_endian")
        binary = true;
      else
        fail("unsupported PLY format '" + format + "' (ascii or binary_little_endian)");
      sawFormat = true;
    } else if (keyword == "element") {
      PlyElement e;
      long long count = -1;
      words >> e.name >> count;
      if (e.name.empty() || count < 0 || words.fail()) fail("malformed element declaration: '" + line + "'");
      e.count = size_t(count);
      e.line = lineNo;
      elements_.push_back(std::move(e));
    } else if (keyword == "property") {
      if (elements_.empty()) fail("property declared before any element");
      PlyProperty p;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType >> p.name;
        p.isList = true;
        if (!parseType(countType, p.countType) || !isIntegerType(p.countType))
          fail("list count type must be an integer type, not '" + countType + "'");
        if (!parseType(itemType, p.type)) fail("unknown property type '" + itemType + "'");
      } else {
        words >> p.name;
        if (!parseType(type, p.type)) fail("unknown property type '" + type + "'");
      }
      if (p.name.empty()) fail("property without a name");
      elements_.back().properties.push_back(p);
    } else if (keyword == "end_header") {
      if (!sawFormat) fail("the header has no 'format' line");
      endHeaderLine_ = lineNo;
      checkCountsFit(binary);
      if (binary)
        source_ = std::make_unique<BinarySource>(in_, path_);
      else
        source_ = std::make_unique<AsciiSource>(in_, path_, lineNo);
      return;
    } else {
      fail("unknown header keyword '" + keyword + "'");
    }
  }
  throw InputError({path, lineNo}, lineNo == 0 ? "empty file" : "the header has no 'end_header' line");
}

PlyReader::~PlyReader() = default;

void PlyReader::checkCountsFit(bool binary) {
  const std::streampos dataStart = in_.tellg();
  in_.seekg(0, std::ios::end);
  const std::streampos fileEnd = in_.tellg();
  in_.seekg(dataStart);
  if (dataStart < 0 || fileEnd < 0 || !in_)
    throw InputError({path_, endHeaderLine_}, "cannot find the size of the file");
  // The last ASCII record may end without a line break.
  const size_t bytesLeft = size_t(fileEnd - dataStart), budget = bytesLeft + (binary ? 0 : 1);
  size_t needed = 0;
  for (const PlyElement& e : elements_) {
    if (e.count == 0) continue;
    const size_t recordBytes = minimumRecordBytes(e, binary);
    if (recordBytes == 0)
      throw headerError(e, "element " + e.name + " declares " + std::to_string(e.count) +
                               " records but has no properties to store them");
    if (e.count > (budget - needed) / recordBytes)
      throw headerError(e, "element " + e.name + " declares " + std::to_string(e.count) + " " + e.name +
                               " records of at least " + std::to_string(recordBytes) +
                               " bytes each, but the file has " + std::to_string(bytesLeft) +
                               " bytes left after the header");
    needed += e.count * recordBytes;
  }
}

InputError PlyReader::headerError(const PlyElement& e, const std::string& message) const {
  return InputError({path_, e.line}, message);
}

void PlyReader::next() {
  if (started_) ++index_;
  started_ = true;
  while (element_ < elements_.size() && index_ >= elements_[element_].count) {
    ++element_;
    index_ = 0;
  }
  if (element_ == elements_.size()) throw std::logic_error("PlyReader::next called after the last record");
  const PlyElement& e = elements_[element_];
  values_.resize(e.properties.size());
  source_->beginRecord(e, index_);
  for (size_t k = 0; k < e.properties.size(); ++k) {
    const PlyProperty& p = e.properties[k];
    values_[k].clear();
    double n = p.isList ? source_->scalar(p.countType) : 1;
    if (n < 0) fail("property '" + p.name + "' has a negative list length");
    for (size_t j = 0; j < size_t(n); ++j) values_[k].push_back(source_->scalar(p.type));
  }
  source_->endRecord();
}

int PlyReader::line() const { return source_->line(); }

void PlyReader::fail(const std::string& message) const { throw source_->recordError(message); }

void PlyReader::finish() { source_->finish(); }

int PlyReader::vertexIndexList(const PlyElement& face) const {
  for (size_t i = 0; i < face.properties.size(); ++i) {
    const PlyProperty& p = face.properties[i];
    if (!p.isList || (p.name != "vertex_indices" && p.name != "vertex_index")) continue;
    if (!isIntegerType(p.type)) throw headerError(face, face.name + " vertex indices must be integers");
    return int(i);
  }
  throw headerError(face, "element " + face.name + " has no list property 'vertex_indices'");
}

uint32_t PlyReader::vertexIndex(double value, size_t vertexCount) const {
  if (value < 0 || value >= double(vertexCount))
    fail("vertex index " + std::to_string(static_cast<long long>(value)) + " is out of range (the file has " +
         std::to_string(vertexCount) + " vertices)");
  return uint32_t(value);
}

}  // namespace columba
