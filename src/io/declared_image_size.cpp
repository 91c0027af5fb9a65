#include "io/declared_image_size.h"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace columba {

namespace {
std::string bytesText(double bytes) {
  if (bytes >= double(uint64_t(1) << 30)) return fmt::format("{:.1f} GiB", bytes / double(uint64_t(1) << 30));
  return fmt::format("{:.1f} MiB", bytes / double(1 << 20));
}
}  // namespace

void checkImageMemory(const std::string& path, int64_t width, int64_t height, int64_t channels, int64_t bytesPerSample,
                      const std::string& declared) {
  const std::string size = fmt::format("{} {} x {} pixels of {} channels", declared, width, height, channels);
  if (width < 1 || height < 1 || channels < 1) throw InputError({path, 0}, size + ": no samples");
  // In double: each factor is below 2^63, so the product is finite and close enough to compare.
  const double bytes = double(width) * double(height) * double(channels) * double(bytesPerSample);
  if (bytes > double(kImageMemoryBudget))
    throw InputError({path, 0}, fmt::format("{} ({}), more than the {} an image may take", size, bytesText(bytes),
                                            bytesText(double(kImageMemoryBudget))));
}

void checkDeclaredImageSize(const std::string& path, int64_t width, int64_t height, int64_t channels,
                            int64_t bytesPerSample, uint64_t fileBytes, double mostSamplesPerByte) {
  const double samples = double(width) * double(height) * double(channels);
  if (width > 0 && height > 0 && channels > 0 && samples > double(fileBytes) * mostSamplesPerByte)
    throw InputError({path, 0},
                     fmt::format("the header declares {} x {} pixels of {} channels, more than a file of "
                                 "{} bytes can hold (at most {:.0f} samples)",
                                 width, height, channels, fileBytes, double(fileBytes) * mostSamplesPerByte));
  checkImageMemory(path, width, height, channels, bytesPerSample);
}

uint64_t fileLength(const std::string& path) {
  std::error_code ec;
  const uint64_t length = std::filesystem::file_size(path, ec);
  if (ec) throw InputError({path, 0}, "cannot read the file: " + ec.message());
  return length;
}

}  // namespace columba
