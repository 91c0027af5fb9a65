// libFuzzer target: an observer's definition by its cones' parameters (observerDefinitionFromBytes).
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::observerDefinitionFromBytes(data, size))
