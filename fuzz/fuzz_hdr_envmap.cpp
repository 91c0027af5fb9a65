// libFuzzer target: the image reader of environment maps (readLinearRGBImage), seeded with
// Radiance HDR files, and the environment map built from the image.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::hdrEnvmapFromBytes(data, size))
