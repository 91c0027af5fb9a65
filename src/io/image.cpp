#include "io/image.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <png.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <thread>
#include "core/error.h"
#include "core/spectrum.h"
#include "core/version.h"
#include "io/compression_bounds.h"
#include "io/declared_image_size.h"
#include "io/output_directory.h"

namespace columba {

namespace {

int writerThreads = 1;  // setImageWriterThreads

void checkImage(const std::string& path, const Image& image) {
  const size_t pixels = size_t(std::max(image.width, 0)) * size_t(std::max(image.height, 0));
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != pixels * 3)
    throw std::runtime_error("cannot write '" + path + "': image of " + std::to_string(image.width) + " x " +
                             std::to_string(image.height) + " pixels holds " + std::to_string(image.rgb.size()) +
                             " values");
  if (image.spectral.values.size() != pixels * image.spectral.count())
    throw std::runtime_error("cannot write '" + path + "': its " + std::to_string(image.spectral.count()) +
                             " spectral bands hold " + std::to_string(image.spectral.values.size()) + " values");
  if (image.cones.values.size() != pixels * image.cones.count())
    throw std::runtime_error("cannot write '" + path + "': its " + std::to_string(image.cones.count()) +
                             " cone channels hold " + std::to_string(image.cones.values.size()) + " values");
}

// Metadata with Columba's own entry first.
ImageMetadata withSoftware(const ImageMetadata& metadata) {
  ImageMetadata all = {{"Software", std::string("Columba ") + kColumbaVersion}};
  all.insert(all.end(), metadata.begin(), metadata.end());
  return all;
}

// The image's pixels lie at `window` of a frame of frameWidth x frameHeight (by default, the
// image is the whole frame).
void writeEXRFile(const std::string& file, const Image& image, const ImageMetadata& metadata,
                  const PixelRect* window = nullptr, int frameWidth = 0, int frameHeight = 0) {
  const Imath::Box2i data = window ? Imath::Box2i({window->x0, window->y0}, {window->x1 - 1, window->y1 - 1})
                                   : Imath::Box2i({0, 0}, {image.width - 1, image.height - 1});
  const Imath::Box2i display = window ? Imath::Box2i({0, 0}, {frameWidth - 1, frameHeight - 1}) : data;
  Imf::Header header(display, data);
  for (const auto& [name, text] : metadata) header.insert(name, Imf::StringAttribute(text));
  Imf::FrameBuffer frame;
  auto slice = [&](const float* first, size_t x, size_t y) { return Imf::Slice::Make(Imf::FLOAT, first, data, x, y); };
  // The colour channels' names and values, `names.size()` floats per pixel.
  const EXRColour colour = window ? EXRColour::RGB : image.exrColour;
  // What the colour channels mean, for a compositor: linear Rec. 709 / sRGB primaries with a D65
  // white (OpenEXR's default chromaticities), or for XYZ the primaries that make R, G, B the CIE
  // X, Y, Z (red (1, 0), green (0, 1), blue (0, 0), white the equal-energy (1/3, 1/3)).
  Imf::addChromaticities(header, colour == EXRColour::XYZ
                                     ? Imf::Chromaticities({1, 0}, {0, 1}, {0, 0}, {1.0f / 3.0f, 1.0f / 3.0f})
                                     : Imf::Chromaticities());
  std::vector<const char*> names = {"R", "G", "B"};
  std::vector<float> converted;
  if (colour != EXRColour::RGB) {
    names = colour == EXRColour::Luminance ? std::vector<const char*>{"Y"} : std::vector<const char*>{"X", "Y", "Z"};
    converted.reserve(image.rgb.size() / 3 * names.size());
    for (size_t i = 0; i < image.rgb.size(); i += 3) {
      const Vec3 xyz = linearRGBToXYZ(Vec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]));
      if (colour == EXRColour::Luminance) {
        converted.push_back(xyz.y);
      } else {
        converted.insert(converted.end(), {xyz.x, xyz.y, xyz.z});
      }
    }
  }
  const float* values = colour == EXRColour::RGB ? image.rgb.data() : converted.data();
  const size_t xStride = names.size() * sizeof(float), yStride = xStride * size_t(image.width);
  for (size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], slice(values + c, xStride, yStride));
  }
  const SpectralBands& bands = image.spectral;
  const size_t bandStride = bands.count() * sizeof(float);
  for (size_t b = 0; b < bands.count(); ++b) {
    std::string name = spectralChannelName(bands.centres[b]);
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    frame.insert(name, slice(bands.values.data() + b, bandStride, bandStride * size_t(image.width)));
  }
  const NamedChannels& cones = image.cones;
  const size_t coneStride = cones.count() * sizeof(float);
  for (size_t c = 0; c < cones.count(); ++c) {
    header.channels().insert(cones.names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(cones.names[c], slice(cones.values.data() + c, coneStride, coneStride * size_t(image.width)));
  }

  // OpenEXR finishes the file in its destructor, which swallows errors: the stream's state
  // tells whether everything reached the disk.
  std::ofstream stream(file, std::ios::binary | std::ios::trunc);
  if (!stream) throw std::runtime_error(std::strerror(errno));
  {
    Imf::StdOFStream exrStream(stream, file.c_str());
    Imf::OutputFile out(exrStream, header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
  }
  stream.close();
  if (!stream) throw std::runtime_error("write error");
}

// libpng reports errors through a callback that must not return: it records the message and
// jumps back to the setjmp in encodePNG.
void onPNGError(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}
void onPNGWarning(png_structp, png_const_charp) {}

bool isASCII(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
}

// Encodes prepared rows and text chunks into `out`; returns false with `error` set if libpng
// fails. Nothing in this frame has a destructor: a libpng error longjmps back into it.
bool encodePNG(FILE* out, png_uint_32 width, png_uint_32 height, png_bytep* rows, png_text* texts, int textCount,
               std::string* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, onPNGError, onPNGWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, out);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_text(png, info, texts, textCount);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

void writePNGFile(const std::string& file, const Image& image, const ImageMetadata& metadata) {
  std::vector<unsigned char> bytes(image.rgb.size());
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = toSRGB8(image.rgb[i]);
  std::vector<png_bytep> rows(size_t(image.height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * 3 * size_t(image.width);
  // tEXt holds Latin-1; text with other characters (such as UTF-8 paths) goes in an iTXt chunk.
  std::vector<png_text> texts(metadata.size());
  for (size_t i = 0; i < metadata.size(); ++i) {
    texts[i].compression = isASCII(metadata[i].second) ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
    texts[i].key = const_cast<char*>(metadata[i].first.c_str());
    texts[i].text = const_cast<char*>(metadata[i].second.c_str());
    texts[i].text_length = metadata[i].second.size();
  }
  FILE* out = std::fopen(file.c_str(), "wb");
  if (!out) throw std::runtime_error(std::strerror(errno));
  std::string error;
  bool encoded = encodePNG(out, png_uint_32(image.width), png_uint_32(image.height), rows.data(), texts.data(),
                           int(texts.size()), &error);
  if (std::fclose(out) != 0 && encoded) throw std::runtime_error(std::string("write error: ") + std::strerror(errno));
  if (!encoded) throw std::runtime_error(error.empty() ? "cannot set up the PNG writer" : error);
}

// One file of a set written through temporary files: where it goes and how it is written.
struct PendingFile {
  std::string path;
  const char* format;
  std::function<void(const std::string&)> write;
};

// Holds an exclusive lock on a directory while alive (none where the directory cannot be opened).
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::string& dir) : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~DirectoryLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_;
};

// Writes every file to a temporary file beside it, then renames all of them into place. If a
// write fails, nothing is renamed; if a rename fails, the files already renamed get their old
// contents back (kept as hard links, or copies, until the last rename). Temporary files never
// outlive the call.
void replaceTogether(const std::vector<PendingFile>& files) {
  const std::string suffix = std::to_string(::getpid());
  std::vector<std::string> temporaries, backups(files.size());
  auto removeAll = [](const std::vector<std::string>& paths) {
    for (const std::string& p : paths)
      if (!p.empty()) std::remove(p.c_str());
  };
  // The temporary files, side by side when there are threads for it.
  std::vector<std::exception_ptr> failures(files.size());
  for (const PendingFile& file : files) temporaries.push_back(file.path + ".tmp" + suffix);
  auto writeOne = [&](size_t i) {
    try {
      files[i].write(temporaries[i]);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  };
  const bool sideBySide = writerThreads > 1;
  std::vector<std::thread> helpers;
  for (size_t i = 1; sideBySide && i < files.size(); ++i) helpers.emplace_back(writeOne, i);
  for (size_t i = 0; i < (sideBySide ? 1 : files.size()); ++i) writeOne(i);
  for (std::thread& helper : helpers) helper.join();
  for (size_t i = 0; i < files.size(); ++i) {
    if (!failures[i]) continue;
    removeAll(temporaries);
    try {
      std::rethrow_exception(failures[i]);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("cannot write ") + files[i].format + " '" + files[i].path +
                               "': " + e.what());
    }
  }

  DirectoryLock lock(directoryOf(files.front().path));
  if (files.size() > 1) {
    for (size_t i = 0; i < files.size(); ++i) {
      const std::string backup = files[i].path + ".old" + suffix;
      std::error_code ec;
      if (::link(files[i].path.c_str(), backup.c_str()) == 0 ||
          (errno != ENOENT && std::filesystem::copy_file(files[i].path, backup, ec)))
        backups[i] = backup;
    }
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(temporaries[i].c_str(), files[i].path.c_str()) == 0) continue;
    const std::string reason = std::strerror(errno);
    for (size_t j = 0; j < i; ++j) {
      if (!backups[j].empty())
        std::rename(backups[j].c_str(), files[j].path.c_str());
      else
        std::remove(files[j].path.c_str());
    }
    removeAll(temporaries);
    removeAll(backups);
    throw std::runtime_error(std::string("cannot write ") + files[i].format + " '" + files[i].path +
                             "': cannot rename the temporary file into place: " + reason +
                             (i > 0 ? " (the files written with it were restored)" : ""));
  }
  removeAll(backups);
}

}  // namespace

