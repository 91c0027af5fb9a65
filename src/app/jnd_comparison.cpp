#include "app/jnd_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/number_text.h"
#include "io/output_directory.h"
#include "vision/colour_distance.h"
#include "vision/observer_table.h"

namespace columba {

namespace {
// The index in `image`'s cone channels of each of the observer's chromatic channels.
std::vector<size_t> channelIndices(const Image& image, const Observer& observer, const std::string& path) {
  std::vector<size_t> indices;
  for (const std::string& name : observer.channels) {
    const auto it = std::find(image.cones.names.begin(), image.cones.names.end(), name);
    if (it == image.cones.names.end())
      throw std::runtime_error(
          fmt::format("'{}' has no {} channel, which the {} observer needs (a render whose film "
                      "has observer '{}' records it)",
                      path, name, observer.name, observer.name));
    indices.push_back(size_t(it - image.cones.names.begin()));
  }
  return indices;
}

// The chromatic catches of pixel p, or nothing where any is not positive (no light: no colour).
std::optional<ConeCatches> pixelCatches(const Image& image, const std::vector<size_t>& indices, size_t p) {
  ConeCatches c;
  for (size_t i : indices) {
    const double q = image.cones.values[p * image.cones.count() + i];
    if (!(q > 0.0) || !std::isfinite(q)) return std::nullopt;
    c.chromatic.push_back(q);
  }
  return c;
}

std::optional<ConeCatches> regionCatches(const Image& image, const std::vector<size_t>& indices, const PixelRect& r) {
  ConeCatches c;
  c.chromatic.assign(indices.size(), 0.0);
  const double n = double(r.width()) * double(r.height());
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (size_t k = 0; k < indices.size(); ++k)
        c.chromatic[k] +=
            image.cones.values[(size_t(y) * size_t(image.width) + size_t(x)) * image.cones.count() + indices[k]] / n;
  for (double q : c.chromatic)
    if (!(q > 0.0) || !std::isfinite(q)) return std::nullopt;
  return c;
}

// The observer the comparison uses: `observer`, else the one `a`'s metadata names.
Observer jndObserver(const EXRImageFile& a, const std::string& pathA, const std::string& observer) {
  std::string name = observer;
  if (name.empty()) {
    const std::string recorded = metadataValue(a.metadata, "Observer");
    name = recorded.substr(0, recorded.find(':'));
    if (name.empty())
      throw std::runtime_error(
          fmt::format("'{}' names no observer (it has no Observer attribute): give --observer", pathA));
  }
  if (!namesObserverTable(name) && !isBuiltinObserver(name))
    throw std::runtime_error(
        fmt::format("unknown observer '{}' (known: {}; or a table of sensitivities, FILE.csv: "
                    "give the table the image was rendered with as --observer)",
                    name, builtinObserverNames()));
  return observerNamedOrTabulated(name);
}
}  // namespace

PixelRect parsePixelRect(const std::string& text, int width, int height, const std::string& what) {
  std::vector<int> v;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) {
    const size_t first = part.find_first_not_of(' '), last = part.find_last_not_of(' ');
    const std::optional<int> value =
        parseNumber<int>(first == std::string::npos ? "" : part.substr(first, last - first + 1));
    if (!value) throw std::runtime_error(fmt::format("{} '{}': '{}' is not an integer", what, text, part));
    v.push_back(*value);
  }
  if (v.size() != 4)
    throw std::runtime_error(fmt::format("{} '{}': give X0,Y0,X1,Y1 (pixels [X0, X1) x [Y0, Y1))", what, text));
  const PixelRect r{v[0], v[1], v[2], v[3]};
  if (r.x0 < 0 || r.y0 < 0 || r.x1 > width || r.y1 > height || r.empty())
    throw std::runtime_error(fmt::format("{} '{}' is not a non-empty rectangle inside the image of {} x {} pixels",
                                         what, text, width, height));
  return r;
}

void compareForBird(const EXRImageFile& a, const EXRImageFile& b, const std::string& pathA, const std::string& pathB,
                    const JndOptions& options) {
  const Observer observer = jndObserver(a, pathA, options.observer);
  const std::vector<size_t> ia = channelIndices(a.image, observer, pathA),
                            ib = channelIndices(b.image, observer, pathB);
  if (options.regionA) {
    const PixelRect ra = *options.regionA, rb = options.regionB ? *options.regionB : ra;
    const std::optional<ConeCatches> qa = regionCatches(a.image, ia, ra), qb = regionCatches(b.image, ib, rb);
    if (!qa || !qb) throw std::runtime_error("a region catches no light in some cone: its colour has no distance");
    fmt::print(
        "{} observer: dS = {:.3f} JND between the mean catches of [{}, {}) x [{}, {}) of '{}' and [{}, {}) x "
        "[{}, {}) of '{}'\n",
        observer.name, chromaticDistance(observer, *qa, *qb), ra.x0, ra.x1, ra.y0, ra.y1, pathA, rb.x0, rb.x1, rb.y0,
        rb.y1, pathB);
    return;
  }
  if (a.image.width != b.image.width || a.image.height != b.image.height)
    throw std::runtime_error(fmt::format("'{}' is {} x {} pixels but '{}' is {} x {}: compare regions (--region)",
                                         pathA, a.image.width, a.image.height, pathB, b.image.width, b.image.height));
  Image map(a.image.width, a.image.height);
  std::vector<double> distances;
  const size_t pixels = size_t(a.image.width) * size_t(a.image.height);
  for (size_t p = 0; p < pixels; ++p) {
    const std::optional<ConeCatches> qa = pixelCatches(a.image, ia, p), qb = pixelCatches(b.image, ib, p);
    if (!qa || !qb) continue;
    const double dS = chromaticDistance(observer, *qa, *qb);
    distances.push_back(dS);
    std::fill(&map.rgb[3 * p], &map.rgb[3 * p] + 3, float(dS));
  }
  if (distances.empty()) throw std::runtime_error("no pixel catches light in every cone of both images");
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  double mean = 0.0;
  for (double d : sorted) mean += d / double(sorted.size());
  auto quantile = [&](double q) { return sorted[std::min(sorted.size() - 1, size_t(q * double(sorted.size())))]; };
  fmt::print(
      "{} observer: dS per pixel over {} of {} pixels (the others catch no light in some cone): mean {:.3f}, "
      "median {:.3f}, 95th percentile {:.3f}, largest {:.3f} JND\n",
      observer.name, sorted.size(), pixels, mean, quantile(0.5), quantile(0.95), sorted.back());
  if (!options.output.empty()) {
    const std::string png = options.output.substr(0, options.output.size() - 4) + ".png";
    makeOutputDirectory(options.output, directoryOf(options.output));
    writeEXRAndPNG(options.output, png, map,
                   {{"Quantity", "receptor-noise-limited colour distance dS (JND) of each pixel's cone catches, " +
                                     observer.name + " observer; 0 where a pixel catches no light in some cone"},
                    {"Images", pathA + ", " + pathB}});
    fmt::print("wrote {}, {}\n", options.output, png);
  }
}

}  // namespace columba
