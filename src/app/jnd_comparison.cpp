#include "app/jnd_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/number_text.h"
#include "io/output_directory.h"
#include "vision/colour_distance.h"
#include "vision/human_colour_difference.h"
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

// The observer the comparison uses: `observer`, else the one `a`'s metadata names, else the CIE 1931
// observer whose RGB every render records.
// The observer an image's cone channels were rendered for, as its Observer attribute names it
// ("" for none).
std::string recordedObserver(const EXRImageFile& image) {
  const std::string recorded = metadataValue(image.metadata, "Observer");
  return recorded.substr(0, recorded.find(':'));
}

std::string observerName(const EXRImageFile& a, const std::string& observer) {
  if (!observer.empty()) return observer;
  const std::string name = recordedObserver(a);
  return name.empty() ? "cie1931" : name;
}

// Catches are read as the image records them: an observer's noise applied to another's catches
// would be a distance under a label that is not the image's.
void requireRenderedFor(const Observer& observer, const EXRImageFile& image, const std::string& path,
                        const std::string& given) {
  const std::string recorded = recordedObserver(image);
  if (!recorded.empty() && recorded != observer.name)
    throw std::runtime_error(
        fmt::format("'{}' records the catches of the {} observer (its Observer attribute), not of {}: compare it with "
                    "--observer {} (or render it for {})",
                    path, recorded, given.empty() ? "the " + observer.name + " observer" : "--observer " + given,
                    recorded, observer.name));
}

Observer birdObserver(const std::string& name) {
  if (!namesObserverTable(name) && !isBuiltinObserver(name))
    throw std::runtime_error(fmt::format(
        "unknown observer '{}' (known: cie1931, {}; or a table of sensitivities or of cone parameters, FILE.csv: "
        "give the table the image was rendered with as --observer)",
        name, builtinObserverNames()));
  return observerNamedOrTabulated(name);
}

// The regions the comparison reads, each checked against the image it is read from.
std::pair<PixelRect, PixelRect> regionsInside(const EXRImageFile& a, const EXRImageFile& b, const std::string& pathA,
                                              const std::string& pathB, const JndOptions& options) {
  const PixelRect ra = *options.regionA, rb = options.regionB ? *options.regionB : ra;
  auto requireInside = [](const PixelRect& r, const Image& image, const std::string& path, const char* what) {
    if (r.x0 < 0 || r.y0 < 0 || r.x1 > image.width || r.y1 > image.height || r.empty())
      throw std::runtime_error(fmt::format("{} [{}, {}) x [{}, {}) does not lie inside '{}', which is {} x {} pixels",
                                           what, r.x0, r.x1, r.y0, r.y1, path, image.width, image.height));
  };
  requireInside(ra, a.image, pathA, "--region");
  requireInside(rb, b.image, pathB,
                options.regionB ? "--region-b" : "--region (read from both images without --region-b)");
  return {ra, rb};
}

Vec3 rgbAt(const Image& image, size_t p) { return {image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]}; }

Vec3 regionMeanRGB(const Image& image, const PixelRect& r) {
  Vec3 sum(0.0f, 0.0f, 0.0f);
  const float n = float(r.width()) * float(r.height());
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) sum = sum + rgbAt(image, size_t(y) * size_t(image.width) + size_t(x)) / n;
  return sum;
}

