#pragma once
// The pixel data of a Radiance HDR file, checked before stb_image decodes it: stb_image reads
// zeros past the end of a file without an error, and a run-length scanline whose literal count is
// zero (or ends where the file ends) makes its decoder loop forever.
#include <cstddef>
#include <string>

namespace columba {

// Checks the `size` bytes of the Radiance HDR file `path`, of width x height pixels (as its header
// declares them), as stb_image's decoder reads them: flat pixels, or run-length scanlines whose
// runs and literals each hold 1 to the scanline's remaining pixels. Throws InputError naming the
// file and the scanline where the data is wrong or ends early.
void checkHDRScanlines(const std::string& path, const unsigned char* bytes, size_t size, int width, int height);

}  // namespace columba
