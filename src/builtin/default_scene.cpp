#include "builtin/default_scene.h"

#include <unistd.h>

#include <filesystem>
#include <optional>

#include "builtin/builtin_plugins.h"
#include "builtin/default_scene_xml.h"
#include "feather/rock_dove.h"

namespace columba {

namespace {
// Generated into a private temporary directory that is removed once the scene has loaded it.
class TemporaryBird {
 public:
  TemporaryBird() {
    directory_ = std::filesystem::temp_directory_path() / ("columba-rock-dove-" + std::to_string(::getpid()));
    writeRockDove(RockDoveOptions{}, directory_.string());
  }
  ~TemporaryBird() {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  std::string scene() const { return (directory_ / "rock_dove.xml").string(); }

 private:
  std::filesystem::path directory_;
};
}  // namespace

ParsedScene loadDefaultScene(const Defines& userDefines) {
  Defines defines = userDefines;
  std::optional<TemporaryBird> bird;
  if (!defines.count("bird")) {
    bird.emplace();
    defines["bird"] = bird->scene();
  }
  return loadSceneString(kDefaultSceneXML, "<default scene>", std::filesystem::current_path().string(), defines,
                         builtinPlugins());
}

}  // namespace columba
