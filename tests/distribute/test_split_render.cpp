// Renders split into parts (bands of rows) and passes (ranges of sample indices), merged back:
// parts bit for bit the one-piece render, passes to float round-off; every way pieces can fail to
// fit is named.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "distribute/merge.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using namespace columba::testing;

namespace {

// A sphere on a plane under an area light and a dim sky, seen by a camera whose view is only
// partly covered, so that rows cost differently; the path integrator and a Gaussian filter.
const char* kScene = R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective"><float name="fov" value="50"/>
    <transform name="to_world"><lookat origin="0, -3, 1.2" target="0, 0, 0.6" up="0, 0, 1"/></transform>
    <film type="hdrfilm"><integer name="width" value="37"/><integer name="height" value="29"/></film>
    <sampler type="ldsampler"><integer name="sample_count" value="12"/></sampler></sensor>
  <shape type="sphere"><point name="center" x="0" y="0" z="0.5"/><float name="radius" value="0.5"/>
    <bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.6, 0.2, 0.1"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="1.5"/></transform><bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.4"/><rotate x="1" angle="180"/><translate z="2.5"/></transform>
    <emitter type="area"><spectrum name="radiance" value="8"/></emitter></shape>
  <emitter type="constant"><spectrum name="radiance" value="0.05"/></emitter>
</scene>)";

