#pragma once
// Errors that point at the input that caused them (file, line, value).
#include <stdexcept>
#include <string>

namespace columba {

struct SourceLocation {
  std::string file;
  int line = 0;
  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

// Prints "warning: FILE:LINE: message" for input that is accepted but probably not meant.
void warn(const SourceLocation& loc, const std::string& message);

class InputError : public std::runtime_error {
 public:
  InputError(const SourceLocation& loc, const std::string& message)
      : std::runtime_error(loc.str().empty() ? message : loc.str() + ": " + message), location(loc) {}
  SourceLocation location;
};

}  // namespace columba
