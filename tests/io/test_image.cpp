#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <png.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>
#include "core/error.h"
#include "io/image.h"
#include "io/output_directory.h"

// A private copy of the PNG decoder, independent of the writer under test.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image.h>
#pragma GCC diagnostic pop

using namespace columba;
namespace fs = std::filesystem;

namespace {

// A fresh empty directory for one test, removed afterwards.
class ImageFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "columba_image_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
    fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Everything in the test directory, to check that no temporary file is left behind.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }
  fs::path dir_;
};

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

Image testImage() {
  Image image(7, 5);
  const float values[] = {0.0f, 1.0f, 0.1f, -2.5f, 1e-30f, 65504.0f, 3.4e38f, 0.333333343f, 1e-45f};
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = values[i % 9] * float(1 + i / 9);
  return image;
}

}  // namespace

TEST(ImageEncoding, SRGBTransferCurve) {
  EXPECT_EQ(toSRGB8(0.0f), 0);
  EXPECT_EQ(toSRGB8(1.0f), 255);
  EXPECT_EQ(toSRGB8(0.5f), 188);
  EXPECT_EQ(toSRGB8(0.18f), 118);
  EXPECT_EQ(toSRGB8(0.001f), 3);  // linear segment: 12.92 x
  EXPECT_EQ(toSRGB8(-1.0f), 0);
  EXPECT_EQ(toSRGB8(7.0f), 255);
  EXPECT_EQ(toSRGB8(NAN), 0);
  for (int i = 1; i < 1000; ++i) EXPECT_LE(toSRGB8((i - 1) / 999.0f), toSRGB8(i / 999.0f));
}

TEST_F(ImageFiles, EXRRoundTripIsBitExact) {
  Image image = testImage();
  writeEXR(path("a.exr"), image);
  Image back = readEXR(path("a.exr"));
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  ASSERT_EQ(back.rgb.size(), image.rgb.size());
  EXPECT_EQ(std::memcmp(back.rgb.data(), image.rgb.data(), image.rgb.size() * sizeof(float)), 0);
  EXPECT_EQ(entries(), std::vector<std::string>{"a.exr"});
}

TEST_F(ImageFiles, ReadsHalfRGBAWithAnOffsetDataWindow) {
  // 3 x 2 pixels at (10, 20) inside a larger display window.
  Imf::Header header(Imath::Box2i({0, 0}, {99, 99}), Imath::Box2i({10, 20}, {12, 21}));
  std::vector<Imf::Rgba> pixels(6);
  for (int i = 0; i < 6; ++i) pixels[i] = Imf::Rgba(0.25f * i, 2.0f, -0.5f, 0.5f);
  {
    Imf::RgbaOutputFile out(path("half.exr").c_str(), header, Imf::WRITE_RGBA);
    out.setFrameBuffer(pixels.data() - 10 - 20 * 3, 1, 3);
    out.writePixels(2);
  }
  Image image = readEXR(path("half.exr"));
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(image.pixel(i % 3, i / 3)[0], 0.25f * i);
    EXPECT_EQ(image.pixel(i % 3, i / 3)[1], 2.0f);
    EXPECT_EQ(image.pixel(i % 3, i / 3)[2], -0.5f);
  }
}

TEST_F(ImageFiles, ReadsLuminanceOnlyEXRAsGrey) {
  Imf::Header header(2, 1);
  header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
  float y[2] = {0.75f, 3.0f};
  Imf::FrameBuffer frame;
  frame.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y), sizeof(float), 2 * sizeof(float)));
  {
    Imf::OutputFile out(path("grey.exr").c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(1);
  }
  Image image = readEXR(path("grey.exr"));
  EXPECT_EQ(image.rgb, (std::vector<float>{0.75f, 0.75f, 0.75f, 3.0f, 3.0f, 3.0f}));
}

// The channels named `names` of an EXR file's pixels, channel by channel, and the names the file has.
std::pair<std::vector<std::vector<float>>, std::vector<std::string>> exrChannels(const std::string& file,
                                                                                 std::vector<const char*> names) {
  Imf::InputFile in(file.c_str());
  const Imath::Box2i window = in.header().dataWindow();
  const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
  std::vector<std::vector<float>> values(names.size(), std::vector<float>(size_t(width * height)));
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < names.size(); ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values[c].data()), sizeof(float),
                                      size_t(width) * sizeof(float)));
  if (!names.empty()) {
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
  }
  std::vector<std::string> all;
  for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) all.push_back(c.name());
  return {values, all};
}