struct Fixture {
  ParsedScene parsed = loadSceneString(kScene, "<split scene>", ".", {}, builtinPlugins());
  Scene scene{parsed, SourceLocation{"<split scene>", 0}};
  int width = scene.sensor().film().width(), height = scene.sensor().film().height();
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

PieceInfo baseInfo(int spp) {
  PieceInfo info;
  info.scene = "<split scene>";
  info.sceneHash = textHash(kScene);
  info.defines = "";
  info.seed = 5;
  info.spp = spp;
  info.frameWidth = fixture().width;
  info.frameHeight = fixture().height;
  return info;
}

Image renderWhole(int spp, int spectralBins = 0) {
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.seed = 5;
  settings.spectralBins = spectralBins;
  RenderStats stats;
  return renderImage(fixture().scene, settings, stats);
}

// The pieces of a render split into `parts` x `passes`, as `columba render --part --pass` makes them.
std::vector<Piece> renderPieces(int parts, int passes, int spp, int spectralBins = 0, int threads = 0) {
  RenderSettings pilot;
  pilot.seed = 5;
  std::vector<int> bounds = balancedRowBands(estimateRowCosts(fixture().scene, pilot), parts);
  std::vector<Piece> pieces;
  for (int k = 1; k <= parts; ++k)
    for (int p = 1; p <= passes; ++p) {
      Piece piece;
      piece.info = baseInfo(spp);
      piece.info.part = PieceIndex{k, parts};
      piece.info.partBounds = bounds;
      if (passes > 1) piece.info.pass = PieceIndex{p, passes};
      std::tie(piece.info.sampleBegin, piece.info.sampleEnd) = passSamples({p, passes}, spp);
      piece.info.window = partWindow(bounds, k, fixture().width);
      piece.path = pieceFileName("img.exr", piece.info.part, piece.info.pass);
      RenderSettings settings;
      settings.samplesPerPixel = spp;
      settings.seed = 5;
      settings.threads = threads;
      settings.spectralBins = spectralBins;
      settings.window = piece.info.window;
      settings.sampleBegin = piece.info.sampleBegin;
      settings.sampleEnd = piece.info.sampleEnd;
      RenderStats stats;
      piece.image = renderImage(fixture().scene, settings, stats);
      EXPECT_TRUE(stats.complete);
      EXPECT_EQ(stats.samples, uint64_t(piece.info.window.width()) * piece.info.window.height() *
                                   uint64_t(piece.info.sampleEnd - piece.info.sampleBegin));
      pieces.push_back(std::move(piece));
    }
  return pieces;
}

std::string mergeError(const std::vector<Piece>& pieces) {
  try {
    mergePieces(pieces);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(merged without an error)";
}

}  // namespace

TEST(SplitRender, PartsMergeBitForBitIntoTheWholeRender) {
  const Image whole = renderWhole(12, 4);
  for (int parts : {1, 2, 3, 4, 7, 29}) {
    SCOPED_TRACE(parts);
    MergedImage merged = mergePieces(renderPieces(parts, 1, 12, 4, parts % 2 ? 1 : 0));
    EXPECT_EQ(merged.parts, parts);
    EXPECT_TRUE(bitIdentical(merged.image.rgb, whole.rgb));
    EXPECT_TRUE(bitIdentical(merged.image.spectral.values, whole.spectral.values));
    EXPECT_EQ(merged.image.spectral.centres, whole.spectral.centres);
    EXPECT_FALSE(merged.info.part);
    EXPECT_EQ(merged.info.spp, 12);
  }
}

TEST(SplitRender, RowCostsAreTheSameForAnyThreadCountAndVaryWithTheScene) {
  RenderSettings one, many;
  one.seed = many.seed = 5;
  one.threads = 1;
  many.threads = 4;
  std::vector<uint64_t> a = estimateRowCosts(fixture().scene, one), b = estimateRowCosts(fixture().scene, many);
  EXPECT_EQ(a, b);
  ASSERT_EQ(a.size(), size_t(fixture().height));
  EXPECT_NE(*std::min_element(a.begin(), a.end()), *std::max_element(a.begin(), a.end()));
}

TEST(SplitRender, PassesMergeToFloatRoundOff) {
  const int spp = 12;
  const Image whole = renderWhole(spp);
  for (int passes : {2, 3, 5, 12}) {
    SCOPED_TRACE(passes);
    std::vector<Piece> pieces = renderPieces(2, passes, spp);
    MergedImage merged = mergePieces(pieces);
    EXPECT_EQ(merged.passes, passes);
    // The bound of merge.h: each pass's mean is rounded to float once, so the merge may differ from
    // the whole render by 2^-23 of the sample-weighted sum of the passes' magnitudes (here 2^-22,
    // with the whole render's own rounding) per value.
    size_t differing = 0;
    for (int y = 0; y < fixture().height; ++y)
      for (int x = 0; x < fixture().width; ++x)
        for (int c = 0; c < 3; ++c) {
          double magnitude = 0.0;
          for (const Piece& p : pieces) {
            const PixelRect& w = p.info.window;
            if (y < w.y0 || y >= w.y1) continue;
            magnitude +=
                double(p.info.sampleEnd - p.info.sampleBegin) / spp * std::abs(p.image.pixel(x - w.x0, y - w.y0)[c]);
          }
          const float m = merged.image.pixel(x, y)[c], f = whole.pixel(x, y)[c];
          EXPECT_LE(std::abs(double(m) - double(f)), std::ldexp(magnitude, -22) + 1e-30)
              << "pixel " << x << ", " << y << " channel " << c;
          differing += m != f;
        }
    std::printf("%d passes: %zu of %d values differ from the one-piece render in their last bits\n", passes, differing,
                fixture().width * fixture().height * 3);
  }
  // One pass holding every sample is the render itself.
  EXPECT_TRUE(bitIdentical(mergePieces(renderPieces(3, 1, spp)).image.rgb, whole.rgb));
}

TEST(SplitRender, AMissingPartIsNamedWithItsRowsAndFile) {
  std::vector<Piece> pieces = renderPieces(4, 1, 2);
  const PixelRect lost = pieces[2].info.window;
  pieces.erase(pieces.begin() + 2);
  std::string message = mergeError(pieces);
  EXPECT_NE(message.find(fmt::format("part 3/4 (rows {}-{}) is missing", lost.y0, lost.y1 - 1)), std::string::npos)
      << message;
  EXPECT_NE(message.find("img.part3of4.exr"), std::string::npos) << message;
}

TEST(SplitRender, OverlappingOrRepeatedPiecesAreNamed) {
  std::vector<Piece> four = renderPieces(4, 1, 2), three = renderPieces(3, 1, 2);
  std::vector<Piece> mixed = {four[0], four[1], three[1], four[3]};
  three[1].path = "other.part2of3.exr";
  mixed[2].path = "other.part2of3.exr";
  std::string message = mergeError(mixed);
  EXPECT_NE(message.find("overlap"), std::string::npos) << message;
  EXPECT_NE(message.find("other.part2of3.exr"), std::string::npos) << message;

  std::vector<Piece> twice = four;
  twice.push_back(four[1]);
  message = mergeError(twice);
  EXPECT_NE(message.find("both hold samples 0:2"), std::string::npos) << message;
  EXPECT_NE(message.find("img.part2of4.exr"), std::string::npos) << message;
}

TEST(SplitRender, AMissingPassIsNamed) {
  std::vector<Piece> pieces = renderPieces(2, 3, 9);
  pieces.erase(pieces.begin() + 4);  // part 2/2, pass 2/3
  std::string message = mergeError(pieces);
  EXPECT_NE(message.find("pass 2/3 of part 2/2 (samples 3:6) is missing"), std::string::npos) << message;
  EXPECT_NE(message.find("img.part2of2.pass2of3.exr"), std::string::npos) << message;
}

TEST(SplitRender, PiecesOfOtherRendersOrUnfinishedOnesAreRejected) {
  std::vector<Piece> pieces = renderPieces(2, 1, 2);
  struct Case {
    const char* expected;
    void (*change)(PieceInfo&);
  };
  const Case cases[] = {
      {"has seed 6", [](PieceInfo& i) { i.seed = 6; }},
      {"has samples per pixel 3", [](PieceInfo& i) { i.spp = 3; }},
      {"has defines angle=3", [](PieceInfo& i) { i.defines = "angle=3"; }},
      {"has scene hash 0123", [](PieceInfo& i) { i.sceneHash = "0123"; }},
      {"has frame size 37x30", [](PieceInfo& i) { i.frameHeight = 30; }},
      {"is unfinished: its render was interrupted", [](PieceInfo& i) { i.complete = false; }},
  };
  for (const Case& c : cases) {
    std::vector<Piece> changed = pieces;
    c.change(changed[1].info);
    std::string message = mergeError(changed);
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    EXPECT_NE(message.find("img.part2of2.exr"), std::string::npos) << message;
  }
  EXPECT_NE(mergeError({}).find("no pieces"), std::string::npos);
}

class SplitRenderFiles : public TempDirTest {};

TEST_F(SplitRenderFiles, PiecesWrittenAndReadBackMergeBitForBit) {
  const Image whole = renderWhole(4, 3);
  std::vector<Piece> pieces = renderPieces(3, 1, 4, 3);
  std::vector<std::string> paths;
  for (Piece& p : pieces) {
    p.path = (dir_ / p.path).string();
    writeEXRWindow(p.path, p.image, p.info.window, p.info.frameWidth, p.info.frameHeight, pieceMetadata(p.info));
    paths.push_back(p.path);
  }
  EXRImageFile header = readEXRFile(paths[1], false);
  EXPECT_EQ(header.dataWindow, pieces[1].info.window);
  EXPECT_EQ(header.frameWidth, 37);
  EXPECT_EQ(header.frameHeight, 29);
  EXPECT_TRUE(header.image.rgb.empty());
  EXPECT_EQ(metadataValue(header.metadata, "Part"), "2/3");
  MergedImage merged = mergePieceFiles(paths);
  EXPECT_TRUE(bitIdentical(merged.image.rgb, whole.rgb));
  EXPECT_TRUE(bitIdentical(merged.image.spectral.values, whole.spectral.values));
  EXPECT_THROW(mergePieceFiles({paths[0], paths[0], paths[1], paths[2]}), std::runtime_error);
  try {
    mergePieceFiles({paths[0], (dir_ / "absent.exr").string()});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("absent.exr"), std::string::npos) << e.what();
  }
}

