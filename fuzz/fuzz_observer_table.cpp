// libFuzzer target: an observer's table of sensitivities (observerTableFromBytes).
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::observerTableFromBytes(data, size))
