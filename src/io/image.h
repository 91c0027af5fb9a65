#pragma once
// Linear RGB float images and their files.
#include <string>
#include <utility>
#include <vector>

namespace columba {

// Per-pixel values in wavelength bins, which an image may carry beside its RGB (spectral renders,
// spectral scatterometer images). EXR files hold them as channels named as the spectral EXR layout
// of Fichet et al. 2021 (JCGT 10(3)) names emitted radiance: "S0.<bin centre>nm", with a comma as
// the decimal separator ("S0.409,375nm").
struct SpectralBands {
  std::vector<float> centres;  // nm, increasing
  std::vector<float> values;   // row-major, centres.size() floats per pixel
  size_t count() const { return centres.size(); }
};
// The EXR channel name of a bin centred at `lambdaNm`.
std::string spectralChannelName(float lambdaNm);

// Per-pixel values of named channels beside RGB: the cone catches a film with an observer records
// (docs/vision.md). EXR files hold them as channels of those names.
struct NamedChannels {
  std::vector<std::string> names;
  std::vector<float> values;  // row-major, names.size() floats per pixel
  size_t count() const { return names.size(); }
};
// The cone channels, in the order an image holds those it has: UVS, VS, SWS, MWS, LWS, DBL.
const std::vector<std::string>& coneChannelNames();

// The colour channels of an image's EXR file, as Mitsuba's hdrfilm `pixel_format` chooses them:
// linear Rec.709 R, G, B; their luminance Y; or CIE 1931 X, Y, Z of those primaries.
enum class EXRColour { RGB, Luminance, XYZ };

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row-major, 3 floats per pixel, linear Rec.709
  SpectralBands spectral;  // empty for RGB images
  NamedChannels cones;     // empty unless a film with an observer rendered it
  // What writeEXR and writeEXRAndPNG write the colour as (the PNG is RGB whatever it is). The
  // pieces of a split render (writeEXRWindow) are RGB, so that merging them is exact.
  EXRColour exrColour = EXRColour::RGB;
  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(size_t(w) * size_t(h) * 3, 0.0f) {}
  float* pixel(int x, int y) { return &rgb[(size_t(y) * width + x) * 3]; }
  const float* pixel(int x, int y) const { return &rgb[(size_t(y) * width + x) * 3]; }
};

// How a PNG shows an image with cone channels, for human eyes: red (2 LWS + S) / 3, green MWS,
// blue (2 SWS + S) / 3, where S is the UVS or VS cone, so that what only the shortest cone catches
// is magenta and a white that every cone catches alike is white. Missing cones count 0.
Image falseColour(const Image& image);

// Text recorded in an image file: EXR string attributes, PNG text chunks (name, text). Every
// file written also records "Software" (Columba and its version).
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;
// The text recorded under `name`, or "" if there is none.
std::string metadataValue(const ImageMetadata& metadata, const std::string& name);

// A rectangle of pixels, [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool operator==(const PixelRect& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
};

// An EXR file as its header describes it: its pixels lie in `dataWindow` of a frame of
// frameWidth x frameHeight pixels (its display window, from the origin), and its string
// attributes are `metadata`. A whole image's data window is the whole frame.
struct EXRImageFile {
  Image image;  // the data window's pixels (empty when only the header was read)
  ImageMetadata metadata;
  PixelRect dataWindow;
  int frameWidth = 0, frameHeight = 0;
};

// Threads the writers below may use (1 until set; 0 sets one per core): OpenEXR compresses an
// EXR's blocks of lines on them, and writeEXRAndPNG writes its two files side by side.
void setImageWriterThreads(int threads);

// Writers go through a temporary file renamed into place, so a failed or interrupted write
// never replaces a good file. They throw std::runtime_error naming the path on failure.
void writeEXR(const std::string& path, const Image& image, const ImageMetadata& metadata = {});  // float32 RGB
// 8-bit sRGB, clamped; an image with cone channels as their false colour (falseColour), here and in
// writeEXRAndPNG's PNG.
void writePNG(const std::string& path, const Image& image, const ImageMetadata& metadata = {});
// An EXR and its PNG preview, replaced together or not at all: both are written to temporary
// files, then renamed into place; if a rename fails, the file already replaced is put back.
// Writers of the same pair in other processes wait for each other's renames (a lock on the
// directory), so the pair never mixes two writers' images.
// How a PNG maps linear values (after the exposure) to its range:
//   Clamp:    each channel clamped to [0, 1] (what the EXR holds, cut at white);
//   Reinhard: the global operator of Reinhard, Stark, Shirley & Ferwerda (2002, "Photographic tone
//             reproduction for digital images", SIGGRAPH), L / (1 + L) on the luminance L, each
//             pixel's RGB scaled alike, so highlights roll off instead of clipping and hue is kept.
enum class ToneMap { Clamp, Reinhard };
// "clamp" or "reinhard"; throws std::invalid_argument naming the known ones.
ToneMap toneMapNamed(const std::string& name);

// `pngExposure` (stops) brightens or darkens the PNG only, and `toneMap` maps it to the PNG's range:
// the EXR keeps the linear values.
void writeEXRAndPNG(const std::string& exrPath, const std::string& pngPath, const Image& image,
                    const ImageMetadata& metadata = {}, float pngExposure = 0.0f, ToneMap toneMap = ToneMap::Clamp);

enum class ImageFormat { EXR, PNG };
// The format a path's extension names (".exr" or ".png", in any letter case). Throws
// std::runtime_error naming the path for any other extension, for a path that is a directory
// and for one whose directory does not exist (or, with `directoryMayBeMade`, cannot be made, as
// checkOutputDirectory checks): checked before work whose result it will hold.
ImageFormat checkOutputImagePath(const std::string& path, bool directoryMayBeMade = false);

// A piece of a larger frame (a part of a split render): `image` holds the pixels of `window`,
// which lies in a frame of frameWidth x frameHeight pixels. Float32 RGB and spectral bands, the
// EXR's data window being `window` and its display window the frame.
void writeEXRWindow(const std::string& path, const Image& image, const PixelRect& window, int frameWidth,
                    int frameHeight, const ImageMetadata& metadata = {});

// RGB (from R, G, B, X, Y, Z, or Y alone as grey, `exrColour` saying which), any spectral
// bands and any cone channels; throws InputError naming the path if it cannot be read.
Image readEXR(const std::string& path);
// The same with the header's windows and string attributes; with `pixels` false, only the header
// is read (the image stays empty).
EXRImageFile readEXRFile(const std::string& path, bool pixels = true);
// An 8-bit PNG (grey, RGB, with or without alpha) as linear values; throws InputError naming
// the path if it cannot be read.
Image readPNG(const std::string& path);
// The 8-bit sRGB encoding of a linear value, and the linear value of an sRGB-encoded one.
unsigned char toSRGB8(float linear);
float srgbToLinear(float encoded);

}  // namespace columba
