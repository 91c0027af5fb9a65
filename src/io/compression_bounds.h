#pragma once
// The most one byte of an image file can hold, at its format's best compression: what a header
// may declare for a file of a given length (io/declared_image_size.h).
#include <cstddef>

namespace columba {

// The most pixels one byte of the image file whose first bytes are `head` holds, told by its
// magic number: PNG (at the bits per pixel of its header), JPEG, BMP, GIF, PSD, PNM, Radiance
// HDR, and TGA (which has none) for anything else stb_image reads.
double mostPixelsPerByte(const unsigned char* head, size_t size);

// The most bytes of pixels one byte of an OpenEXR file holds with `compression` (the header's
// compression attribute).
double mostEXRBytesPerByte(int compression);

}  // namespace columba
