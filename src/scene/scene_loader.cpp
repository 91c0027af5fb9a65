#include "scene/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include "core/file_lookup.h"
#include "scene/unsupported_plugins.h"
#include "scene/xml_source.h"
#include "scene/xml_transform.h"
#include "scene/xml_values.h"

namespace columba {

namespace {

const std::set<std::string> kPluginTags = {"bsdf",    "shape",      "emitter", "sensor", "film",  "rfilter",
                                           "sampler", "integrator", "texture", "medium", "phase", "volume"};

// Plug-ins are built recursively; real scenes nest a handful deep, and a bound keeps a hostile
// file from exhausting the stack.
constexpr int kMaxPluginNesting = 64;

struct NamedObject {
  std::shared_ptr<Object> object;
  std::string tag, type;
  SourceLocation location;
};

// Reads a scene in two passes, as Mitsuba does. Reading takes every file's <default>s, <path>s
// and <include>s in document order and notes its plug-ins and their ids; building then creates
// the top-level plug-ins in document order, each once its nested plug-ins exist. A <ref> may so
// name an id declared anywhere in the scene, before or after it: the plug-in it names is built
// when first needed, once, and shared.
class SceneBuilder {
 public:
  // `mainDir` is the main scene file's directory, where relative file names are looked for after
  // the declaring file's.
  SceneBuilder(const Defines& defines, const PluginRegistry& registry, std::string mainDir)
      : vars_(defines), registry_(registry), mainDir_(std::move(mainDir)) {}

  // `doc` must outlive build().
  void readScene(const XmlDocument& doc);
  // Reads a scene file, which must not be one of the files whose <include>s led to it.
  void readFile(const std::string& path);
  void build(ParsedScene& scene);
  std::vector<std::string> unusedDefines() const { return vars_.unusedDefines(); }

 private:
  void include(const XmlElement& e);
  // Notes the plug-in elements with an id in `e` and below; `depth` counts the plug-ins enclosing `e`.
  void declareIds(const XmlElement& e, int depth);
  void addSearchPath(const XmlElement& e);
  // Where a file name in `doc` is looked for: its directory, the main file's, the <path>s.
  std::vector<std::string> searchDirs(const XmlDocument& doc) const;
  // `depth` counts the plug-ins enclosing `e`.
  NamedObject instantiate(const XmlElement& e, int depth);
  Properties::Child reference(const XmlElement& e, int depth);
  void readParameter(const XmlElement& e, Properties& props) const;