bool finite(const Vec3& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

// Per-pixel distances summarised, printed after `what`, and written as a map where asked.
void reportPerPixel(const std::vector<double>& distances, size_t pixels, const Image& map, const std::string& what,
                    const std::string& skipped, const std::string& unit, const std::string& quantity,
                    const std::string& pathA, const std::string& pathB, const JndOptions& options) {
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  double mean = 0.0;
  for (double d : sorted) mean += d / double(sorted.size());
  auto quantile = [&](double q) { return sorted[std::min(sorted.size() - 1, size_t(q * double(sorted.size())))]; };
  fmt::print(
      "{} per pixel over {} of {} pixels{}: mean {:.3f}, median {:.3f}, 95th percentile {:.3f}, largest {:.3f} {}\n",
      what, sorted.size(), pixels, skipped, mean, quantile(0.5), quantile(0.95), sorted.back(), unit);
  if (options.output.empty()) return;
  const std::string png = pngBesideMap(options.output);
  makeOutputDirectory(options.output, directoryOf(options.output));
  writeEXRAndPNG(options.output, png, map, {{"Quantity", quantity}, {"Images", pathA + ", " + pathB}});
  fmt::print("wrote {}, {}\n", options.output, png);
}

// The human observer: CIEDE2000 between the images' RGB in CIELAB, RGB (1, 1, 1) the white.
void compareForHuman(const EXRImageFile& a, const EXRImageFile& b, const std::string& pathA, const std::string& pathB,
                     const JndOptions& options) {
  if (options.regionA) {
    const auto [ra, rb] = regionsInside(a, b, pathA, pathB, options);
    const CIELab la = labFromLinearRGB(regionMeanRGB(a.image, ra)), lb = labFromLinearRGB(regionMeanRGB(b.image, rb));
    const double dE76 = deltaE1976(la, lb);
    fmt::print(
        "cie1931 observer (CIELAB, white RGB 1): dE2000 = {:.3f}, dE*ab = {:.3f} (about {:.2f} JND at 2.3 a JND) "
        "between the mean colours of [{}, {}) x [{}, {}) of '{}' (L*a*b* {:.1f} {:.1f} {:.1f}) and [{}, {}) x "
        "[{}, {}) of '{}' (L*a*b* {:.1f} {:.1f} {:.1f})\n",
        deltaE2000(la, lb), dE76, dE76 / kJustNoticeableDeltaE1976, ra.x0, ra.x1, ra.y0, ra.y1, pathA, la.L, la.a, la.b,
        rb.x0, rb.x1, rb.y0, rb.y1, pathB, lb.L, lb.a, lb.b);
    return;
  }
  Image map(a.image.width, a.image.height);
  std::vector<double> distances;
  const size_t pixels = size_t(a.image.width) * size_t(a.image.height);
  for (size_t p = 0; p < pixels; ++p) {
    const Vec3 ca = rgbAt(a.image, p), cb = rgbAt(b.image, p);
    if (!finite(ca) || !finite(cb)) continue;
    const double dE = deltaE2000(labFromLinearRGB(ca), labFromLinearRGB(cb));
    distances.push_back(dE);
    std::fill(&map.rgb[3 * p], &map.rgb[3 * p] + 3, float(dE));
  }
  if (distances.empty()) throw std::runtime_error("no pixel of both images has a finite colour");
  reportPerPixel(distances, pixels, map, "cie1931 observer (CIELAB, white RGB 1): dE2000", "", "",
                 "CIEDE2000 colour difference of each pixel's RGB in CIELAB, RGB (1, 1, 1) the white; 0 where a "
                 "pixel is not finite",
                 pathA, pathB, options);
}
}  // namespace

std::string pngBesideMap(const std::string& exr) { return exr.substr(0, exr.size() - 4) + ".png"; }

PixelRect parsePixelRect(const std::string& text, const std::string& what) {
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
  if (r.x0 < 0 || r.y0 < 0 || r.empty())
    throw std::runtime_error(fmt::format("{} '{}' is not a non-empty rectangle of pixels", what, text));
  return r;
}

void compareColours(const EXRImageFile& a, const EXRImageFile& b, const std::string& pathA, const std::string& pathB,
                    const JndOptions& options) {
  if (!options.regionA && (a.image.width != b.image.width || a.image.height != b.image.height))
    throw std::runtime_error(fmt::format("'{}' is {} x {} pixels but '{}' is {} x {}: compare regions (--region)",
                                         pathA, a.image.width, a.image.height, pathB, b.image.width, b.image.height));
  const std::string name = observerName(a, options.observer);
  if (name == "cie1931") return compareForHuman(a, b, pathA, pathB, options);
  const Observer observer = birdObserver(name);
  requireRenderedFor(observer, a, pathA, options.observer);
  requireRenderedFor(observer, b, pathB, options.observer);
  const std::vector<size_t> ia = channelIndices(a.image, observer, pathA),
                            ib = channelIndices(b.image, observer, pathB);
  if (options.regionA) {
    const auto [ra, rb] = regionsInside(a, b, pathA, pathB, options);
    const std::optional<ConeCatches> qa = regionCatches(a.image, ia, ra), qb = regionCatches(b.image, ib, rb);
    if (!qa || !qb) throw std::runtime_error("a region catches no light in some cone: its colour has no distance");
    fmt::print(
        "{} observer: dS = {:.3f} JND between the mean catches of [{}, {}) x [{}, {}) of '{}' and [{}, {}) x "
        "[{}, {}) of '{}'\n",
        observer.name, chromaticDistance(observer, *qa, *qb), ra.x0, ra.x1, ra.y0, ra.y1, pathA, rb.x0, rb.x1, rb.y0,
        rb.y1, pathB);
    return;
  }
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
  reportPerPixel(distances, pixels, map, observer.name + " observer: dS", " (the others catch no light in some cone)",
                 "JND",
                 "receptor-noise-limited colour distance dS (JND) of each pixel's cone catches, " + observer.name +
                     " observer; 0 where a pixel catches no light in some cone",
                 pathA, pathB, options);
}

}  // namespace columba
