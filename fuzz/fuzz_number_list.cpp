// libFuzzer target: a list parameter's numbers (listNumbers) as a tabulated phase function.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::numberListFromBytes(data, size))