TEST_F(ImageFiles, LuminanceAndXYZFilesHoldTheColoursYAndXYZ) {
  // Red, green and blue primaries and white: Y is Rec.709's luminance weights (0.2126, 0.7152,
  // 0.0722, ITU-R BT.709), XYZ the primaries' columns (sRGB, IEC 61966-2-1) and D65's white point.
  Image image(4, 1);
  image.rgb = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  image.exrColour = EXRColour::Luminance;
  writeEXR(path("y.exr"), image);
  auto [y, yNames] = exrChannels(path("y.exr"), {"Y"});
  EXPECT_EQ(yNames, std::vector<std::string>{"Y"});
  const float weights[3] = {0.2126f, 0.7152f, 0.0722f};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(y[0][i], weights[i], 1e-4f);
  EXPECT_NEAR(y[0][3], 1.0f, 1e-5f);
  Image grey = readEXR(path("y.exr"));
  EXPECT_EQ(grey.exrColour, EXRColour::Luminance);
  EXPECT_EQ(grey.pixel(1, 0)[0], y[0][1]);
  EXPECT_EQ(grey.pixel(1, 0)[2], y[0][1]);

  image.exrColour = EXRColour::XYZ;
  writeEXR(path("xyz.exr"), image);
  auto [xyz, xyzNames] = exrChannels(path("xyz.exr"), {"X", "Y", "Z"});
  EXPECT_EQ(xyzNames, (std::vector<std::string>{"X", "Y", "Z"}));
  const float red[3] = {0.4124f, 0.2126f, 0.0193f}, d65[3] = {0.95047f, 1.0f, 1.08883f};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(xyz[size_t(c)][0], red[c], 1e-4f);
    EXPECT_NEAR(xyz[size_t(c)][3], d65[c], 1e-4f);
  }
  Image back = readEXR(path("xyz.exr"));  // read back as RGB
  EXPECT_EQ(back.exrColour, EXRColour::XYZ);
  for (size_t i = 0; i < image.rgb.size(); ++i) EXPECT_NEAR(back.rgb[i], image.rgb[i], 1e-5f);

  // The pieces of a split render stay RGB, so that merging them is exact.
  writeEXRWindow(path("piece.exr"), image, {0, 0, 4, 1}, 4, 2);
  EXPECT_EQ(exrChannels(path("piece.exr"), {}).second, (std::vector<std::string>{"B", "G", "R"}));
}

// A compositor reads what the colour channels mean from the chromaticities attribute: Rec. 709 /
// sRGB primaries and D65's white (ITU-R BT.709: red 0.64, 0.33; green 0.30, 0.60; blue 0.15, 0.06;
// white 0.3127, 0.3290) for RGB, luminance and the pieces of a split render; for XYZ the
// primaries that make the channels X, Y and Z.
TEST_F(ImageFiles, EXRsSayWhatTheirColourChannelsMean) {
  auto chromaticities = [](const std::string& file) {
    Imf::InputFile in(file.c_str());
    const auto* attribute = in.header().findTypedAttribute<Imf::ChromaticitiesAttribute>("chromaticities");
    EXPECT_NE(attribute, nullptr) << file;
    return attribute ? attribute->value() : Imf::Chromaticities({0, 0}, {0, 0}, {0, 0}, {0, 0});
  };
  auto expectPoints = [](const Imf::Chromaticities& c, const std::vector<float>& xy, const std::string& file) {
    const float got[8] = {c.red.x, c.red.y, c.green.x, c.green.y, c.blue.x, c.blue.y, c.white.x, c.white.y};
    for (size_t i = 0; i < 8; ++i) EXPECT_NEAR(got[i], xy[i], 1e-4f) << file << " coordinate " << i;
  };
  const std::vector<float> rec709 = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
  Image image(2, 1);
  for (EXRColour colour : {EXRColour::RGB, EXRColour::Luminance}) {
    image.exrColour = colour;
    writeEXR(path("c.exr"), image);
    expectPoints(chromaticities(path("c.exr")), rec709, "c.exr");
  }
  writeEXRWindow(path("piece.exr"), image, {0, 0, 2, 1}, 2, 2);
  expectPoints(chromaticities(path("piece.exr")), rec709, "piece.exr");
  image.exrColour = EXRColour::XYZ;
  writeEXR(path("xyz.exr"), image);
  expectPoints(chromaticities(path("xyz.exr")), {1, 0, 0, 1, 0, 0, 1.0f / 3.0f, 1.0f / 3.0f}, "xyz.exr");
}

