#include "scene/scene_variables.h"

#include <cctype>

namespace columba {

namespace {

bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

void SceneVariables::addDefault(const std::string& name, const std::string& value, const SourceLocation& loc) {
  if (name.empty()) throw InputError(loc, "<default> needs a non-empty name");
  auto it = defaults_.find(name);
  if (it != defaults_.end())
    throw InputError(loc, "duplicate <default> '" + name + "' (first declared at " + it->second.second.str() + ")");
  defaults_.emplace(name, std::make_pair(value, loc));
}

const std::string* SceneVariables::lookup(const std::string& name) const {
  auto d = defines_.find(name);
  if (d != defines_.end()) return &d->second;
  auto it = defaults_.find(name);
  return it == defaults_.end() ? nullptr : &it->second.first;
}

std::string SceneVariables::substitute(const std::string& text, const SourceLocation& loc) const {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '$') {
      out += text[i];
      continue;
    }
    const std::string* value = nullptr;
    size_t nameLength = 0;
    for (size_t n = 1; i + n < text.size(); ++n)
      if (const std::string* v = lookup(text.substr(i + 1, n))) {
        value = v;
        nameLength = n;
      }
    if (value) {
      out += *value;
      i += nameLength;
      continue;
    }
    size_t end = i + 1;
    while (end < text.size() && isNameChar(text[end])) ++end;
    if (end == i + 1 || std::isdigit(static_cast<unsigned char>(text[i + 1]))) {
      out += '$';
      continue;
    }
    throw InputError(loc, "undefined variable '$" + text.substr(i + 1, end - i - 1) + "' in '" + text +
                              "' (declare it with <default name=\"...\" value=\"...\"/> or define it with -D)");
  }
  return out;
}

}  // namespace columba