namespace {
// The bin centre of a channel named as spectralChannelName does, if it is one.
std::optional<float> spectralChannelCentre(const std::string& name) {
  if (name.size() < 6 || name.compare(0, 3, "S0.") != 0 || name.compare(name.size() - 2, 2, "nm") != 0)
    return std::nullopt;
  std::string number = name.substr(3, name.size() - 5);
  std::replace(number.begin(), number.end(), ',', '.');
  char* end = nullptr;
  float value = std::strtof(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool isConeChannel(const std::string& name) {
  const std::vector<std::string>& names = coneChannelNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}
}  // namespace

ToneMap toneMapNamed(const std::string& name) {
  if (name == "clamp") return ToneMap::Clamp;
  if (name == "reinhard") return ToneMap::Reinhard;
  throw std::invalid_argument("unknown tone mapping '" + name + "' (known: clamp, reinhard)");
}

const std::vector<std::string>& coneChannelNames() {
  static const std::vector<std::string> names = {"UVS", "VS", "SWS", "MWS", "LWS", "DBL"};
  return names;
}

std::string spectralChannelName(float lambdaNm) {
  std::string centre = fmt::format("{:g}", double(lambdaNm));
  std::replace(centre.begin(), centre.end(), '.', ',');
  return "S0." + centre + "nm";
}

void setImageWriterThreads(int threads) {
  writerThreads = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  Imf::setGlobalThreadCount(writerThreads > 1 ? writerThreads : 0);
}

void writeEXR(const std::string& path, const Image& image, const ImageMetadata& metadata) {
  checkImage(path, image);
  const ImageMetadata all = withSoftware(metadata);
  replaceTogether({{path, "EXR", [&](const std::string& file) { writeEXRFile(file, image, all); }}});
}

void writeEXRWindow(const std::string& path, const Image& image, const PixelRect& window, int frameWidth,
                    int frameHeight, const ImageMetadata& metadata) {
  checkImage(path, image);
  if (window.width() != image.width || window.height() != image.height || window.x0 < 0 || window.y0 < 0 ||
      window.x1 > frameWidth || window.y1 > frameHeight)
    throw std::runtime_error(fmt::format(
        "cannot write '{}': an image of {} x {} pixels does not fill the window "
        "[{}, {}) x [{}, {}) of a frame of {} x {}",
        path, image.width, image.height, window.x0, window.x1, window.y0, window.y1, frameWidth, frameHeight));
  const ImageMetadata all = withSoftware(metadata);
  replaceTogether({{path, "EXR", [&](const std::string& file) {
                      writeEXRFile(file, image, all, &window, frameWidth, frameHeight);
                    }}});
}

std::string metadataValue(const ImageMetadata& metadata, const std::string& name) {
  for (const auto& [key, text] : metadata)
    if (key == name) return text;
  return "";
}

Image falseColour(const Image& image) {
  Image shown(image.width, image.height);
  const size_t n = image.cones.count();
  auto index = [&](const char* name) {
    for (size_t c = 0; c < n; ++c)
      if (image.cones.names[c] == name) return int(c);
    return -1;
  };
  const int lws = index("LWS"), mws = index("MWS"), sws = index("SWS");
  const int shortest = index("UVS") >= 0 ? index("UVS") : index("VS");
  for (size_t p = 0; p < shown.rgb.size() / 3; ++p) {
    const float* q = &image.cones.values[p * n];
    auto at = [&](int c) { return c >= 0 ? q[c] : 0.0f; };
    shown.rgb[3 * p + 0] = (2.0f * at(lws) + at(shortest)) / 3.0f;
    shown.rgb[3 * p + 1] = at(mws);
    shown.rgb[3 * p + 2] = (2.0f * at(sws) + at(shortest)) / 3.0f;
  }
  return shown;
}

namespace {
// What a PNG of the image shows: its RGB, or the false colour of its cone catches, scaled by
// 2^exposure and tone mapped (the PNG writer clamps what is left above 1).
Image previewOf(const Image& image, float exposure, ToneMap toneMap) {
  Image preview = image.cones.count() > 0 ? falseColour(image) : image;
  const float scale = std::exp2(exposure);
  if (exposure != 0.0f)
    for (float& v : preview.rgb) v *= scale;
  if (toneMap == ToneMap::Reinhard)
    for (size_t p = 0; p < preview.rgb.size(); p += 3) {
      float* c = &preview.rgb[p];
      const float luminance = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
      if (!(luminance > 0.0f)) continue;
      for (int k = 0; k < 3; ++k) c[k] /= 1.0f + luminance;
    }
  return preview;
}
}  // namespace

void writePNG(const std::string& path, const Image& image, const ImageMetadata& metadata) {
  checkImage(path, image);
  const ImageMetadata all = withSoftware(metadata);
  const Image preview = previewOf(image, 0.0f, ToneMap::Clamp);
  replaceTogether({{path, "PNG", [&](const std::string& file) { writePNGFile(file, preview, all); }}});
}

void writeEXRAndPNG(const std::string& exrPath, const std::string& pngPath, const Image& image,
                    const ImageMetadata& metadata, float pngExposure, ToneMap toneMap) {
  checkImage(exrPath, image);
  const ImageMetadata all = withSoftware(metadata);
  const Image preview = previewOf(image, pngExposure, toneMap);
  replaceTogether({{exrPath, "EXR", [&](const std::string& file) { writeEXRFile(file, image, all); }},
                   {pngPath, "PNG", [&](const std::string& file) { writePNGFile(file, preview, all); }}});
}

ImageFormat checkOutputImagePath(const std::string& path, bool directoryMayBeMade) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw std::runtime_error("cannot write '" + path + "': it is a directory");
  const std::string given = fs::path(path).extension().string();
  std::string extension = given;
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".exr" && extension != ".png")
    throw std::runtime_error(
        "cannot write '" + path +
        "': " + (given.empty() ? "the name has no extension" : "'" + given + "' is not a format Columba writes") +
        " (use .exr or .png)");
  if (directoryMayBeMade)
    checkOutputDirectory(path, directoryOf(path));
  else if (!fs::is_directory(directoryOf(path), ec))
    throw std::runtime_error("cannot write '" + path + "': the directory '" + directoryOf(path) + "' does not exist");
  return extension == ".exr" ? ImageFormat::EXR : ImageFormat::PNG;
}

