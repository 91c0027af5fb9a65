#include "core/error.h"
#include "core/quiet_warnings.h"

#include <atomic>
#include <cstdio>

namespace columba {

namespace {
std::atomic<int> quietScopes{0};
}  // namespace

QuietWarnings::QuietWarnings() { ++quietScopes; }
QuietWarnings::~QuietWarnings() { --quietScopes; }

void warn(const SourceLocation& loc, const std::string& message) {
  if (quietScopes > 0) return;
  std::string where = loc.str();
  std::fprintf(stderr, "warning: %s%s\n", where.empty() ? "" : (where + ": ").c_str(), message.c_str());
}

}  // namespace columba
