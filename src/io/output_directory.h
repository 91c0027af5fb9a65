#pragma once
// The directories outputs go in: made when missing, as `mkdir -p` makes them, after a check
// before any work that they can be made.
#include <string>
#include <vector>

namespace columba {

// The directory a file's path names ("." when it names none).
std::string directoryOf(const std::string& path);

// `text` safe as (part of) a file name: characters other than letters, digits and . + - , = become _.
std::string safeForFileName(const std::string& text);

// Checks that the directory `dir`, which `path` is written in (or is, for a directory of
// outputs), exists or can be made: the nearest of its ancestors that exists is a directory one
// may write in. Throws std::runtime_error naming `path` and what is in the way ("cannot write
// 'a/b/x.exr': 'a' is a file, not a directory").
void checkOutputDirectory(const std::string& path, const std::string& dir);

// Makes `dir` and every missing directory above it; throws std::runtime_error naming `path`
// where one cannot be made. Nothing is done for a directory that exists.
void makeOutputDirectory(const std::string& path, const std::string& dir);

// Refuses to write `output` where it is one of `inputs` (the same file by another name included):
// throws std::runtime_error "cannot write WHAT to 'out': it is the INPUT 'in', which READER reads",
// e.g. what "the merged image", input "the piece", reader "the merge". Checked before any output
// is written, so that a command never replaces what it reads.
void refuseWritingOverAnInput(const std::string& output, const std::vector<std::string>& inputs,
                              const std::string& what, const std::string& input, const std::string& reader);

}  // namespace columba
