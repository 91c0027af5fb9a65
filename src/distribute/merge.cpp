#include "distribute/merge.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include "io/declared_image_size.h"

namespace columba {

namespace {

std::string rowsText(const PixelRect& r) { return fmt::format("rows {}-{}", r.y0, r.y1 - 1); }

std::string windowText(const PixelRect& r, int frameWidth) {
  if (r.x0 == 0 && r.x1 == frameWidth) return rowsText(r);
  return fmt::format("pixels [{}, {}) x [{}, {})", r.x0, r.x1, r.y0, r.y1);
}

// How a piece is named in messages: its file, which part and pass it says it is, and `more`.
std::string describe(const Piece& p, const std::string& more = "") {
  std::string what;
  if (p.info.part) what = "part " + p.info.part->str();
  if (p.info.pass) what += (what.empty() ? "" : ", ") + ("pass " + p.info.pass->str());
  if (!more.empty()) what += (what.empty() ? "" : ", ") + more;
  return what.empty() ? "'" + p.path + "'" : "'" + p.path + "' (" + what + ")";
}

bool overlap(const PixelRect& a, const PixelRect& b) {
  return std::max(a.x0, b.x0) < std::min(a.x1, b.x1) && std::max(a.y0, b.y0) < std::min(a.y1, b.y1);
}

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.empty() ? "(none)" : text;
}

// The file a missing piece probably has: a sibling's name with its part (or pass) index replaced.
std::string guessName(const std::string& sibling, const char* kind, int index, int count) {
  std::regex pattern(std::string("\\.") + kind + "[0-9]+of" + std::to_string(count) + "\\.");
  std::string replaced = std::regex_replace(sibling, pattern, fmt::format(".{}{}of{}.", kind, index, count),
                                            std::regex_constants::format_first_only);
  return replaced == sibling ? "" : " (expected in '" + replaced + "')";
}

// Checks that every piece belongs to the same render as the first one.
void checkSameRender(const std::vector<Piece>& pieces) {
  const Piece& first = pieces.front();
  struct Field {
    const char* name;
    std::string (*value)(const PieceInfo&);
  };
  const Field fields[] = {
      {"scene hash", [](const PieceInfo& i) { return i.sceneHash.empty() ? "of '" + i.scene + "'" : i.sceneHash; }},
      {"defines", [](const PieceInfo& i) { return oneLine(i.defines); }},
      {"seed", [](const PieceInfo& i) { return std::to_string(i.seed); }},
      {"samples per pixel", [](const PieceInfo& i) { return std::to_string(i.spp); }},
      {"frame size", [](const PieceInfo& i) { return fmt::format("{}x{}", i.frameWidth, i.frameHeight); }},
      {"spectral channels", [](const PieceInfo& i) { return i.spectral.empty() ? std::string("none") : i.spectral; }},
      {"observer", [](const PieceInfo& i) { return i.observer.empty() ? std::string("none") : i.observer; }},
  };
  for (const Piece& p : pieces)
    for (const Field& f : fields)
      if (f.value(p.info) != f.value(first.info))
        throw std::runtime_error(fmt::format("the pieces do not belong together: {} has {} {}, but {} has {} {}",
                                             describe(first), f.name, f.value(first.info), describe(p), f.name,
                                             f.value(p.info)));
  for (const Piece& p : pieces)
    if (p.image.spectral.centres != first.image.spectral.centres)
      throw std::runtime_error(
          fmt::format("the pieces do not belong together: {} and {} have different spectral "
                      "channels",
                      describe(first), describe(p)));
  for (const Piece& p : pieces)
    if (p.image.cones.names != first.image.cones.names)
      throw std::runtime_error(fmt::format("the pieces do not belong together: {} and {} have different cone channels",
                                           describe(first), describe(p)));
}

using WindowGroups = std::map<std::tuple<int, int, int, int>, std::vector<const Piece*>>;

// Every piece's window lies in the frame of width x height, and is the band its part says it is.
void checkWindows(const std::vector<Piece>& pieces, int width, int height) {
  for (const Piece& p : pieces) {
    const PixelRect& w = p.info.window;
    if (w.empty() || w.x0 < 0 || w.y0 < 0 || w.x1 > width || w.y1 > height)
      throw std::runtime_error(fmt::format("{} holds {}, which is not inside the frame of {} x {}", describe(p),
                                           windowText(w, width), width, height));
    if (p.info.part && !(partWindow(p.info.partBounds, p.info.part->index, width) == w))
      throw std::runtime_error(
          fmt::format("{} holds {}, but its part's bounds say {}", describe(p), windowText(w, width),
                      windowText(partWindow(p.info.partBounds, p.info.part->index, width), width)));
    if (p.image.width != w.width() || p.image.height != w.height())
      throw std::runtime_error(fmt::format("{} holds {} x {} pixels for {}", describe(p), p.image.width, p.image.height,
                                           windowText(w, width)));
  }
}

// Windows: no two overlap, and together they cover the frame.
void findCoverageProblems(const std::vector<Piece>& pieces, const WindowGroups& groups, int width, int height,
                          std::vector<std::string>& problems) {
  std::vector<const Piece*> representatives;
  for (const auto& [key, group] : groups) representatives.push_back(group.front());
  for (size_t i = 0; i < representatives.size(); ++i)
    for (size_t j = i + 1; j < representatives.size(); ++j) {
      const PixelRect &a = representatives[i]->info.window, &b = representatives[j]->info.window;
      if (overlap(a, b))
        problems.push_back(fmt::format("{} and {} overlap: they were split differently",
                                       describe(*representatives[i], windowText(a, width)),
                                       describe(*representatives[j], windowText(b, width))));
    }
  if (problems.empty()) {
    std::vector<unsigned char> covered(size_t(width) * size_t(height), 0);
    for (const Piece* p : representatives)
      for (int y = p->info.window.y0; y < p->info.window.y1; ++y)
        std::fill_n(covered.begin() + ptrdiff_t(size_t(y) * width + p->info.window.x0), p->info.window.width(), 1);
    // Missing bands are named by the split the pieces record; other gaps by their rows.
    const Piece* split = nullptr;
    for (const Piece& p : pieces)
      if (p.info.part) split = &p;
    auto rowCovered = [&](int y) {
      return std::all_of(covered.begin() + ptrdiff_t(size_t(y) * width),
                         covered.begin() + ptrdiff_t(size_t(y + 1) * width), [](unsigned char c) { return c != 0; });
    };
    if (split) {
      const std::vector<int>& bounds = split->info.partBounds;
      for (int k = 1; k < int(bounds.size()); ++k) {
        PixelRect band = partWindow(bounds, k, width);
        bool any = false;
        for (int y = band.y0; y < band.y1 && !any; ++y) any = !rowCovered(y);
        if (any)
          problems.push_back(fmt::format("part {}/{} ({}) is missing{}", k, bounds.size() - 1, rowsText(band),
                                         guessName(split->path, "part", k, int(bounds.size()) - 1)));
      }
    }
    if (problems.empty())
      for (int y = 0; y < height; ++y) {
        if (rowCovered(y)) continue;
        int end = y;
        while (end < height && !rowCovered(end)) ++end;
        problems.push_back(fmt::format("{} are covered by no piece", rowsText({0, y, width, end})));
        y = end;
      }
  }
}

// Passes: in each window, every sample index 0 .. spp - 1 exactly once. Sorts each group by its
// samples; returns the most passes any window has.
int findPassProblems(WindowGroups& groups, int spp, std::vector<std::string>& problems) {
  int mostPasses = 0;
  for (auto& [key, group] : groups) {
    std::sort(group.begin(), group.end(),
              [](const Piece* a, const Piece* b) { return a->info.sampleBegin < b->info.sampleBegin; });
    mostPasses = std::max(mostPasses, int(group.size()));
    const Piece& any = *group.front();
    std::string where = any.info.part ? " of part " + any.info.part->str() : "";
    int passCount = 0;
    for (const Piece* p : group)
      if (p->info.pass) passCount = p->info.pass->count;
    int next = 0;
    for (const Piece* p : group) {
      if (p->info.sampleBegin < next)
        problems.push_back(fmt::format("{} and another piece{} both hold samples {}:{} (a pass given twice?)",
                                       describe(*p), where, p->info.sampleBegin, std::min(next, p->info.sampleEnd)));
      next = std::max(next, p->info.sampleEnd);
    }
    std::vector<std::pair<int, int>> gaps;
    next = 0;
    for (const Piece* p : group) {
      if (p->info.sampleBegin > next) gaps.push_back({next, p->info.sampleBegin});
      next = std::max(next, p->info.sampleEnd);
    }
    if (next < spp) gaps.push_back({next, spp});
    for (auto [b, e] : gaps) {
      // Named as the missing passes of the split the window's pieces record.
      bool named = false;
      for (int k = 1; passCount > 0 && k <= passCount; ++k) {
        auto [pb, pe] = passSamples({k, passCount}, spp);
        if (pb >= b && pe <= e) {
          problems.push_back(fmt::format("pass {}/{}{} (samples {}:{}) is missing{}", k, passCount, where, pb, pe,
                                         guessName(any.path, "pass", k, passCount)));
          named = true;
        }
      }
      if (!named) problems.push_back(fmt::format("samples {}:{}{} are in no piece", b, e, where));
    }
  }
  return mostPasses;
}

void throwProblems(const std::vector<std::string>& problems) {
  std::string message = problems.size() == 1 ? "cannot merge: " + problems.front()
                                             : fmt::format("cannot merge, {} problems:", problems.size());
  if (problems.size() > 1)
    for (const std::string& p : problems) message += "\n  " + p;
  throw std::runtime_error(message);
}

// The merge itself: each window's pieces, weighted by their sample counts (a window of one piece
// bit for bit).
MergedImage combinePieces(const std::vector<Piece>& pieces, const WindowGroups& groups, int mostPasses) {
  const PieceInfo& first = pieces.front().info;
  const int width = first.frameWidth, height = first.frameHeight, spp = first.spp;
  MergedImage merged;
  merged.info = first;
  merged.info.part.reset();
  merged.info.partBounds.clear();
  merged.info.pass.reset();
  merged.info.sampleBegin = 0;
  merged.info.sampleEnd = spp;
  merged.info.window = {0, 0, width, height};
  merged.info.seconds = 0.0;
  for (const Piece& p : pieces) merged.info.seconds += p.info.seconds;
  merged.parts = int(groups.size());
  merged.passes = mostPasses;
  Image& image = merged.image;
  image = Image(width, height);
  const size_t bands = pieces.front().image.spectral.count();
  image.spectral.centres = pieces.front().image.spectral.centres;
  image.spectral.values.assign(size_t(width) * size_t(height) * bands, 0.0f);
  const size_t cones = pieces.front().image.cones.count();
  image.cones.names = pieces.front().image.cones.names;
  image.cones.values.assign(size_t(width) * size_t(height) * cones, 0.0f);
  for (const auto& window : groups) {
    // A variable, not a structured binding: clang 14 cannot capture those in the lambdas below.
    const std::vector<const Piece*>& group = window.second;
    const PixelRect w = group.front()->info.window;
    for (int y = w.y0; y < w.y1; ++y)
      for (int x = w.x0; x < w.x1; ++x) {
        const size_t at = size_t(y) * width + x, from = size_t(y - w.y0) * w.width() + (x - w.x0);
        auto combine = [&](auto valueOf) {
          if (group.size() == 1) return valueOf(*group.front());  // bit for bit
          double sum = 0.0;
          for (const Piece* p : group) sum += double(p->info.sampleEnd - p->info.sampleBegin) * double(valueOf(*p));
          return float(sum / spp);
        };
        for (int c = 0; c < 3; ++c)
          image.rgb[at * 3 + c] = combine([&](const Piece& p) { return p.image.rgb[from * 3 + c]; });
        for (size_t b = 0; b < bands; ++b)
          image.spectral.values[at * bands + b] =
              combine([&](const Piece& p) { return p.image.spectral.values[from * bands + b]; });
        for (size_t c = 0; c < cones; ++c)
          image.cones.values[at * cones + c] =
              combine([&](const Piece& p) { return p.image.cones.values[from * cones + c]; });
      }
  }
  return merged;
}

}  // namespace