// An EXR header's pixels, checked before they are allocated: by OpenEXR as it opens the file
// (its line buffers), then by readEXRFile (3 floats a pixel and one a spectral band). A header
// declaring more than its compression can fit in the file is an error, not gigabytes.
struct EXRDeclaredSize {
  int64_t width = 0, height = 0;
  double storedBytesPerPixel = 0;  // of every channel, at its sampling
  int64_t spectralBands = 0;       // and cone channels: one float a pixel each
  int compression = 0;
};

static void checkEXRDeclaredSize(const std::string& path, const EXRDeclaredSize& size) {
  const int64_t held = 3 + size.spectralBands;
  // A header without channels still has OpenEXR read a line offset table: a byte a pixel at least.
  const double stored = std::max(size.storedBytesPerPixel, 1.0);
  checkDeclaredImageSize(path, size.width, size.height, held, sizeof(float), fileLength(path),
                         mostEXRBytesPerByte(size.compression) * double(held) / stored);
}

static int exrSampleBytes(int pixelType) { return pixelType == Imf::HALF ? 2 : 4; }

// Adds a chlist attribute's channels (name, int32 pixel type, 4 bytes, int32 x and y sampling,
// ending with an empty name) to `size`; returns the bytes the list takes to its end, as OpenEXR
// reads it (0 if it has no end).
static size_t addEXRChannels(const std::string& list, EXRDeclaredSize& size) {
  for (size_t at = 0; at < list.size();) {
    if (list[at] == '\0') return at + 1;
    const size_t end = list.find('\0', at);
    if (end == std::string::npos || list.size() - end - 1 < 16) return 0;
    int32_t fields[4];
    std::memcpy(fields, list.data() + end + 1, sizeof fields);
    size.storedBytesPerPixel +=
        double(exrSampleBytes(fields[0])) / std::max(1.0, double(fields[2])) / std::max(1.0, double(fields[3]));
    if (spectralChannelCentre(list.substr(at, end - at)) || isConeChannel(list.substr(at, end - at)))
      ++size.spectralBands;
    at = end + 17;
  }
  return 0;
}

