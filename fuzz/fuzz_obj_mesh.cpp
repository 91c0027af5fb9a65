// libFuzzer target: the OBJ reader (readObjMesh) and the triangle mesh built from it.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::objMeshFromBytes(data, size))
