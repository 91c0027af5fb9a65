#pragma once
// The scene `columba render` draws when given none.
#include <string>

namespace columba {

// Scene XML; relative paths in it resolve against the current directory.
std::string defaultSceneXML();

}  // namespace columba
