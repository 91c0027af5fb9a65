#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include "core/error.h"
#include "render/image.h"

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
      write(target, testImage());
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
    write(target, testImage());
    const std::string good = fileBytes(target);
    Image broken(4, 4);
    broken.rgb.resize(5);
    EXPECT_THROW(write(target, broken), std::runtime_error);
    EXPECT_EQ(fileBytes(target), good);
    EXPECT_EQ(entries(), std::vector<std::string>{"keep"});
    fs::remove(target);
  }
}

TEST_F(ImageFiles, FailedRenameRemovesTheTemporaryFile) {
  // The temporary file is written completely; the rename onto a non-empty directory fails.
  fs::create_directories(path("occupied/inside"));
  for (auto write : {writeEXR, writePNG}) {
    EXPECT_THROW(write(path("occupied"), testImage()), std::runtime_error);
    EXPECT_EQ(entries(), std::vector<std::string>{"occupied"});
    EXPECT_TRUE(fs::is_directory(path("occupied/inside")));
  }
}

TEST_F(ImageFiles, UnwritableDirectoryKeepsTheOldFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "permissions do not restrict root";
  const std::string target = path("keep.exr");
  writeEXR(target, testImage());
  const std::string good = fileBytes(target);
  fs::permissions(dir_, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  Image other(2, 2);
  EXPECT_THROW(writeEXR(target, other), std::runtime_error);
  EXPECT_THROW(writePNG(target, other), std::runtime_error);
  EXPECT_EQ(fileBytes(target), good);
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.exr"});
}
