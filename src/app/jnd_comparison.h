#pragma once
// `columba compare --jnd`: how far apart two renders' colours are for a bird, in just noticeable
// differences (receptor-noise-limited distance of their cone catches), or for a human (CIEDE2000
// of their RGB in CIELAB); docs/vision.md.
#include <optional>
#include <string>
#include "io/image.h"
#include "vision/observer.h"

namespace columba {

struct JndOptions {
  std::string observer;                       // "" : the one image A's Observer attribute names, else cie1931
  std::optional<PixelRect> regionA, regionB;  // compare these regions' mean catches instead of pixels
  std::string output;                         // per-pixel dS as an EXR (and its PNG); "" for none
};

// Prints the distances (per pixel: how many pixels, their mean, median, 95th percentile and
// largest dS or dE2000; per region: the distance of the regions' mean catches or colours) and
// writes the per-pixel map. A region must lie inside each image it is read from (A's region, and
// B's, which is A's unless given): std::runtime_error naming the image, its size and the region.
void compareColours(const EXRImageFile& a, const EXRImageFile& b, const std::string& pathA, const std::string& pathB,
                    const JndOptions& options);

// The PNG written beside the map of distances OUT.exr: OUT.png.
std::string pngBesideMap(const std::string& exr);

// "X0,Y0,X1,Y1" as a non-empty rectangle of pixels [X0, X1) x [Y0, Y1); throws std::runtime_error
// naming `what` and the text. compareColours checks that it lies inside each image it is read from.
PixelRect parsePixelRect(const std::string& text, const std::string& what);

}  // namespace columba
