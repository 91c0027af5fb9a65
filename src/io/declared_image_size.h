#pragma once
// The size an image file's header declares, checked before anything is allocated for it: a
// corrupt or hostile header must cost an error naming the file, not gigabytes of memory or
// minutes spent decoding pixels that are not there. Every image reader goes through here
// (io/image.h, io/image_file_reader.h), and so does the merge of a split render's pieces for the
// frame they declare (distribute/merge.h).
#include <cstdint>
#include <string>

namespace columba {

// The most memory the samples of one image read from a file may take.
constexpr uint64_t kImageMemoryBudget = uint64_t(4) << 30;

// Throws InputError naming `path` and the declared size when an image of width x height pixels
// of `channels` samples, `bytesPerSample` bytes each in memory, is empty or takes more than
// kImageMemoryBudget. `declared` says what the size is (the message's subject).
void checkImageMemory(const std::string& path, int64_t width, int64_t height, int64_t channels, int64_t bytesPerSample,
                      const std::string& declared = "the header declares");

// checkImageMemory, and the same error when the image has more samples than a file of
// `fileBytes` bytes can hold: `mostSamplesPerByte` of them a byte at most, its format's best
// compression (io/compression_bounds.h).
void checkDeclaredImageSize(const std::string& path, int64_t width, int64_t height, int64_t channels,
                            int64_t bytesPerSample, uint64_t fileBytes, double mostSamplesPerByte);

// The length of the file at `path` in bytes; InputError naming it when it cannot be read.
uint64_t fileLength(const std::string& path);

}  // namespace columba
