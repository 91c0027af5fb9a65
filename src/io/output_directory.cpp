#include "io/output_directory.h"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace columba {

namespace fs = std::filesystem;

std::string safeForFileName(const std::string& text) {
  std::string safe = text;
  for (char& c : safe)
    if (!std::isalnum(static_cast<unsigned char>(c)) && std::string(".+-,=").find(c) == std::string::npos) c = '_';
  return safe;
}

std::string directoryOf(const std::string& path) {
  std::string dir = fs::path(path).parent_path().string();
  return dir.empty() ? "." : dir;
}

void checkOutputDirectory(const std::string& path, const std::string& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  // The nearest ancestor that exists (the working directory at the end of a relative path).
  fs::path missing = dir, existing = fs::path(dir).parent_path();
  for (; !existing.empty(); missing = existing, existing = existing.parent_path())
    if (fs::exists(existing, ec) || existing == existing.root_path()) break;
  const std::string where = existing.empty() ? "." : existing.string();
  if (fs::exists(dir, ec))
    throw std::runtime_error("cannot write '" + path + "': '" + dir + "' is a file, not a directory");
  if (!fs::is_directory(where, ec))
    throw std::runtime_error("cannot write '" + path + "': '" + where + "' is a file, not a directory");
  if (::access(where.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error("cannot write '" + path + "': cannot make the directory '" + missing.string() +
                             "': " + std::strerror(errno));
}

void makeOutputDirectory(const std::string& path, const std::string& dir) {
  checkOutputDirectory(path, dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  // Another process may have made it meanwhile: only a directory that still is not there fails.
  if (ec && !fs::is_directory(dir))
    throw std::runtime_error("cannot write '" + path + "': cannot make the directory '" + dir + "': " + ec.message());
}

void refuseWritingOverAnInput(const std::string& output, const std::vector<std::string>& inputs,
                              const std::string& what, const std::string& input, const std::string& reader) {
  std::error_code outputError;
  const fs::path resolved = fs::weakly_canonical(output, outputError);
  for (const std::string& in : inputs) {
    std::error_code error;
    if (fs::equivalent(output, in, error) || (!outputError && fs::weakly_canonical(in, error) == resolved))
      throw std::runtime_error("cannot write " + what + " to '" + output + "': it is " + input + " '" + in +
                               "', which " + reader + " reads");
  }
}

}  // namespace columba