// The bytes OpenEXR reads for a header attribute's value of type `type` with `value` (of the
// size the file declares): a fixed size for most types, whatever the file declares; the channel
// list to its end; a preview image by its width and height. 0 for the types it reads by the
// declared size.
static size_t exrAttributeValueBytes(const std::string& type, const std::string& value) {
  static const std::map<std::string, size_t> fixed = {{"box2i", 16},
                                                      {"box2f", 16},
                                                      {"chromaticities", 32},
                                                      {"compression", 1},
                                                      {"deepImageState", 1},
                                                      {"double", 8},
                                                      {"envmap", 1},
                                                      {"float", 4},
                                                      {"int", 4},
                                                      {"keycode", 28},
                                                      {"lineOrder", 1},
                                                      {"m33f", 36},
                                                      {"m33d", 72},
                                                      {"m44f", 64},
                                                      {"m44d", 128},
                                                      {"rational", 8},
                                                      {"tiledesc", 9},
                                                      {"timecode", 8},
                                                      {"v2i", 8},
                                                      {"v2f", 8},
                                                      {"v2d", 16},
                                                      {"v3i", 12},
                                                      {"v3f", 12},
                                                      {"v3d", 24}};
  if (auto f = fixed.find(type); f != fixed.end()) return f->second;
  if (type == "chlist") {  // without its end in the declared bytes, OpenEXR reads past them
    EXRDeclaredSize ignored;
    const size_t end = addEXRChannels(value, ignored);
    return end ? end : value.size() + 1;
  }
  if (type == "preview" && value.size() >= 8) {
    uint32_t size[2];
    std::memcpy(size, value.data(), sizeof size);
    return 8 + 4 * size_t(size[0]) * size_t(size[1]);
  }
  return 0;
}

