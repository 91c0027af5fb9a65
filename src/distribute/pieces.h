#pragma once
// A render split into independent pieces: parts (bands of rows of the image, chosen so that
// they cost about the same) and passes (disjoint ranges of every pixel's sample indices). A
// piece is written as an EXR whose data window is its part's rows and whose attributes say
// what it belongs to, so that `mergePieces` (distribute/merge.h) can check that pieces fit
// together and put them back.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include "io/image.h"

namespace columba {

// "K/N": the K-th (1-based) of N.
struct PieceIndex {
  int index = 1, count = 1;
  std::string str() const { return std::to_string(index) + "/" + std::to_string(count); }
  bool operator==(const PieceIndex& o) const { return index == o.index && count == o.count; }
};
// Parses "K/N" with 1 <= K <= N <= `most`; `option` names it in the error (std::runtime_error).
PieceIndex parsePieceIndex(const std::string& option, const std::string& text, int most);

// Row boundaries of `parts` bands of the image, 0 = b[0] < b[1] < ... < b[parts] = rows, chosen
// so that each band's share of `rowCosts` (one cost per row) is as close to 1/parts of the total
// as whole rows allow. Throws std::runtime_error when there are fewer rows than parts.
std::vector<int> balancedRowBands(const std::vector<uint64_t>& rowCosts, int parts);
// The pixels of part `part` (1-based) of the bands `bounds` in an image `width` pixels wide.
PixelRect partWindow(const std::vector<int>& bounds, int part, int width);
// The sample indices [begin, end) of pass K/N of `spp` samples per pixel: contiguous ranges of
// sizes differing by at most one (pass 1 starts at 0). Throws when spp < N.
std::pair<int, int> passSamples(const PieceIndex& pass, int spp);

// The file a piece of the render to `output` (an .exr or .png name) is written to:
// OUT.part2of4.exr, OUT.pass1of2.exr, OUT.part2of4.pass1of2.exr (always EXR).
std::string pieceFileName(const std::string& output, const std::optional<PieceIndex>& part,
                          const std::optional<PieceIndex>& pass);
// Where an interrupted render (whole or piece) to `path` goes instead: NAME.partial.EXT.
std::string partialFileName(const std::string& path);

// A 64-bit FNV-1a hash of `bytes`, as 16 hexadecimal digits: identifies a scene's text.
std::string textHash(const std::string& bytes);

// What a piece (or a whole image) records about the render it belongs to, in its EXR attributes.
struct PieceInfo {
  std::string scene;                    // the scene file as given ("Scene")
  std::string sceneHash;                // textHash of the scene file ("Scene hash")
  std::string defines;                  // the -D values, one name=value a line ("Defines")
  uint64_t seed = 0;                    // "Seed"
  int spp = 0;                          // of the whole render ("Samples per pixel")
  int frameWidth = 0, frameHeight = 0;  // of the whole image ("Frame size", "512x512")
  std::string spectral;                 // the spectral channels' description, "" for RGB ("Spectral channels")
  std::string observer;                 // the cone channels' description, "" for none ("Observer")
  bool complete = true;                 // "Status": "complete" or "interrupted"
  double seconds = 0.0;                 // "Render time"
  // Set for pieces only:
  std::optional<PieceIndex> part;  // "Part", with its band's rows in "Part rows"
  std::vector<int> partBounds;     // every band's bounds: "0,130,260,390,512" ("Part bounds")
  std::optional<PieceIndex> pass;  // "Pass", with the sample indices [begin, end) in "Pass samples"
  int sampleBegin = 0, sampleEnd = 0;
  PixelRect window;  // the EXR data window (not an attribute)
};

ImageMetadata pieceMetadata(const PieceInfo& info);
// Reads what pieceMetadata wrote (and what a whole render records); throws std::runtime_error
// naming `path` and the attribute that is missing or malformed.
PieceInfo pieceInfoFromFile(const std::string& path, const EXRImageFile& file);

}  // namespace columba
