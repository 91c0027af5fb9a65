#pragma once
// The $name variables of a scene file: <default name= value=> declarations, overridden by the
// -D name=value defines given on the command line.
#include <map>
#include <set>
#include <string>
#include <vector>
#include "core/error.h"

namespace columba {

class SceneVariables {
 public:
  // Throws std::runtime_error for a define whose name is not a variable name (letters, digits
  // and '_').
  explicit SceneVariables(std::map<std::string, std::string> defines);

  // A <default>: the value of $name unless a define of that name exists. A second <default> of
  // the same name is ignored (the first holds, as in Mitsuba); a name that is not a variable name
  // is an error.
  void addDefault(const std::string& name, const std::string& value, const SourceLocation& loc);

  // Replaces each "$name" in `text` with its value. At every '$' the longest known name that
  // follows is used, so with `o` defined, "la$o0.obj" reads as "la" + $o + "0.obj". A '$' that
  // starts no known name but is followed by a letter or '_' is an error naming that word; any
  // other '$' stays as it is. Linear in the length of `text` (for a given set of names).
  std::string substitute(const std::string& text, const SourceLocation& loc) const;

  // The defines that no substitution has used so far, in name order.
  std::vector<std::string> unusedDefines() const;

 private:
  // The longest known name that `text` has at `pos`, within the `run` name characters there.
  const std::pair<const std::string, std::string>* longestNameAt(const std::string& text, size_t pos, size_t run) const;
  std::map<std::string, std::string> defines_;
  std::map<std::string, std::string> defaults_;
  mutable std::set<std::string> usedDefines_;
};

}  // namespace columba