// OpenEXR allocates every header attribute at the size the file declares before reading it (a
// string attribute declaring 2 GB takes seconds and gigabytes): each declared size is checked
// against the bytes the file has left first, and each header's pixels as checkEXRDeclaredSize
// does. Files that are not EXR, or end early, are left to OpenEXR to report.
static void checkEXRAttributeSizes(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return;
  const std::streamoff fileSize = in.tellg();
  in.seekg(0);
  unsigned char start[8];
  if (!in.read(reinterpret_cast<char*>(start), 8) || start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 ||
      start[3] != 0x01)
    return;
  const bool multipart = start[5] & 0x10;  // bit 12 of the version field
  bool headerEmpty = true;
  EXRDeclaredSize size;
  for (std::string name, type; std::getline(in, name, '\0');) {
    if (name.empty()) {  // the end of a header; a multi-part file ends with an empty header
      if (!headerEmpty) checkEXRDeclaredSize(path, size);
      if (!multipart || headerEmpty) return;
      headerEmpty = true;
      size = EXRDeclaredSize();
      continue;
    }
    headerEmpty = false;
    unsigned char sizeBytes[4];
    if (!std::getline(in, type, '\0') || !in.read(reinterpret_cast<char*>(sizeBytes), 4)) return;
    const int32_t declared = int32_t(uint32_t(sizeBytes[0]) | uint32_t(sizeBytes[1]) << 8 |
                                     uint32_t(sizeBytes[2]) << 16 | uint32_t(sizeBytes[3]) << 24);
    const std::streamoff left = fileSize - in.tellg();
    if (declared < 0 || declared > left)
      throw InputError({path, 0}, "EXR header attribute '" + name.substr(0, 60) + "' declares " +
                                      std::to_string(declared) + " bytes but the file has " + std::to_string(left) +
                                      " bytes left");
    std::string value(size_t(declared), '\0');
    if (!in.read(value.data(), declared)) return;
    // OpenEXR goes on reading where its reader of the type stops: a value of another size than
    // the one declared would have it read the rest of the header out of step with this check.
    if (const size_t read = exrAttributeValueBytes(type, value); read != 0 && read != size_t(declared))
      throw InputError({path, 0}, "EXR header attribute '" + name.substr(0, 60) + "' of type '" + type.substr(0, 60) +
                                      "' declares " + std::to_string(declared) + " bytes, but its value takes " +
                                      std::to_string(read));
    if (name == "dataWindow" && type == "box2i" && declared == 16) {
      int32_t box[4];
      std::memcpy(box, value.data(), sizeof box);
      size.width = int64_t(box[2]) - box[0] + 1;
      size.height = int64_t(box[3]) - box[1] + 1;
    } else if (name == "channels" && type == "chlist") {
      addEXRChannels(value, size);
    } else if (name == "compression" && type == "compression" && declared == 1) {
      size.compression = static_cast<unsigned char>(value[0]);
    }
  }
}