TEST_F(ImageFiles, ReadingAMissingOrBrokenEXRNamesThePath) {
  const std::string missing = path("missing.exr");
  try {
    readEXR(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  std::ofstream(path("junk.exr")) << "not an image";
  EXPECT_THROW(readEXR(path("junk.exr")), InputError);
}

TEST_F(ImageFiles, PNGHoldsSRGBBytes) {
  Image image(3, 2);
  const float values[6] = {0.0f, 1.0f, 0.5f, 2.0f, -1.0f, 0.18f};
  for (int p = 0; p < 6; ++p)
    for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = values[(p + c) % 6];
  writePNG(path("a.png"), image);
  EXPECT_EQ(fileBytes(path("a.png")).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path("a.png").c_str(), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  const int expected[6] = {0, 255, 188, 255, 0, 118};
  for (int p = 0; p < 6; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(data[p * 3 + c], expected[(p + c) % 6]) << "pixel " << p << " channel " << c;
  stbi_image_free(data);
  EXPECT_EQ(entries(), std::vector<std::string>{"a.png"});
}

TEST_F(ImageFiles, WritingIntoAMissingDirectoryThrowsAndLeavesNothing) {
  const std::string target = path("no/such/dir/out");
  for (auto write : {writeEXR, writePNG}) {
    try {
      write(target, testImage(), {});
      FAIL() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(target), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageFiles, FailedWritesKeepTheOldFile) {
  for (auto write : {writeEXR, writePNG}) {
    const std::string target = path("keep");
    write(target, testImage(), {});
    const std::string good = fileBytes(target);
    Image broken(4, 4);
    broken.rgb.resize(5);
    EXPECT_THROW(write(target, broken, {}), std::runtime_error);
    EXPECT_EQ(fileBytes(target), good);
    EXPECT_EQ(entries(), std::vector<std::string>{"keep"});
    fs::remove(target);
  }
}

TEST_F(ImageFiles, FailedRenameRemovesTheTemporaryFile) {
  // The temporary file is written completely; the rename onto a non-empty directory fails.
  fs::create_directories(path("occupied/inside"));
  for (auto write : {writeEXR, writePNG}) {
    EXPECT_THROW(write(path("occupied"), testImage(), {}), std::runtime_error);
    EXPECT_EQ(entries(), std::vector<std::string>{"occupied"});
    EXPECT_TRUE(fs::is_directory(path("occupied/inside")));
  }
}

namespace {
// Runs `attempt` in a child process that cannot write to `dir` (its write permission removed;
// for root, whom permissions do not restrict, the child also becomes the unprivileged user
// nobody); true if the child ran it and it returned true.
bool inProcessThatCannotWrite(const fs::path& dir, const std::function<bool()>& attempt) {
  fs::permissions(dir, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  fs::permissions(dir, fs::perms::others_read | fs::perms::others_exec, fs::perm_options::add);
  pid_t child = ::fork();
  if (child == 0) {
    constexpr uid_t kNobody = 65534;
    if (::geteuid() == 0 && (::setgid(kNobody) != 0 || ::setuid(kNobody) != 0)) ::_exit(2);
    ::_exit(attempt() ? 0 : 1);
  }
  int status = 0;
  return child > 0 && ::waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}
}  // namespace

TEST_F(ImageFiles, UnwritableDirectoryKeepsTheOldFile) {
  const std::string target = path("keep.exr");
  writeEXR(target, testImage());
  const std::string good = fileBytes(target);
  EXPECT_TRUE(inProcessThatCannotWrite(dir_, [&] {
    Image other(2, 2);
    auto fails = [](const std::function<void()>& write) {
      try {
        write();
      } catch (const std::runtime_error&) {
        return true;
      }
      return false;
    };
    return fails([&] { writeEXR(target, other); }) && fails([&] { writePNG(target, other); });
  })) << "writing into a directory without write permission did not fail with an error";
  EXPECT_EQ(fileBytes(target), good);
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.exr"});
}

namespace {

std::map<std::string, std::string> exrAttributes(const std::string& path) {
  Imf::InputFile file(path.c_str());
  std::map<std::string, std::string> attributes;
  for (auto it = file.header().begin(); it != file.header().end(); ++it)
    if (auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) attributes[it.name()] = text->value();
  return attributes;
}

std::map<std::string, std::string> pngTexts(const std::string& path) {
  std::map<std::string, std::string> texts;
  FILE* in = std::fopen(path.c_str(), "rb");
  if (!in) return texts;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, in);
    png_read_info(png, info);
    png_textp chunks = nullptr;
    int count = png_get_text(png, info, &chunks, nullptr);
    for (int i = 0; i < count; ++i)
      texts[chunks[i].key] =
          std::string(chunks[i].text, chunks[i].text_length ? chunks[i].text_length : chunks[i].itxt_length);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(in);
  return texts;
}

}  // namespace

TEST_F(ImageFiles, MetadataIsRecordedInBothFormats) {
  const ImageMetadata metadata = {{"Scene", "scenes/n\u00e4cken.xml"}, {"Defines", "a=1\nb=two words"}, {"Seed", "7"}};
  writeEXRAndPNG(path("m.exr"), path("m.png"), testImage(), metadata);
  for (auto texts : {exrAttributes(path("m.exr")), pngTexts(path("m.png"))}) {
    EXPECT_EQ(texts["Software"].rfind("Columba ", 0), 0u) << texts["Software"];
    EXPECT_GT(texts["Software"].size(), std::string("Columba ").size());
    for (const auto& [name, text] : metadata) EXPECT_EQ(texts[name], text) << name;
  }
  writePNG(path("plain.png"), testImage());
  EXPECT_EQ(pngTexts(path("plain.png")).count("Software"), 1u);
}

TEST_F(ImageFiles, PairIsReplacedTogether) {
  Image first = testImage(), second(2, 2);
  writeEXRAndPNG(path("p.exr"), path("p.png"), first);
  EXPECT_EQ(readEXR(path("p.exr")).width, 7);
  EXPECT_EQ(readPNG(path("p.png")).width, 7);
  writeEXRAndPNG(path("p.exr"), path("p.png"), second);
  EXPECT_EQ(readEXR(path("p.exr")).width, 2);
  EXPECT_EQ(readPNG(path("p.png")).width, 2);
  EXPECT_EQ(entries().size(), 2u);
}

TEST_F(ImageFiles, PairStaysOldWhenThePNGCannotBePutInPlace) {
  // The EXR is renamed into place first; the PNG's rename onto a non-empty directory fails, and
  // the old EXR must come back.
  writeEXR(path("q.exr"), testImage());
  const std::string oldEXR = fileBytes(path("q.exr"));
  fs::create_directories(path("q.png/inside"));
  try {
    writeEXRAndPNG(path("q.exr"), path("q.png"), Image(2, 2));
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path("q.png")), std::string::npos) << e.what();
  }
  EXPECT_EQ(fileBytes(path("q.exr")), oldEXR);
  std::vector<std::string> names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"q.exr", "q.png"}));
  // With no old EXR, the new one is removed again.
  fs::remove(path("q.exr"));
  EXPECT_THROW(writeEXRAndPNG(path("q.exr"), path("q.png"), Image(2, 2)), std::runtime_error);
  EXPECT_EQ(entries(), std::vector<std::string>{"q.png"});
}

// With writer threads the pair's files are written side by side, and OpenEXR compresses on
// several threads: the files are the same, and a failure of either still leaves the old pair.
TEST_F(ImageFiles, PairWrittenSideBySideIsTheSameAndFailsTheSame) {
  const ImageMetadata metadata = {{"Seed", "3"}};
  std::map<int, std::pair<std::string, std::string>> bytes;
  for (int threads : {1, 3}) {
    setImageWriterThreads(threads);
    const std::string exr = path("t" + std::to_string(threads) + ".exr");
    const std::string png = path("t" + std::to_string(threads) + ".png");
    writeEXRAndPNG(exr, png, testImage(), metadata);
    bytes[threads] = {fileBytes(exr), fileBytes(png)};
    // The PNG's directory does not exist: its temporary file cannot be made, while the EXR's is.
    const std::string oldEXR = fileBytes(exr);
    try {
      writeEXRAndPNG(exr, path("missing/t.png"), Image(2, 2), metadata);
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("missing/t.png"), std::string::npos) << e.what();
    }
    EXPECT_EQ(fileBytes(exr), oldEXR);
  }
  setImageWriterThreads(1);
  EXPECT_EQ(bytes[1].first, bytes[3].first);
  EXPECT_EQ(bytes[1].second, bytes[3].second);
  std::vector<std::string> names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"t1.exr", "t1.png", "t3.exr", "t3.png"}));
}

