#include "core/error.h"

#include <cstdio>

namespace columba {

void warn(const SourceLocation& loc, const std::string& message) {
  std::string where = loc.str();
  std::fprintf(stderr, "warning: %s%s\n", where.empty() ? "" : (where + ": ").c_str(), message.c_str());
}

}  // namespace columba
