#include "optics/film_layer_text.h"

#include <optional>
#include <stdexcept>
#include <utility>

#include "core/number_text.h"
#include "optics/rod_layer.h"

namespace columba {

namespace {

constexpr int kMaxRepeats = 1000;

std::string quoted(const std::string& text) { return "'" + excerpt(text) + "'"; }

// "N+Ki" as (N, K); nullopt where `text` is not of that form.
std::optional<std::pair<float, float>> complexIndex(const std::string& text) {
  if (text.size() < 4 || text.back() != 'i') return std::nullopt;
  const size_t plus = text.find('+', 1);
  if (plus == std::string::npos) return std::nullopt;
  const std::optional<float> n = parseNumber<float>(text.substr(0, plus));
  const std::optional<float> k = parseNumber<float>(text.substr(plus + 1, text.size() - plus - 2));
  if (!n || !k) return std::nullopt;
  return std::pair{*n, *k};
}

// INDEX as a material; `piece` names the item in messages.
LayerMaterial material(const std::string& index, const std::string& piece) {
  LayerMaterial m;
  if (const std::optional<std::pair<float, float>> c = complexIndex(index)) {
    if (!(c->first > 0.0f) || !(c->second >= 0.0f))
      throw std::invalid_argument("layer " + quoted(piece) + ": an index N+Ki needs N > 0 and K >= 0");
    m.n = RefractiveIndex::constant(c->first);
    m.k = c->second;
  } else if (index == "melanin") {
    m = melanin();
  } else if (const std::optional<RefractiveIndex> n = iorFromName(index)) {
    m.n = *n;
  } else {
    throw std::invalid_argument("layer " + quoted(piece) + ": unknown index '" + index +
                                "' (a number, a named index such as air, keratin, melanin, or N+Ki)");
  }
  if (!(m.n.maximumVisible() <= kMaxFilmIndex && m.k <= kMaxFilmIndex))
    throw std::invalid_argument("layer " + quoted(piece) + ": an index above " + std::to_string(int(kMaxFilmIndex)) +
                                " (n or k) is no material's");
  return m;
}

// The items of `text` separated by commas outside brackets and parentheses, trimmed.
std::vector<std::string> topLevelItems(const std::string& text) {
  std::vector<std::string> items;
  int depth = 0;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? text[i] : ',';
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (depth < 0) throw std::invalid_argument(quoted(text) + ": a ')' or ']' closes nothing");
    if (c == ',' && depth == 0) {
      items.push_back(trimmed(text.substr(start, i - start)));
      start = i + 1;
    }
  }
  if (depth != 0) throw std::invalid_argument(quoted(text) + ": a '(' or '[' is not closed");
  return items;
}

float positiveNumber(const std::string& text, const std::string& what, const std::string& piece) {
  const std::optional<float> v = parseNumber<float>(trimmed(text));
  if (!v || !(*v > 0.0f) || !std::isfinite(*v))
    throw std::invalid_argument("layer " + quoted(piece) + ": the " + what +
                                " must be a positive number of micrometres");
  return *v;
}

// Layers as written: runs of layers, each repeated some number of times.
struct Run {
  std::vector<FilmLayer> layers;
  int times = 1;
};
struct Runs {
  std::vector<Run> runs;
  size_t expandedLayers = 0;  // the layers with every repeat written out

  void add(Run run, const std::string& piece) {
    expandedLayers += run.layers.size() * size_t(run.times);
    if (expandedLayers > kMaxFilmLayers)
      throw std::invalid_argument("layer " + quoted(piece) + ": the stack would have more than " +
                                  std::to_string(kMaxFilmLayers) + " layers");
    if (run.times == 1 && !runs.empty() && runs.back().times == 1)
      runs.back().layers.insert(runs.back().layers.end(), run.layers.begin(), run.layers.end());
    else
      runs.push_back(std::move(run));
  }
};

Runs parseRuns(const std::string& text, int depth) {
  if (depth > 8) throw std::invalid_argument(quoted(text) + ": repetitions nest more than 8 deep");
  Runs out;
  const std::vector<std::string> items = topLevelItems(text);
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string& piece = items[i];
    if (piece.empty()) {
      if (i + 1 == items.size() && !out.runs.empty()) break;  // a trailing comma
      throw std::invalid_argument(quoted(text) + ": an empty layer");
    }
    if (piece.front() == '[') {
      const size_t close = piece.rfind(']');
      std::string count = trimmed(piece.substr(close + 1));
      if (count.empty() || (count[0] != 'x' && count[0] != 'X'))
        throw std::invalid_argument("layer " + quoted(piece) + ": give [LAYERS] x N");
      const std::optional<int> n = parseNumber<int>(trimmed(count.substr(1)));
      if (!n || *n < 1 || *n > kMaxRepeats)
        throw std::invalid_argument("layer " + quoted(piece) + ": the repeat count must be a whole number from 1 to " +
                                    std::to_string(kMaxRepeats));
      Runs group = parseRuns(piece.substr(1, close - 1), depth + 1);
      if (group.runs.size() == 1) {
        group.runs[0].times *= *n;  // one run repeated: one run (at most 4096 x 1000 times)
        out.add(std::move(group.runs[0]), piece);
      } else {  // runs within the repeat: written out (runs do not nest)
        for (int k = 0; k < *n; ++k)
          for (const Run& run : group.runs) out.add(run, piece);
      }
      continue;
    }
    if (piece.rfind("rods(", 0) == 0) {
      if (piece.back() != ')')
        throw std::invalid_argument("layer " + quoted(piece) + ": give rods(INDEX, DIAMETER, SPACING)");
      const std::vector<std::string> args = topLevelItems(piece.substr(5, piece.size() - 6));
      if (args.size() < 3 || args.size() > 4)
        throw std::invalid_argument("layer " + quoted(piece) + ": give rods(INDEX, DIAMETER, SPACING[, MATRIX])");
      const float diameter = positiveNumber(args[1], "diameter", piece);
      const float spacing = positiveNumber(args[2], "spacing", piece);
      const LayerMaterial matrix =
          args.size() == 4 ? material(args[3], piece) : LayerMaterial{RefractiveIndex::keratin()};
      try {
        out.add({rodRow(material(args[0], piece), matrix, diameter, spacing), 1}, piece);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("layer " + quoted(piece) + ": " + e.what());
      }
      continue;
    }
    const size_t colon = piece.rfind(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("layer " + quoted(piece) + ": give INDEX:THICKNESS (thickness in um)");
    const std::optional<float> thickness = parseNumber<float>(trimmed(piece.substr(colon + 1)));
    if (!thickness || !(*thickness >= 0.0f))
      throw std::invalid_argument("layer " + quoted(piece) +
                                  ": the thickness must be a number of micrometres, not negative");
    FilmLayer layer;
    layer.material = material(trimmed(piece.substr(0, colon)), piece);
    layer.thicknessUm = *thickness;
    out.add({{layer}, 1}, piece);
  }
  return out;
}

}  // namespace

FilmStack parseFilmLayers(const std::string& text) {
  const Runs written = parseRuns(text, 0);
  FilmStack stack;
  const bool repeats = written.runs.size() > 1 || (written.runs.size() == 1 && written.runs[0].times > 1);
  for (const Run& run : written.runs) {
    stack.layers.insert(stack.layers.end(), run.layers.begin(), run.layers.end());
    if (repeats) stack.runs.push_back({run.layers.size(), run.times});
  }
  return stack;
}

}  // namespace columba
