#include "distribute/pieces.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>

namespace columba {

namespace {

bool parseInt(const std::string& text, long long& value) {
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

// "a,b,c" as integers; false if any is not one.
bool parseIntList(const std::string& text, std::vector<int>& values) {
  values.clear();
  size_t start = 0;
  while (start <= text.size()) {
    size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    long long value = 0;
    if (!parseInt(item, value) || value < 0 || value > 1 << 30) return false;
    values.push_back(int(value));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return !values.empty();
}

std::string joinInts(const std::vector<int>& values) {
  std::string text;
  for (int v : values) text += (text.empty() ? "" : ",") + std::to_string(v);
  return text;
}

}  // namespace

PieceIndex parsePieceIndex(const std::string& option, const std::string& text, int most) {
  const size_t slash = text.find('/');
  long long k = 0, n = 0;
  if (slash == std::string::npos || !parseInt(text.substr(0, slash), k) || !parseInt(text.substr(slash + 1), n))
    throw std::runtime_error(fmt::format("{} expects K/N (the K-th of N pieces, such as 2/4), not '{}'", option, text));
  if (n < 1 || n > most)
    throw std::runtime_error(fmt::format("{} {}: the number of pieces must be between 1 and {}", option, text, most));
  if (k < 1 || k > n)
    throw std::runtime_error(fmt::format("{} {}: K must be between 1 and {} (pieces count from 1)", option, text, n));
  return {int(k), int(n)};
}

std::vector<int> balancedRowBands(const std::vector<uint64_t>& rowCosts, int parts) {
  const int rows = int(rowCosts.size());
  if (parts < 1 || parts > rows)
    throw std::runtime_error(
        fmt::format("cannot split an image of {} rows into {} parts (at most one part a row)", rows, parts));
  std::vector<double> prefix(size_t(rows) + 1, 0.0);  // cost of rows [0, y)
  for (int y = 0; y < rows; ++y) prefix[size_t(y) + 1] = prefix[size_t(y)] + double(rowCosts[size_t(y)]) + 1.0;
  const double total = prefix.back();
  std::vector<int> bounds(size_t(parts) + 1, 0);
  bounds.back() = rows;
  for (int k = 1; k < parts; ++k) {
    const double target = total * k / parts;
    // The row boundary whose prefix cost is closest to the target, leaving at least one row for
    // every band before and after it.
    int lo = bounds[size_t(k) - 1] + 1, hi = rows - (parts - k);
    int y = int(std::lower_bound(prefix.begin() + lo, prefix.begin() + hi + 1, target) - prefix.begin());
    if (y > hi) y = hi;
    if (y > lo && target - prefix[size_t(y) - 1] < prefix[size_t(y)] - target) --y;
    bounds[size_t(k)] = y;
  }
  return bounds;
}

PixelRect partWindow(const std::vector<int>& bounds, int part, int width) {
  if (part < 1 || part + 1 > int(bounds.size())) throw std::runtime_error("part index outside the bands");
  return {0, bounds[size_t(part) - 1], width, bounds[size_t(part)]};
}

std::pair<int, int> passSamples(const PieceIndex& pass, int spp) {
  if (spp < pass.count)
    throw std::runtime_error(
        fmt::format("cannot split {} samples per pixel into {} passes (at least one sample a pass)", spp, pass.count));
  auto start = [&](int k) { return int(int64_t(spp) * k / pass.count); };
  return {start(pass.index - 1), start(pass.index)};
}

std::string pieceFileName(const std::string& output, const std::optional<PieceIndex>& part,
                          const std::optional<PieceIndex>& pass) {
  std::filesystem::path path(output);
  path.replace_extension();
  std::string name = path.string();
  if (part) name += fmt::format(".part{}of{}", part->index, part->count);
  if (pass) name += fmt::format(".pass{}of{}", pass->index, pass->count);
  return name + ".exr";
}

std::string partialFileName(const std::string& file) {
  std::filesystem::path path(file);
  std::filesystem::path extension = path.extension();
  return path.replace_extension().concat(".partial").concat(extension.string()).string();
}

std::string textHash(const std::string& bytes) {
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return fmt::format("{:016x}", hash);
}

ImageMetadata pieceMetadata(const PieceInfo& info) {
  ImageMetadata metadata = {{"Scene", info.scene},
                            {"Scene hash", info.sceneHash},
                            {"Defines", info.defines},
                            {"Samples per pixel", std::to_string(info.spp)},
                            {"Seed", std::to_string(info.seed)},
                            {"Frame size", fmt::format("{}x{}", info.frameWidth, info.frameHeight)},
                            {"Render time", fmt::format("{:.3f} s", info.seconds)},
                            {"Status", info.complete ? "complete" : "interrupted"}};
  if (!info.spectral.empty()) metadata.emplace_back("Spectral channels", info.spectral);
  if (!info.observer.empty()) metadata.emplace_back("Observer", info.observer);
  if (info.part) {
    metadata.emplace_back("Part", info.part->str());
    metadata.emplace_back("Part bounds", joinInts(info.partBounds));
  }
  if (info.pass) {
    metadata.emplace_back("Pass", info.pass->str());
    metadata.emplace_back("Pass samples", fmt::format("{}:{}", info.sampleBegin, info.sampleEnd));
  }
  return metadata;
}

PieceInfo pieceInfoFromFile(const std::string& path, const EXRImageFile& file) {
  auto fail = [&](const std::string& what) {
    return std::runtime_error(fmt::format("'{}' is not a piece of a Columba render: {}", path, what));
  };
  auto has = [&](const char* name) {
    for (const auto& entry : file.metadata)
      if (entry.first == name) return true;
    return false;
  };
  auto get = [&](const char* name) {
    if (!has(name)) throw fail(fmt::format("it has no '{}' attribute", name));
    return metadataValue(file.metadata, name);
  };
  auto integer = [&](const char* name, long long lowest) {
    long long value = 0;
    std::string text = get(name);
    if (!parseInt(text, value) || value < lowest)
      throw fail(fmt::format("its '{}' attribute is '{}', not a whole number", name, text));
    return value;
  };
  PieceInfo info;
  info.scene = get("Scene");
  info.sceneHash = has("Scene hash") ? get("Scene hash") : "";
  info.defines = get("Defines");
  info.seed = uint64_t(integer("Seed", 0));
  info.spp = int(integer("Samples per pixel", 1));
  info.frameWidth = file.frameWidth;
  info.frameHeight = file.frameHeight;
  if (has("Frame size")) {
    std::string size = get("Frame size");
    size_t x = size.find('x');
    long long w = 0, h = 0;
    if (x == std::string::npos || !parseInt(size.substr(0, x), w) || !parseInt(size.substr(x + 1), h))
      throw fail("its 'Frame size' attribute is '" + size + "', not WIDTHxHEIGHT");
    if (w != file.frameWidth || h != file.frameHeight)
      throw fail(fmt::format("its 'Frame size' {} is not its display window of {} x {}", size, file.frameWidth,
                             file.frameHeight));
  }
  info.spectral = has("Spectral channels") ? get("Spectral channels") : "";
  info.observer = has("Observer") ? get("Observer") : "";
  const std::string status = get("Status");
  info.complete = status == "complete";
  info.seconds = has("Render time") ? std::atof(get("Render time").c_str()) : 0.0;
  info.window = file.dataWindow;
  if (has("Part")) {
    info.part = parsePieceIndex("its 'Part' attribute", get("Part"), 1 << 20);
    // Every band's rows, increasing from the frame's first row to its last: the merge looks up
    // the rows of every band in the frame.
    const std::vector<int>& bounds = info.partBounds;
    if (!parseIntList(get("Part bounds"), info.partBounds) || int(bounds.size()) != info.part->count + 1 ||
        bounds.front() != 0 || bounds.back() != info.frameHeight ||
        std::adjacent_find(bounds.begin(), bounds.end(), std::greater_equal<int>()) != bounds.end())
      throw fail(
          fmt::format("its 'Part bounds' attribute is '{}', not {} row numbers increasing from 0 to the "
                      "frame's height {}",
                      get("Part bounds"), info.part->count + 1, info.frameHeight));
  }
  if (has("Pass")) {
    info.pass = parsePieceIndex("its 'Pass' attribute", get("Pass"), 1 << 20);
    std::string samples = get("Pass samples");
    size_t colon = samples.find(':');
    long long b = 0, e = 0;
    if (colon == std::string::npos || !parseInt(samples.substr(0, colon), b) ||
        !parseInt(samples.substr(colon + 1), e) || b < 0 || e <= b || e > info.spp)
      throw fail("its 'Pass samples' attribute is '" + samples + "', not BEGIN:END within the samples per pixel");
    info.sampleBegin = int(b);
    info.sampleEnd = int(e);
  } else {
    info.sampleBegin = 0;
    info.sampleEnd = info.spp;
  }
  return info;
}

}  // namespace columba
