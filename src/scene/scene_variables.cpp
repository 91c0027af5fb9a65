#include "scene/scene_variables.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/number_text.h"

namespace columba {

namespace {

bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool isVariableName(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), isNameChar);
}

}  // namespace

SceneVariables::SceneVariables(std::map<std::string, std::string> defines) : defines_(std::move(defines)) {
  for (const auto& entry : defines_)
    if (!isVariableName(entry.first))
      throw std::runtime_error("-D " + excerpt(entry.first) + "=...: a variable name has only letters, digits and '_'");
}

void SceneVariables::addDefault(const std::string& name, const std::string& value, const SourceLocation& loc) {
  if (!isVariableName(name))
    throw InputError(loc, "<default> name '" + excerpt(name) + "' is not a variable name (letters, digits and '_')");
  // As in Mitsuba, the first <default> of a name holds: a scene can give its own before it
  // includes a file whose defaults would otherwise apply.
  defaults_.emplace(name, value);
}

const std::pair<const std::string, std::string>* SceneVariables::longestNameAt(const std::string& text, size_t pos,
                                                                               size_t run) const {
  // Each known name is compared once, so a '$' costs at most the total length of the names.
  const std::pair<const std::string, std::string>* best = nullptr;
  for (const auto* variables : {&defines_, &defaults_})
    for (const auto& entry : *variables) {
      const std::string& name = entry.first;
      if (name.size() <= run && (!best || name.size() > best->first.size()) &&
          text.compare(pos, name.size(), name) == 0)
        best = &entry;  // a define comes first, so it wins over a <default> of the same name
    }
  return best;
}

std::string SceneVariables::substitute(const std::string& text, const SourceLocation& loc) const {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '$') {
      out += text[i];
      continue;
    }
    size_t end = i + 1;
    while (end < text.size() && isNameChar(text[end])) ++end;
    if (const auto* variable = longestNameAt(text, i + 1, end - i - 1)) {
      if (defines_.count(variable->first)) usedDefines_.insert(variable->first);
      out += variable->second;
      i += variable->first.size();
      continue;
    }
    if (end == i + 1 || std::isdigit(static_cast<unsigned char>(text[i + 1]))) {
      out += '$';
      continue;
    }
    throw InputError(loc, "undefined variable '$" + excerpt(text.substr(i + 1, end - i - 1)) + "' in '" +
                              excerpt(text) +
                              "' (declare it with <default name=\"...\" value=\"...\"/> or define it with -D)");
  }
  return out;
}

std::vector<std::string> SceneVariables::unusedDefines() const {
  std::vector<std::string> unused;
  for (const auto& entry : defines_)
    if (!usedDefines_.count(entry.first)) unused.push_back(entry.first);
  return unused;
}

}  // namespace columba