TEST_F(ImageFiles, OutputPathsAreCheckedBeforeWork) {
  EXPECT_EQ(checkOutputImagePath(path("a.exr")), ImageFormat::EXR);
  EXPECT_EQ(checkOutputImagePath(path("a.EXR")), ImageFormat::EXR);
  EXPECT_EQ(checkOutputImagePath(path("a.Png")), ImageFormat::PNG);
  fs::create_directories(path("dir.exr"));
  for (const std::string& bad : {path("a.jpg"), path("a"), path("dir.exr"), path("missing/a.exr")}) {
    try {
      checkOutputImagePath(bad);
      ADD_FAILURE() << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  // A directory that can be made is no error when the caller makes it; one under a file is.
  EXPECT_EQ(checkOutputImagePath(path("missing/deeper/a.exr"), true), ImageFormat::EXR);
  EXPECT_FALSE(fs::exists(path("missing")));
  std::ofstream(path("file")) << "";
  for (const std::string& bad : {path("file/a.exr"), path("file/sub/a.png"), path("a.jpg"), path("dir.exr")}) {
    try {
      checkOutputImagePath(bad, true);
      ADD_FAILURE() << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

TEST_F(ImageFiles, OutputDirectoriesAreMadeWithTheirParents) {
  makeOutputDirectory(path("a/b/c/x.exr"), path("a/b/c"));
  EXPECT_TRUE(fs::is_directory(path("a/b/c")));
  makeOutputDirectory(path("a/b/c/x.exr"), path("a/b/c"));  // already there
  std::ofstream(path("a/file")) << "";
  try {
    makeOutputDirectory(path("a/file/d/x.exr"), path("a/file/d"));
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write '" + path("a/file/d/x.exr") + "': '" + path("a/file") + "' is a file, not a directory");
  }
  EXPECT_THROW(checkOutputDirectory(path("a/file"), path("a/file")), std::runtime_error);
  EXPECT_EQ(directoryOf("x.exr"), ".");
  EXPECT_EQ(directoryOf("out/x.exr"), "out");
}

TEST(SpectralImageFiles, BandsRoundTripThroughEXRWithTheirWavelengths) {
  const std::string dir = ::testing::TempDir();
  Image image(3, 2);
  image.spectral.centres = {409.375f, 428.125f, 700.0f};
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = 0.1f * float(i);
  for (size_t i = 0; i < 3 * 2 * 3; ++i) image.spectral.values.push_back(1.0f + float(i));
  const std::string path = dir + "/spectral_bands.exr";
  writeEXR(path, image);
  Image back = readEXR(path);
  EXPECT_EQ(back.rgb, image.rgb);
  EXPECT_EQ(back.spectral.centres, image.spectral.centres);
  EXPECT_EQ(back.spectral.values, image.spectral.values);
  // The channel names of the spectral EXR layout: a comma as the decimal separator.
  EXPECT_EQ(spectralChannelName(409.375f), "S0.409,375nm");
  EXPECT_EQ(spectralChannelName(700.0f), "S0.700nm");
  // A band count that does not match the pixels is refused.
  image.spectral.values.pop_back();
  EXPECT_THROW(writeEXR(dir + "/bad_bands.exr", image), std::runtime_error);
}

TEST(ConeImageFiles, ConeChannelsRoundTripThroughEXRAndShowInFalseColour) {
  const std::string dir = ::testing::TempDir();
  Image image(2, 1);
  image.cones.names = {"VS", "SWS", "MWS", "LWS"};
  // Pixel 0 catches alike in every cone; pixel 1 only in the violet cone.
  image.cones.values = {0.5f, 0.5f, 0.5f, 0.5f, 0.9f, 0.0f, 0.0f, 0.0f};
  const std::string path = dir + "/cones.exr";
  writeEXR(path, image);
  const Image back = readEXR(path);
  EXPECT_EQ(back.cones.names, image.cones.names);
  EXPECT_EQ(back.cones.values, image.cones.values);
  const Image shown = falseColour(back);
  EXPECT_EQ(std::vector<float>(shown.rgb.begin(), shown.rgb.begin() + 3), (std::vector<float>{0.5f, 0.5f, 0.5f}));
  EXPECT_FLOAT_EQ(shown.rgb[3], 0.3f);  // magenta: (2 LWS + VS) / 3, MWS, (2 SWS + VS) / 3
  EXPECT_FLOAT_EQ(shown.rgb[4], 0.0f);
  EXPECT_FLOAT_EQ(shown.rgb[5], 0.3f);
  // The PNG beside the EXR shows the false colour, not the (black) RGB.
  writeEXRAndPNG(dir + "/cones2.exr", dir + "/cones2.png", image);
  const Image png = readPNG(dir + "/cones2.png");
  EXPECT_NEAR(png.rgb[0], 0.5f, 0.01f);
  EXPECT_NEAR(png.rgb[3], 0.3f, 0.01f);
  EXPECT_NEAR(png.rgb[4], 0.0f, 0.01f);
  // A channel count that does not match the pixels is refused.
  image.cones.values.pop_back();
  EXPECT_THROW(writeEXR(dir + "/bad_cones.exr", image), std::runtime_error);
}
