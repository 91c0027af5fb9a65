// Replays every input in tests/fuzz-regressions/ through the reader its directory names: each must
// be read or rejected with an InputError, never crash. The files are the fuzzers' findings (fuzz/,
// `make fuzz`), minimised, kept after the fix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <cmath>
#include "core/error.h"
#include "core/transform.h"
#include "emitters/envmap_emitter.h"
#include "fuzz_targets.h"
#include "shapes/triangle_mesh.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRegressions = fs::path(COLUMBA_SOURCE_DIR) / "tests" / "fuzz-regressions";

using Reader = std::function<void(const uint8_t*, size_t)>;

const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> r{
      {"scene", [](const uint8_t* d,
                   size_t n) { columba::fuzz::sceneFromBytes(d, n, std::string(COLUMBA_SOURCE_DIR) + "/examples"); }},
      {"ply_mesh", columba::fuzz::plyMeshFromBytes},
      {"feather_ply", columba::fuzz::featherPlyFromBytes},
      {"obj_mesh", columba::fuzz::objMeshFromBytes},
      {"serialized_mesh", columba::fuzz::serializedMeshFromBytes},
      {"sdf_grid", columba::fuzz::sdfGridFromBytes},
      {"exr_envmap", columba::fuzz::exrEnvmapFromBytes},
      {"hdr_envmap", columba::fuzz::hdrEnvmapFromBytes},
      {"bitmap", columba::fuzz::bitmapFromBytes},
      {"merge_piece", columba::fuzz::mergePieceFromBytes},
      {"manifest", columba::fuzz::manifestFromBytes},
      {"spectra_csv", columba::fuzz::spectraCSVFromBytes},
      {"layer_text", columba::fuzz::layerTextFromBytes},
      {"observer_table", columba::fuzz::observerTableFromBytes},
      {"observer_definition", columba::fuzz::observerDefinitionFromBytes},
      {"medium_grid", columba::fuzz::mediumGridFromBytes},
      {"number_list", columba::fuzz::numberListFromBytes},
  };
  return r;
}

TEST(FuzzRegressions, EveryDirectoryNamesAReader) {
  ASSERT_TRUE(fs::is_directory(kRegressions));
  for (const auto& entry : fs::directory_iterator(kRegressions)) {
    if (entry.is_directory()) {
      EXPECT_TRUE(readers().count(entry.path().filename().string())) << entry.path() << " names no reader";
    }
  }
}

TEST(FuzzRegressions, EveryInputIsReadOrRejectedSlow) {
  size_t replayed = 0;
  for (const auto& [name, read] : readers()) {
    fs::path dir = kRegressions / name;
    if (!fs::is_directory(dir)) continue;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      std::ifstream in(file, std::ios::binary);
      std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      SCOPED_TRACE(file.string());
      try {
        read(bytes.data(), bytes.size());
      } catch (const columba::InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
      }
      ++replayed;
    }
  }
  std::printf("replayed %zu inputs\n", replayed);
}

// Found by the ply_mesh fuzzer: finite coordinates whose triangle area overflows float made
// the area distribution throw std::invalid_argument instead of an error naming the mesh.
TEST(FuzzRegressions, TriangleAreaOverflowingFloatIsAnInputError) {
  columba::MeshData mesh;
  mesh.positions = {columba::Vec3(-2.6e33f, 0, 0), columba::Vec3(1, 0, 0), columba::Vec3(0, 1e33f, 0)};
  mesh.indices = {0, 1, 2};
  try {
    columba::TriangleMesh shape(mesh, columba::Transform(), false, false, {"huge.ply", 0});
    FAIL() << "no error";
  } catch (const columba::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.ply: triangle 0 is too large"), std::string::npos) << e.what();
  }
}

// Found by the scene fuzzer: the harness passes -D names as the command line would; a malformed
// one is the command line's error and must not be mistaken for a crash.
TEST(FuzzRegressions, MalformedDefineNameIsAnError) {
  std::string input = "-D \"area\"rs=1\n<scene version=\"3.0.0\"/>";
  EXPECT_THROW(columba::fuzz::sceneFromBytes(reinterpret_cast<const uint8_t*>(input.data()), input.size(), "."),
               columba::InputError);
}

