#pragma once
// The $name variables of a scene file: <default name= value=> declarations, overridden by the
// -D name=value defines given on the command line.
#include <map>
#include <string>
#include "core/error.h"

namespace columba {

class SceneVariables {
 public:
  explicit SceneVariables(std::map<std::string, std::string> defines) : defines_(std::move(defines)) {}

  // A <default>: takes effect from here on, unless a define of that name exists. A second
  // <default> of the same name is an error.
  void addDefault(const std::string& name, const std::string& value, const SourceLocation& loc);

  // Replaces each "$name" in `text` with its value. At every '$' the longest known name that
  // follows is used, so with `o` defined, "la$o0.obj" reads as "la" + $o + "0.obj". A '$' that
  // starts no known name but is followed by a letter or '_' is an error naming that word; any
  // other '$' stays as it is.
  std::string substitute(const std::string& text, const SourceLocation& loc) const;

 private:
  const std::string* lookup(const std::string& name) const;
  std::map<std::string, std::string> defines_;
  std::map<std::string, std::pair<std::string, SourceLocation>> defaults_;
};

}  // namespace columba
