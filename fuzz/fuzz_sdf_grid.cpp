// libFuzzer target: the Mitsuba grid volume reader (parseVolumeGrid), the SDF grid shape built from
// it and a few rays traced through its voxels.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::sdfGridFromBytes(data, size))
