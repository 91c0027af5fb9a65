#pragma once
// Images the texture tests write for themselves.
#include <string>
#include "io/image.h"

namespace columba::testing {

// A grey OpenEXR image of two texels in one row, `left` then `right` in every channel, written to
// `path` (returned): looked up at u = 1/4 and 3/4, or blended between them.
inline std::string writeTwoTexelEXR(const std::string& path, float left, float right) {
  Image texels(2, 1);
  for (int c = 0; c < 3; ++c) {
    texels.rgb[c] = left;
    texels.rgb[3 + c] = right;
  }
  writeEXR(path, texels);
  return path;
}

}  // namespace columba::testing