Piece loadPiece(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("'" + path + "' does not exist or is not a regular file");
  EXRImageFile file = readEXRFile(path);
  Piece piece;
  piece.path = path;
  piece.info = pieceInfoFromFile(path, file);
  piece.image = std::move(file.image);
  // The merge allocates the whole frame, whatever the pieces hold.
  checkImageMemory(path, piece.info.frameWidth, piece.info.frameHeight,
                   3 + int64_t(piece.image.spectral.count() + piece.image.cones.count()), sizeof(float),
                   "its frame (the EXR display window) is");
  return piece;
}

MergedImage mergePieces(const std::vector<Piece>& pieces) {
  if (pieces.empty()) throw std::runtime_error("no pieces to merge");
  for (const Piece& p : pieces)
    if (!p.info.complete)
      throw std::runtime_error(
          fmt::format("{} is unfinished: its render was interrupted (Status: interrupted); "
                      "render that piece again",
                      describe(p)));
  checkSameRender(pieces);
  const PieceInfo& first = pieces.front().info;
  checkWindows(pieces, first.frameWidth, first.frameHeight);
  // Pieces of the same window, in the order of their samples.
  WindowGroups groups;
  for (const Piece& p : pieces)
    groups[{p.info.window.y0, p.info.window.x0, p.info.window.y1, p.info.window.x1}].push_back(&p);
  std::vector<std::string> problems;
  findCoverageProblems(pieces, groups, first.frameWidth, first.frameHeight, problems);
  const int mostPasses = findPassProblems(groups, first.spp, problems);
  if (!problems.empty()) throwProblems(problems);
  return combinePieces(pieces, groups, mostPasses);
}

MergedImage mergePieceFiles(const std::vector<std::string>& paths) {
  std::set<std::string> seen;
  std::vector<Piece> pieces;
  for (const std::string& path : paths) {
    if (!seen.insert(std::filesystem::weakly_canonical(path).string()).second)
      throw std::runtime_error("'" + path + "' is given twice");
    pieces.push_back(loadPiece(path));
  }
  return mergePieces(pieces);
}

}  // namespace columba
