#include "distribute/manifest.h"

#include <fstream>
#include <stdexcept>
#include "io/data_files.h"

namespace columba {

using nlohmann::json;

namespace {
constexpr const char* kFormat = "columba-manifest-1";

json pieceIndexJSON(const std::optional<PieceIndex>& index) { return index ? json(index->str()) : json(nullptr); }
std::optional<PieceIndex> pieceIndexFrom(const json& j, const char* what) {
  if (j.is_null()) return std::nullopt;
  return parsePieceIndex(what, j.get<std::string>(), 1 << 20);
}
}  // namespace

json manifestToJSON(const Manifest& m) {
  json sweeps = json::array();
  for (const SweepAxis& axis : m.sweeps)
    sweeps.push_back({{"name", axis.name}, {"spec", axis.spec}, {"values", axis.values}});
  json frames = json::array();
  for (const ManifestFrame& f : m.frames) {
    json frame = {
        {"frame", f.frame},   {"defines", f.defines}, {"seed", f.seed},   {"spp", f.spp ? json(f.spp) : json(nullptr)},
        {"output", f.output}, {"status", f.status},   {"time", f.seconds}};
    if (!f.pieces.empty()) {
      json pieces = json::array();
      for (const ManifestPiece& p : f.pieces)
        pieces.push_back({{"part", pieceIndexJSON(p.part)},
                          {"pass", pieceIndexJSON(p.pass)},
                          {"file", p.file},
                          {"status", p.status},
                          {"time", p.seconds}});
      frame["pieces"] = pieces;
    }
    frames.push_back(frame);
  }
  json j = {{"format", kFormat},
            {"columba", m.columbaVersion},
            {"scene", m.scene},
            {"scene_hash", m.sceneHash},
            {"defines", m.defines},
            {"sweeps", sweeps},
            {"spp", m.spp ? json(m.spp) : json(nullptr)},
            {"seed", m.seed},
            {"parts", m.parts},
            {"passes", m.passes},
            {"frames", frames}};
  if (!m.renderScript.empty() || !m.submissions.empty()) {
    json submissions = json::array();
    for (const SlurmSubmission& s : m.submissions)
      submissions.push_back(
          {{"render_job", s.renderJob}, {"merge_job", s.mergeJob}, {"tasks", s.tasks}, {"submitted", s.submitted}});
    j["slurm"] = {{"render_script", m.renderScript},
                  {"merge_script", m.mergeScript},
                  {"log_dir", m.logDir},
                  {"submissions", submissions}};
  }
  return j;
}

Manifest manifestFromJSON(const json& j, const std::string& source) {
  try {
    if (j.value("format", "") != kFormat)
      throw std::runtime_error(std::string("it is not a Columba manifest (no \"format\": \"") + kFormat + "\")");
    Manifest m;
    m.columbaVersion = j.value("columba", "");
    m.scene = j.at("scene").get<std::string>();
    m.sceneHash = j.at("scene_hash").get<std::string>();
    m.defines = j.at("defines").get<std::map<std::string, std::string>>();
    for (const json& s : j.at("sweeps")) {
      SweepAxis axis;
      axis.name = s.at("name").get<std::string>();
      axis.spec = s.at("spec").get<std::string>();
      axis.values = s.at("values").get<std::vector<std::string>>();
      m.sweeps.push_back(axis);
    }
    m.spp = j.at("spp").is_null() ? 0 : j.at("spp").get<int>();
    m.seed = j.at("seed").get<uint64_t>();
    m.parts = j.at("parts").get<int>();
    m.passes = j.at("passes").get<int>();
    for (const json& f : j.at("frames")) {
      ManifestFrame frame;
      frame.frame = f.at("frame").get<int>();
      frame.defines = f.at("defines").get<std::map<std::string, std::string>>();
      frame.seed = f.at("seed").get<uint64_t>();
      frame.spp = f.at("spp").is_null() ? 0 : f.at("spp").get<int>();
      frame.output = f.at("output").get<std::string>();
      frame.status = f.at("status").get<std::string>();
      frame.seconds = f.value("time", 0.0);
      if (f.contains("pieces"))
        for (const json& p : f.at("pieces")) {
          ManifestPiece piece;
          piece.part = pieceIndexFrom(p.at("part"), "a piece's part");
          piece.pass = pieceIndexFrom(p.at("pass"), "a piece's pass");
          piece.file = p.at("file").get<std::string>();
          piece.status = p.at("status").get<std::string>();
          piece.seconds = p.value("time", 0.0);
          frame.pieces.push_back(piece);
        }
      m.frames.push_back(frame);
    }
    if (j.contains("slurm")) {
      const json& s = j.at("slurm");
      m.renderScript = s.value("render_script", "");
      m.mergeScript = s.value("merge_script", "");
      m.logDir = s.value("log_dir", "");
      for (const json& sub : s.at("submissions"))
        m.submissions.push_back({sub.value("render_job", ""), sub.value("merge_job", ""), sub.value("tasks", ""),
                                 sub.value("submitted", "")});
    }
    return m;
  } catch (const json::exception& e) {
    throw std::runtime_error("cannot read the manifest '" + source + "': " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot read the manifest '" + source + "': " + e.what());
  }
}

Manifest readManifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the manifest '" + path + "': it does not exist or cannot be opened");
  json j;
  try {
    in >> j;
  } catch (const json::exception& e) {
    throw std::runtime_error("cannot read the manifest '" + path + "': " + e.what());
  }
  return manifestFromJSON(j, path);
}

void writeManifest(const std::string& path, const Manifest& manifest) { writeJSON(path, manifestToJSON(manifest)); }

}  // namespace columba
