#include "builtin/default_scene.h"

#include <unistd.h>

#include <filesystem>
#include <optional>

#include "builtin/builtin_plugins.h"
#include "builtin/default_scene_xml.h"
#include "feather/feather_generator.h"

namespace columba {

namespace {
// Generated into a private temporary file that is removed once the scene has loaded it.
class TemporaryNeck {
 public:
  TemporaryNeck() {
    path_ = (std::filesystem::temp_directory_path() / ("columba-neck-" + std::to_string(::getpid()) + ".ply")).string();
    FeatherGenerationOptions options;
    options.neck = true;
    options.binary = true;
    generateFeatherPly(options, path_);
  }
  ~TemporaryNeck() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};
}  // namespace

ParsedScene loadDefaultScene(const Defines& userDefines) {
  // Sized to render in about a minute on two cores.
  Defines defines = {{"width", "800"}, {"height", "600"}, {"spp", "32"}};
  for (const auto& [name, value] : userDefines) defines[name] = value;
  std::optional<TemporaryNeck> neck;
  if (!defines.count("feathers")) {
    neck.emplace();
    defines["feathers"] = neck->path();
  }
  return loadSceneString(kDefaultSceneXML, "<default scene>", std::filesystem::current_path().string(), defines,
                         builtinPlugins());
}

}  // namespace columba