// Found by the EXR fuzzer: OpenEXR allocates a header attribute at its declared size before
// reading it, so a 40-byte file declaring a 2 GB string took seconds and gigabytes to reject.
TEST(FuzzRegressions, ExrAttributeLargerThanTheFileIsAnErrorBeforeOpenEXRAllocatesIt) {
  std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
  bytes += std::string("comments\0string\0", 16) + std::string("\xf0\xff\xff\x7f", 4) + "abcd";
  try {
    columba::fuzz::exrEnvmapFromBytes(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    FAIL() << "no error";
  } catch (const columba::InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("attribute 'comments' declares 2147483632 bytes but the file has 4 bytes left"),
        std::string::npos)
        << e.what();
  }
}

// Found by the merge_piece fuzzer: OpenEXR reads a channel list to its end (and most types at
// their own size), whatever size the file declares, then goes on from there: a channel list
// declared a byte short had the size check read the rest of the header out of step and miss an
// attribute declaring 1.2 GB, which OpenEXR allocated.
TEST(FuzzRegressions, ExrAttributeDeclaringAnotherSizeThanItsValueIsAnError) {
  std::ifstream in(std::string(COLUMBA_SOURCE_DIR) + "/fuzz/seeds/exr_envmap/rgb_none.exr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key("channels\0chlist\0", 16);
  size_t at = bytes.find(key);
  ASSERT_NE(at, std::string::npos);
  int32_t declared = 0;
  std::memcpy(&declared, &bytes[at + key.size()], 4);
  --declared;
  std::memcpy(&bytes[at + key.size()], &declared, 4);
  try {
    columba::fuzz::exrEnvmapFromBytes(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    FAIL() << "no error";
  } catch (const columba::InputError& e) {
    const std::string expected = "attribute 'channels' of type 'chlist' declares " + std::to_string(declared) +
                                 " bytes, but its value takes " + std::to_string(declared + 1);
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

// Found by the EXR fuzzer: a NaN, infinite or overly bright pixel made the environment map's
// sampling distribution throw std::invalid_argument instead of an error naming the file.
TEST(FuzzRegressions, EnvmapPixelsThatCannotBeSampledAreInputErrors) {
  // Not finite; finite but too bright together (8e37 each); one too bright for its spectrum, twice
  // its largest component (3e38).
  for (float value : {std::nanf(""), INFINITY, 8e37f, 3e38f}) {
    columba::Image image(2, 2);
    for (float& v : image.rgb) v = 0.5f;
    if (std::isfinite(value))
      for (float& v : image.rgb) v = value;
    else
      image.pixel(1, 0)[1] = value;
    try {
      columba::EnvmapEmitter envmap(image, 1.0f, columba::Transform(), {"sky.exr", 0});
      ADD_FAILURE() << "no error for " << value;
    } catch (const columba::InputError& e) {
      const std::string expected =
          !std::isfinite(value) ? "sky.exr: environment map pixel (1, 0) is not finite"
          : value < 1e38f       ? "sky.exr: the environment map's total luminance overflows"
                                : "sky.exr: environment map pixel (0, 0) is too bright: twice its largest component";
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

// Found by the EXR fuzzer: a 391-byte file declaring 2.4 million x 66 pixels had Columba fill
// 1.9 GB before OpenEXR found the pixels missing.
TEST(FuzzRegressions, ExrDeclaringMorePixelsThanTheFileCanHoldIsAnError) {
  std::ifstream in(std::string(COLUMBA_SOURCE_DIR) + "/fuzz/seeds/exr_envmap/rgb_none.exr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key("dataWindow\0box2i\0", 17);
  size_t at = bytes.find(key);
  ASSERT_NE(at, std::string::npos);
  const int32_t window[4] = {0, 0, 2399999, 65};
  std::memcpy(&bytes[at + key.size() + 4], window, sizeof window);
  try {
    columba::fuzz::exrEnvmapFromBytes(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    FAIL() << "no error";
  } catch (const columba::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("declares 2400000 x 66 pixels of 3 channels, more than a file of"),
              std::string::npos)
        << e.what();
  }
}

TEST(FuzzRegressions, SeedsAreValidInputs) {
  // These targets' starting inputs must be read without an error (every image format, a piece
  // that completes the target's own, ...), or the fuzzer starts from nothing.
  for (const char* target : {"sdf_grid", "hdr_envmap", "bitmap", "merge_piece", "manifest", "spectra_csv", "layer_text",
                             "observer_table", "observer_definition", "medium_grid", "number_list"}) {
    int seeds = 0;
    for (const auto& entry : fs::directory_iterator(std::string(COLUMBA_SOURCE_DIR) + "/fuzz/seeds/" + target)) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      try {
        readers().at(target)(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": " << e.what();
      }
      ++seeds;
    }
    EXPECT_GE(seeds, 2) << target;
  }
}

}  // namespace
