// libFuzzer target: the Mitsuba serialized mesh reader (parseSerializedMesh) and the triangle mesh
// built from it.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::serializedMeshFromBytes(data, size))
