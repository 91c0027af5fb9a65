// libFuzzer target: a grid volume file as a heterogeneous medium's extinction, tracked through.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::mediumGridFromBytes(data, size))
