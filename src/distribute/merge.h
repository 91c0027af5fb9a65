#pragma once
// Putting the pieces of a split render back together (distribute/pieces.h).
//
// Parts: every pixel of a part is computed exactly as in the whole render (its samples depend
// only on pixel, sample index and seed), so parts are copied into place and the merged image is
// bit-identical to the render done in one piece.
// Passes: each pass holds the float32 mean of its samples; the merge weights each pass's mean by
// its sample count, sums in double and rounds once to float32. The one-piece render rounds the
// mean of all samples once, so the two agree to float round-off: they differ by at most about
// one float32 rounding of each pass's mean, |merged - whole| <= 2^-23 * sum_k (n_k / spp) |mean_k|
// per channel (bit-identical when there is only one pass).
#include <stdexcept>
#include <string>
#include <vector>
#include "distribute/pieces.h"

namespace columba {

// A piece of a render, read from its file.
struct Piece {
  std::string path;
  PieceInfo info;
  Image image;  // the pixels of info.window
};

// Reads a piece (or a whole image written by Columba); throws std::runtime_error naming the path.
Piece loadPiece(const std::string& path);

struct MergedImage {
  Image image;
  PieceInfo info;  // of the whole render: no part or pass; seconds is the sum of the pieces' times
  int parts = 0;   // distinct windows
  int passes = 0;  // most passes of any window
};

// Checks that `pieces` belong together (the same scene hash, defines, seed, samples per pixel,
// frame size and spectral channels; every piece finished; every pixel in exactly one window, and
// every window's passes holding each sample index exactly once) and merges them. Throws
// std::runtime_error naming every piece that is wrong, missing or overlapping.
MergedImage mergePieces(const std::vector<Piece>& pieces);
MergedImage mergePieceFiles(const std::vector<std::string>& paths);

}  // namespace columba