// A piece's part bounds must run from the frame's first row to its last: bounds reaching past the
// frame had the merge look up rows it never allocated (a heap over-read) and report them missing.
TEST_F(SplitRenderFiles, PartBoundsPastTheFrameAreRejectedAsThePieceIsRead) {
  PieceInfo info;
  info.scene = "s.xml";
  info.spp = 4;
  info.frameWidth = info.frameHeight = 16;
  info.part = PieceIndex{1, 2};
  Image band(16, 8);
  for (const std::vector<int>& bounds : {std::vector<int>{0, 8, 1073741824}, {0, 8, 15}, {1, 8, 16}, {0, 8, 8}}) {
    info.partBounds = bounds;
    const std::string path = (dir_ / "img.part1of2.exr").string();
    writeEXRWindow(path, band, {0, 0, 16, 8}, 16, 16, pieceMetadata(info));
    try {
      loadPiece(path);
      ADD_FAILURE() << "no error for " << ::testing::PrintToString(bounds);
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("img.part1of2.exr"), std::string::npos) << message;
      EXPECT_NE(message.find("'Part bounds' attribute is '" + fmt::format("{}", fmt::join(bounds, ",")) + "'"),
                std::string::npos)
          << message;
      EXPECT_NE(message.find("increasing from 0 to the frame's height 16"), std::string::npos) << message;
    }
  }
}

// The merge allocates the frame a piece's display window declares: a frame larger than the
// memory budget is an error as the piece is read (a 1 x 1 piece of a 20000 x 20000 frame had the
// merge allocate 400 MB before finding the frame uncovered).
TEST_F(SplitRenderFiles, AFrameLargerThanTheMemoryBudgetIsRejectedAsThePieceIsRead) {
  PieceInfo info;
  info.scene = "s.xml";
  info.spp = 4;
  info.frameWidth = info.frameHeight = 20000;
  const std::string path = (dir_ / "img.exr").string();
  writeEXRWindow(path, Image(1, 1), {0, 0, 1, 1}, 20000, 20000, pieceMetadata(info));
  try {
    loadPiece(path);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("img.exr: its frame (the EXR display window) is 20000 x 20000 pixels of 3 channels (4.5 "
                           "GiB), more than the 4.0 GiB an image may take"),
              std::string::npos)
        << message;
  }
}
