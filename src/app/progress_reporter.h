#pragma once
// Progress of long work on stderr: a bar with ETA on a terminal, plain lines otherwise.
#include <chrono>
#include <mutex>
#include <string>

namespace columba {

// Where one piece of work stands in a longer run (a frame of a sweep): `done` of `total` items
// finished since `start`; the reporter adds the run's progress and ETA to the item's.
struct OverallProgress {
  int done = 0, total = 1;
  std::chrono::steady_clock::time_point start;
  // The fraction of the run done when the current item is `fraction` done, and the ETA of the run.
  double fraction(double itemFraction) const { return (done + itemFraction) / total; }
  std::string eta(double itemFraction) const;
};

class ProgressReporter {
 public:
  explicit ProgressReporter(std::string label, const OverallProgress* overall = nullptr);
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
  const OverallProgress* overall_;
  std::mutex mutex_;
};

std::string formatDuration(double seconds);

}  // namespace columba