Image readEXR(const std::string& path) { return readEXRFile(path).image; }

EXRImageFile readEXRFile(const std::string& path, bool pixels) {
  try {
    checkEXRAttributeSizes(path);
    Imf::InputFile file(path.c_str());
    EXRImageFile result;
    for (auto a = file.header().begin(); a != file.header().end(); ++a)
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&a.attribute()))
        result.metadata.emplace_back(a.name(), text->value());
    const Imath::Box2i window = file.header().dataWindow();
    const Imath::Box2i display = file.header().displayWindow();
    result.dataWindow = {window.min.x, window.min.y, window.max.x + 1, window.max.y + 1};
    result.frameWidth = display.max.x - display.min.x + 1;
    result.frameHeight = display.max.y - display.min.y + 1;
    const Imf::ChannelList& channels = file.header().channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool xyz = !rgb && channels.findChannel("X") && channels.findChannel("Y") && channels.findChannel("Z");
    if (!rgb && !channels.findChannel("Y"))
      throw InputError({path, 0}, "EXR image has neither R, G, B, nor X, Y, Z, nor Y channels");
    const int64_t width = int64_t(window.max.x) - window.min.x + 1, height = int64_t(window.max.y) - window.min.y + 1;
    EXRDeclaredSize size{width, height, 0.0, 0, int(file.header().compression())};
    for (auto c = channels.begin(); c != channels.end(); ++c) {
      size.storedBytesPerPixel += double(exrSampleBytes(c.channel().type)) / std::max(1, c.channel().xSampling) /
                                  std::max(1, c.channel().ySampling);
      if (spectralChannelCentre(c.name()) || isConeChannel(c.name())) ++size.spectralBands;
    }
    checkEXRDeclaredSize(path, size);
    if (!pixels) return result;
    Image& image = result.image;
    image = Image(static_cast<int>(width), static_cast<int>(height));
    const size_t xStride = 3 * sizeof(float), yStride = xStride * size_t(image.width);
    auto slice = [&](int c) { return Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, window, xStride, yStride); };
    Imf::FrameBuffer frame;
    if (rgb || xyz) {
      const char *names[3] = {"R", "G", "B"}, *xyzNames[3] = {"X", "Y", "Z"};
      for (int c = 0; c < 3; ++c) frame.insert(rgb ? names[c] : xyzNames[c], slice(c));
    } else {
      frame.insert("Y", slice(0));
    }
    // Spectral bands, in the order of their wavelengths.
    std::vector<std::pair<float, std::string>> bands;
    for (auto c = channels.begin(); c != channels.end(); ++c)
      if (std::optional<float> centre = spectralChannelCentre(c.name())) bands.emplace_back(*centre, c.name());
    std::sort(bands.begin(), bands.end());
    image.spectral.values.assign(size_t(image.width) * image.height * bands.size(), 0.0f);
    const size_t bandStride = bands.size() * sizeof(float);
    for (size_t b = 0; b < bands.size(); ++b) {
      image.spectral.centres.push_back(bands[b].first);
      frame.insert(bands[b].second, Imf::Slice::Make(Imf::FLOAT, image.spectral.values.data() + b, window, bandStride,
                                                     bandStride * size_t(image.width)));
    }
    for (const std::string& name : coneChannelNames())
      if (channels.findChannel(name)) image.cones.names.push_back(name);
    image.cones.values.assign(size_t(image.width) * image.height * image.cones.count(), 0.0f);
    const size_t coneStride = image.cones.count() * sizeof(float);
    for (size_t c = 0; c < image.cones.count(); ++c)
      frame.insert(image.cones.names[c], Imf::Slice::Make(Imf::FLOAT, image.cones.values.data() + c, window, coneStride,
                                                          coneStride * size_t(image.width)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    image.exrColour = rgb ? EXRColour::RGB : xyz ? EXRColour::XYZ : EXRColour::Luminance;
    for (size_t i = 0; !rgb && i < image.rgb.size(); i += 3) {
      float* p = &image.rgb[i];
      if (xyz) {
        const Vec3 c = xyzToLinearRGB(Vec3(p[0], p[1], p[2]));
        p[0] = c.x;
        p[1] = c.y;
        p[2] = c.z;
      } else {  // grey
        p[1] = p[2] = p[0];
      }
    }
    return result;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError({path, 0}, std::string("cannot read EXR image: ") + e.what());
  }
}

Image readPNG(const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    std::string message = png.message;
    png_image_free(&png);
    throw InputError({path, 0}, "cannot read PNG image: " + message);
  }
  png.format = PNG_FORMAT_RGB;
  try {  // the declared size against the file's length (at the IHDR chunk's bits per pixel) first
    unsigned char head[26] = {};
    std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(head), sizeof head);
    checkDeclaredImageSize(path, png.width, png.height, 3, sizeof(float), fileLength(path),
                           mostPixelsPerByte(head, sizeof head) * 3);
  } catch (const InputError&) {
    png_image_free(&png);
    throw;
  }
  std::vector<unsigned char> bytes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
    std::string message = png.message;
    png_image_free(&png);
    throw InputError({path, 0}, "cannot read PNG image: " + message);
  }
  Image image(int(png.width), int(png.height));
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = srgbToLinear(bytes[i] / 255.0f);
  return image;
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

unsigned char toSRGB8(float linear) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<unsigned char>(std::lround(encoded * 255.0f));
}

}  // namespace columba
