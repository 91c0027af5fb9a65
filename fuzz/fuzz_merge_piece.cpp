// libFuzzer target: a piece of a split render (loadPiece) and its merge.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::mergePieceFromBytes(data, size))
