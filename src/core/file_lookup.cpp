#include "core/file_lookup.h"

#include <algorithm>
#include <filesystem>

namespace columba {

namespace fs = std::filesystem;

std::vector<std::string> fileCandidates(const std::string& name, const std::vector<std::string>& dirs) {
  std::vector<std::string> candidates;
  if (fs::path(name).is_relative())
    for (const std::string& dir : dirs) {
      if (dir.empty()) continue;  // the working directory comes last, as `name` itself
      std::string candidate = (fs::path(dir) / name).string();
      if (std::find(candidates.begin(), candidates.end(), candidate) == candidates.end())
        candidates.push_back(std::move(candidate));
    }
  if (std::find(candidates.begin(), candidates.end(), name) == candidates.end()) candidates.push_back(name);
  return candidates;
}

std::optional<std::string> findFile(const std::string& name, const std::vector<std::string>& dirs) {
  std::error_code ec;
  for (std::string& candidate : fileCandidates(name, dirs))
    if (fs::exists(candidate, ec)) return std::move(candidate);
  return std::nullopt;
}

std::string requireFile(const std::string& name, const std::vector<std::string>& dirs, const SourceLocation& where,
                        const std::string& what) {
  if (std::optional<std::string> found = findFile(name, dirs)) return *found;
  const std::vector<std::string> candidates = fileCandidates(name, dirs);
  std::string places;
  for (size_t i = 0; i < candidates.size(); ++i)
    places += (i == 0 ? "'" : i + 1 == candidates.size() ? " and '" : ", '") + candidates[i] + "'";
  throw InputError(where, what + " '" + name + "' not found (looked for " + places + ")");
}

}  // namespace columba
