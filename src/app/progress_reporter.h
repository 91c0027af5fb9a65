#pragma once
// Progress of long work on stderr: a bar with ETA on a terminal, plain lines otherwise.
#include <chrono>
#include <mutex>
#include <string>

namespace columba {

class ProgressReporter {
 public:
  explicit ProgressReporter(std::string label);
  // Thread-safe; redraws at most a few times per second.
  void update(int done, int total);
  // Ends the bar's line (call once the work is over).
  void finish();

 private:
  std::string label_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  int lastPercentPrinted_ = -1;
  bool drawn_ = false;
  std::mutex mutex_;
};

std::string formatDuration(double seconds);

}  // namespace columba
