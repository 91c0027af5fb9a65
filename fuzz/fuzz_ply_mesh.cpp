// libFuzzer target: the mesh PLY reader (readPlyMesh) and the triangle mesh built from it.
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::plyMeshFromBytes(data, size))
