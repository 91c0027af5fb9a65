// libFuzzer target: a table of measured spectra (readSpectraCSV).
#include "fuzz_main.h"
#include "fuzz_targets.h"
COLUMBA_FUZZ_TARGET(columba::fuzz::spectraCSVFromBytes(data, size))
