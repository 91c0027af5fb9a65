#pragma once
// Where a scene's file names lead. A relative name is looked up, as by Mitsuba's file resolver, in
// a list of directories (the declaring file's, the main scene file's, those of <path> elements)
// and last in the working directory; an absolute name is taken as it is.
#include <optional>
#include <string>
#include <vector>
#include "core/error.h"

namespace columba {

// The places `name` is looked for, in order: `dirs` joined with it (directories that repeat are
// looked in once), then `name` itself. Just `name` when it is absolute.
std::vector<std::string> fileCandidates(const std::string& name, const std::vector<std::string>& dirs);

// The first candidate that exists (file, directory or device), if any.
std::optional<std::string> findFile(const std::string& name, const std::vector<std::string>& dirs);

// The first candidate that exists; else an InputError at `where`: "<what> 'name' not found
// (looked for 'a', 'b' and 'c')".
std::string requireFile(const std::string& name, const std::vector<std::string>& dirs, const SourceLocation& where,
                        const std::string& what);

}  // namespace columba
