// libFuzzer target: the image reader of bitmap textures (readImagePixels) in every format it
// reads, the texture built from the image, and readPNG.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::bitmapFromBytes(data, size))
