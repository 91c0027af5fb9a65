// libFuzzer target: a sweep's manifest (readManifest).
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::manifestFromBytes(data, size))
