#include "core/error.h"
#include "core/quiet_warnings.h"
#include "core/warning_listener.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace columba {

namespace {
std::atomic<int> quietScopes{0};
std::mutex listenerMutex;
std::function<void(const std::string&)> listener;
}  // namespace

void setWarningListener(std::function<void(const std::string&)> f) {
  std::lock_guard<std::mutex> lock(listenerMutex);
  listener = std::move(f);
}

QuietWarnings::QuietWarnings() { ++quietScopes; }
QuietWarnings::~QuietWarnings() { --quietScopes; }

void warn(const SourceLocation& loc, const std::string& message) {
  if (quietScopes > 0) return;
  std::string where = loc.str();
  const std::string text = (where.empty() ? "" : where + ": ") + message;
  std::fprintf(stderr, "warning: %s\n", text.c_str());
  std::lock_guard<std::mutex> lock(listenerMutex);
  if (listener) listener(text);
}

}  // namespace columba
