// libFuzzer target: the EXR reader (readEXR) and the environment map built from the image.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::exrEnvmapFromBytes(data, size))
