// libFuzzer target: the feather PLY reader (readFeatherPly) and the feather shape built from it.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::featherPlyFromBytes(data, size))