  SceneVariables vars_;
  const PluginRegistry& registry_;
  std::vector<std::unique_ptr<XmlDocument>> includedDocuments_;  // the elements below point into them
  std::vector<XmlElement> topLevel_;                             // in document order, across files
  std::map<std::string, XmlElement> declared_;                   // every plug-in element with an id
  std::map<std::string, NamedObject> built_;                     // by id
  std::set<std::string> building_;         // ids whose plug-ins are being built: a <ref> to one is a cycle
  std::vector<std::string> includeStack_;  // the files being read, outermost first
  std::string mainDir_;
  std::vector<std::string> searchPaths_;  // the <path> directories, the latest first (as Mitsuba)
};

void SceneBuilder::readScene(const XmlDocument& doc) {
  XmlElement root(doc.root(), doc, vars_);
  if (root.tag() != "scene")
    throw InputError(root.location(), "the root element must be <scene>, not <" + root.tag() + ">");
  root.allowAttributes({"version"});
  std::string version = root.attribute("version");
  if (version.rfind("2.", 0) != 0 && version.rfind("3.", 0) != 0)
    throw InputError(root.location(), "unsupported scene version '" + version + "' (expected 2.x or 3.x)");

  for (const XmlElement& e : root.children()) {
    const std::string tag = e.tag();
    if (kPluginTags.count(tag)) {
      declareIds(e, 0);
      topLevel_.push_back(e);
    } else if (tag == "default") {
      e.allowAttributes({"name", "value"});
      e.requireNoChildren();
      vars_.addDefault(e.attribute("name"), e.attribute("value"), e.location());
    } else if (tag == "include") {
      include(e);
    } else if (tag == "path") {
      addSearchPath(e);
    } else {
      throw InputError(e.location(), "<" + tag + "> cannot appear directly inside <scene>");
    }
  }
}

// The included file's <scene> contents are read as if they stood in place of the <include>.
void SceneBuilder::include(const XmlElement& e) {
  e.allowAttributes({"filename"});
  e.requireNoChildren();
  namespace fs = std::filesystem;
  const fs::path path = requireFile(e.attribute("filename"), searchDirs(e.document()), e.location(), "included file");
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(e.location(), "included file '" + path.string() + "' is not a regular file");
  std::string key = fs::weakly_canonical(path).string();
  auto first = std::find(includeStack_.begin(), includeStack_.end(), key);
  if (first != includeStack_.end()) {
    std::string cycle;
    for (auto file = first; file != includeStack_.end(); ++file) cycle += *file + " -> ";
    throw InputError(e.location(), "including '" + path.string() + "' closes an include cycle: " + cycle + key);
  }
  readFile(path.string());
}

// A <path>: a directory where later relative file names are also looked for; a relative one is
// relative to the declaring file's directory.
void SceneBuilder::addSearchPath(const XmlElement& e) {
  e.allowAttributes({"value"});
  e.requireNoChildren();
  namespace fs = std::filesystem;
  const std::string value = e.attribute("value");
  fs::path dir(value);
  if (dir.is_relative()) dir = fs::path(e.document().baseDir()) / dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(e.location(), "<path> '" + value + "': directory '" + dir.string() + "' not found");
  searchPaths_.insert(searchPaths_.begin(), dir.string());
}

std::vector<std::string> SceneBuilder::searchDirs(const XmlDocument& doc) const {
  std::vector<std::string> dirs = {doc.baseDir(), mainDir_};
  dirs.insert(dirs.end(), searchPaths_.begin(), searchPaths_.end());
  return dirs;
}

void SceneBuilder::readFile(const std::string& path) {
  includedDocuments_.push_back(XmlDocument::fromFile(path));
  includeStack_.push_back(std::filesystem::weakly_canonical(path).string());
  readScene(*includedDocuments_.back());
  includeStack_.pop_back();
}

void SceneBuilder::declareIds(const XmlElement& e, int depth) {
  if (depth >= kMaxPluginNesting)
    throw InputError(e.location(),
                     "<" + e.tag() + "> is nested more than " + std::to_string(kMaxPluginNesting) + " plug-ins deep");
  if (e.has("id")) {
    const std::string id = e.attribute("id");
    if (id.empty()) throw InputError(e.location(), "empty id");
    auto [it, added] = declared_.emplace(id, e);
    if (!added)
      throw InputError(e.location(),
                       "duplicate id '" + id + "' (first declared at " + it->second.location().str() + ")");
  }
  for (const XmlElement& c : e.children())
    if (kPluginTags.count(c.tag())) declareIds(c, depth + 1);
}

void SceneBuilder::build(ParsedScene& scene) {
  for (const XmlElement& e : topLevel_) {
    NamedObject built = instantiate(e, 0);
    // As in Mitsuba, a top-level film, sampler or filter is there to be referenced by a sensor, a
    // top-level texture by a BSDF, and a top-level medium, phase function or volume by a shape, a
    // sensor or a medium.
    static const std::set<std::string> kReferencedOnly = {"film",   "sampler", "rfilter", "texture",
                                                          "medium", "phase",   "volume"};
    if (kReferencedOnly.count(built.tag)) {
      if (!e.has("id")) warn(e.location(), "<" + built.tag + "> without an id is never used (a <ref> to it needs one)");
      continue;
    }
    scene.objects.push_back(built.object);
  }
}

NamedObject SceneBuilder::instantiate(const XmlElement& e, int depth) {
  // Built already: it was referenced before its place in the document, or is referenced again.
  if (e.has("id"))
    if (auto it = built_.find(e.attribute("id")); it != built_.end()) return it->second;
  if (depth >= kMaxPluginNesting)
    throw InputError(e.location(),
                     "<" + e.tag() + "> is nested more than " + std::to_string(kMaxPluginNesting) + " plug-ins deep");
  e.allowAttributes({"type", "id", "name"});
  Properties props;
  props.tag = e.tag();
  props.type = e.attribute("type");
  props.id = e.attribute("id", "");
  props.location = e.location();
  props.searchDirs = searchDirs(e.document());

  const PluginFactory* factory = registry_.find(props.tag, props.type);
  if (!factory) {
    if (std::optional<std::string> reason = unsupportedMitsubaPlugin(props.tag, props.type))
      throw InputError(e.location(), "<" + props.tag + " type='" + props.type +
                                         "'>: a Mitsuba plug-in Columba does "
                                         "not have (" +
                                         *reason + ")");
    throw InputError(e.location(), "unknown <" + props.tag + "> plug-in type '" + props.type + "'");
  }
  if (!props.id.empty()) building_.insert(props.id);

  for (const XmlElement& c : e.children()) {
    if (kPluginTags.count(c.tag())) {
      NamedObject nested = instantiate(c, depth + 1);
      Properties::Child child;
      child.name = c.attribute("name", "");
      child.object = nested.object;
      child.location = c.location();
      child.tag = nested.tag;
      child.type = nested.type;
      props.addChild(std::move(child));
    } else if (c.tag() == "ref") {
      props.addChild(reference(c, depth));
    } else {
      readParameter(c, props);
    }
  }

  NamedObject result{nullptr, props.tag, props.type, props.location};
  try {
    result.object = (*factory)(props);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& ex) {
    throw InputError(props.location, "cannot create <" + props.tag + "> '" + props.type + "': " + ex.what());
  }
  if (!result.object) throw InputError(props.location, "<" + props.tag + "> '" + props.type + "' created nothing");
  props.checkAllUsed();
  if (!props.id.empty()) {
    building_.erase(props.id);
    built_.emplace(props.id, result);
  }
  return result;
}

// `depth` counts the plug-ins enclosing the <ref>; one built here is nested one deeper.
Properties::Child SceneBuilder::reference(const XmlElement& e, int depth) {
  e.allowAttributes({"id", "name"});
  e.requireNoChildren();
  const std::string id = e.attribute("id");
  auto declaration = declared_.find(id);
  if (declaration == declared_.end()) throw InputError(e.location(), "<ref> to unknown id '" + id + "'");
  if (building_.count(id))
    throw InputError(e.location(), "<ref> to '" + id + "' closes a cycle: it is needed to build '" + id + "' itself (" +
                                       declaration->second.location().str() + ")");
  const NamedObject target = instantiate(declaration->second, depth + 1);
  Properties::Child child;
  child.name = e.attribute("name", "");
  child.object = target.object;
  child.location = e.location();
  child.tag = target.tag;
  child.type = target.type;
  return child;
}

void SceneBuilder::readParameter(const XmlElement& e, Properties& props) const {
  using Kind = Properties::ValueKind;
  const std::string tag = e.tag();
  const SourceLocation& loc = e.location();
  Properties::Value v;
  v.location = loc;

  if (tag == "transform") {
    e.allowAttributes({"name"});
    std::string name = e.attribute("name");
    v.kind = Kind::Transform;
    v.transform = parseTransform(e);
    props.set(name, std::move(v));
    return;
  }
  e.requireNoChildren();
  if (tag == "integer" || tag == "float" || tag == "string" || tag == "boolean" || tag == "rgb") {
    e.allowAttributes({"name", "value"});
  } else if (tag == "point" || tag == "vector") {
    e.allowAttributes({"name", "value", "x", "y", "z"});
  } else if (tag == "spectrum") {
    e.allowAttributes({"name", "value", "filename"});
  } else if (tag == "default" || tag == "include" || tag == "path") {
    throw InputError(loc, "<" + tag + "> is only allowed directly inside <scene>");
  } else {
    throw InputError(loc, "unknown element <" + tag + "> in <" + props.tag + "> '" + props.type + "'");
  }
  std::string name = e.attribute("name");
  std::string what = "<" + tag + "> '" + name + "'";

  if (tag == "integer") {
    v.kind = Kind::Integer;
    v.number = double(parseInteger(e.attribute("value"), what, loc));
  } else if (tag == "float") {
    v.kind = Kind::Float;
    v.number = parseFloat(e.attribute("value"), what, loc);
  } else if (tag == "boolean") {
    v.kind = Kind::Boolean;
    v.boolean = parseBoolean(e.attribute("value"), what, loc);
  } else if (tag == "string") {
    v.kind = Kind::String;
    v.text = e.attribute("value");
  } else if (tag == "point" || tag == "vector") {
    v.kind = Kind::Vector;
    if (e.has("value")) {
      if (e.has("x") || e.has("y") || e.has("z"))
        throw InputError(loc, what + " takes either 'value' or x/y/z, not both");
      v.vector = parseVec3(e.attribute("value"), what, loc);
    } else {
      const char* axes[] = {"x", "y", "z"};
      for (int i = 0; i < 3; ++i)
        if (e.has(axes[i])) v.vector[i] = float(parseFloat(e.attribute(axes[i]), what, loc));
    }
  } else if (tag == "rgb") {
    v.kind = Kind::Spectrum;
    v.isRGB = true;
    v.rgb = parseVec3(e.attribute("value"), what, loc);
  } else {
    v.kind = Kind::Spectrum;
    if (e.has("value") == e.has("filename"))
      throw InputError(loc, what + " needs exactly one of 'value' and 'filename'");
    if (e.has("value")) {
      GivenSpectrum given = parseSpectrum(e.attribute("value"), what, loc);
      v.spectrum = std::move(given.distribution);
      v.lowest = given.lowest;
    } else {
      // A name found nowhere is read where the declaring file is, to say that it does not exist.
      const std::string name = e.attribute("filename");
      const std::string file = findFile(name, props.searchDirs).value_or(fileCandidates(name, props.searchDirs)[0]);
      GivenSpectrum given = readSpectrumFile(file, what, loc);
      v.spectrum = std::move(given.distribution);
      v.lowest = given.lowest;
    }
  }
  props.set(name, std::move(v));
}

}  // namespace

ParsedScene loadSceneFile(const std::string& path, const Defines& defines, const PluginRegistry& registry) {
  ParsedScene scene;
  SceneBuilder builder(defines, registry, std::filesystem::path(path).parent_path().string());
  builder.readFile(path);
  builder.build(scene);
  scene.unusedDefines = builder.unusedDefines();
  return scene;
}

ParsedScene loadSceneString(const std::string& xml, const std::string& sourceName, const std::string& baseDir,
                            const Defines& defines, const PluginRegistry& registry) {
  XmlDocument doc(xml, sourceName, baseDir);
  ParsedScene scene;
  SceneBuilder builder(defines, registry, baseDir);
  builder.readScene(doc);
  builder.build(scene);
  scene.unusedDefines = builder.unusedDefines();
  return scene;
}

}  // namespace columba
