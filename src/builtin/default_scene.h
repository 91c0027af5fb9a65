#pragma once
// The scene `columba render` draws when given none: a rock dove (scenes/rock_dove.xml) whose
// feathers are generated on the fly.
#include "scene/scene_loader.h"

namespace columba {

// `defines` are the user's -D values; they override the default scene's own settings.
ParsedScene loadDefaultScene(const Defines& defines);

}  // namespace columba
