#pragma once
// While a QuietWarnings exists, warn() (core/error.h) prints nothing: for code that reads the same
// input many times (a fit loads its scene at every evaluation) and has shown its warnings once.

namespace columba {

class QuietWarnings {
 public:
  QuietWarnings();
  ~QuietWarnings();
  QuietWarnings(const QuietWarnings&) = delete;
  QuietWarnings& operator=(const QuietWarnings&) = delete;
};

}  // namespace columba
