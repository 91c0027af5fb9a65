// libFuzzer target: a barbule's layer text (parseFilmLayers) and the layered film built from it.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::layerTextFromBytes(data, size))
