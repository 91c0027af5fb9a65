// libFuzzer target: scene XML (with leading `-Dname=value` lines as -D defines) through
// loadSceneString and Scene construction. Relative file names resolve against examples/, so
// the fuzzer can reach the feather shape through tiny_feather.ply.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::sceneFromBytes(data, size, COLUMBA_SOURCE_DIR "/examples"))
