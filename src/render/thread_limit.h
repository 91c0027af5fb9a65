#pragma once
// A render's thread count: `threads` > 0 limits oneTBB to that many while the returned object
// lives; 0 leaves it all the hardware's (and returns null).
#include <tbb/global_control.h>

#include <memory>

namespace columba {

inline std::unique_ptr<tbb::global_control> limitThreads(int threads) {
  if (threads <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
}

}  // namespace columba
