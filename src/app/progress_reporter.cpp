#include "app/progress_reporter.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace columba {

std::string formatDuration(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.1f}s", seconds);
  int s = int(seconds + 0.5);
  if (s < 3600) return fmt::format("{}m{:02d}s", s / 60, s % 60);
  return fmt::format("{}h{:02d}m", s / 3600, (s / 60) % 60);
}

std::string OverallProgress::eta(double itemFraction) const {
  const double f = fraction(itemFraction);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (f <= 0.0) return "ETA unknown";
  if (f >= 1.0) return "done";
  return "ETA " + formatDuration(elapsed * (1.0 - f) / f);
}

ProgressReporter::ProgressReporter(std::string label, const OverallProgress* overall)
    : label_(std::move(label)),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      overall_(overall) {}

void ProgressReporter::update(int done, int total) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto now = std::chrono::steady_clock::now();
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double fraction = total > 0 ? double(done) / total : 1.0;
  if (terminal_) {
    if (done < total && drawn_ && now - lastDraw_ < std::chrono::milliseconds(200)) return;
    lastDraw_ = now;
    drawn_ = true;
    const int width = 40;
    int filled = int(fraction * width);
    std::string bar(size_t(filled), '=');
    bar.resize(width, ' ');
    std::string eta =
        fraction > 0 && done < total ? " ETA " + formatDuration(elapsed * (1.0 - fraction) / fraction) : "";
    std::string all =
        overall_ ? fmt::format(" | all {:.0f}% {}", 100.0 * overall_->fraction(fraction), overall_->eta(fraction)) : "";
    fmt::print(stderr, "\r{} [{}] {:5.1f}% {}{}{}   ", label_, bar, 100.0 * fraction, formatDuration(elapsed), eta,
               all);
  } else {
    int percent = int(fraction * 100.0);
    if (percent / 10 == lastPercentPrinted_ / 10 && done < total) return;
    lastPercentPrinted_ = percent;
    std::string all = overall_ ? fmt::format("; all frames {:.0f}%, {}", 100.0 * overall_->fraction(fraction),
                                             overall_->eta(fraction))
                               : "";
    fmt::print(stderr, "{}: {}% after {}{}\n", label_, percent, formatDuration(elapsed), all);
  }
  std::fflush(stderr);
}

void ProgressReporter::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (terminal_ && drawn_) fmt::print(stderr, "\n");
}

}  // namespace columba
