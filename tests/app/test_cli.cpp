#include <gtest/gtest.h>

#include "support/temp_dir_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/image.h"
#include "support/cli_test_support.h"
#include "vision/observer.h"

namespace fs = std::filesystem;
using columba::testing::CommandResult;
using columba::testing::renderAndSignal;
using columba::testing::run;
using columba::testing::runShell;

namespace {

class CliTest : public columba::testing::TempDirTest {};

const char* kTinyScene = R"(<scene version="3.0.0">
  <default name="res" value="8"/>
  <default name="radiance" value="0.5"/>
  <sensor type="perspective">
    <film type="hdrfilm"><integer name="width" value="$res"/><integer name="height" value="$res"/></film>
    <sampler type="independent"><integer name="sample_count" value="2"/></sampler>
  </sensor>
  <emitter type="constant"><spectrum name="radiance" value="$radiance"/></emitter>
</scene>
)";
}  // namespace

TEST_F(CliTest, RenderWritesExrAndPngBesideIt) {
  std::string scene = write("tiny.xml", kTinyScene);
  CommandResult r = run("render " + scene + " -o " + (dir_ / "img.exr").string() + " -D res=6 -D unused=3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("samples/s"), std::string::npos) << r.output;
  columba::Image img = columba::readEXR((dir_ / "img.exr").string());
  EXPECT_EQ(img.width, 6);
  EXPECT_NEAR(img.pixel(3, 3)[1], 0.5f, 0.1f);
  EXPECT_TRUE(fs::exists(dir_ / "img.png"));
}

TEST_F(CliTest, ExposureBrightensThePngAndLeavesTheExrLinear) {
  std::string scene = write("tiny.xml", kTinyScene);
  ASSERT_EQ(run("render " + scene + " -o " + (dir_ / "plain.exr").string()).status, 0);
  CommandResult r = run("render " + scene + " --exposure 1 -o " + (dir_ / "bright.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(columba::readEXR((dir_ / "plain.exr").string()).rgb, columba::readEXR((dir_ / "bright.exr").string()).rgb);
  // One stop up doubles the PNG's linear values (to its white at most); the EXR's stay.
  const columba::Image exr = columba::readEXR((dir_ / "plain.exr").string());
  const columba::Image plain = columba::readPNG((dir_ / "plain.png").string());
  const columba::Image bright = columba::readPNG((dir_ / "bright.png").string());
  for (int c = 0; c < 3; ++c) {
    const float linear = exr.pixel(4, 4)[c];
    EXPECT_NEAR(plain.pixel(4, 4)[c], linear, 0.01f) << c;
    EXPECT_NEAR(bright.pixel(4, 4)[c], std::min(1.0f, 2.0f * linear), 0.01f) << c;
  }
  EXPECT_NE(run("render " + scene + " --exposure 30 -o " + (dir_ / "x.exr").string()).status, 0);
}

TEST_F(CliTest, ReinhardToneMappingRollsHighlightsOffInThePngOnly) {
  // Two stops up, the grey sky (about 0.5) is about 2: clamped to white by default, 2 / (1 + 2) with
  // --tonemap reinhard; the EXR is the same linear image either way.
  std::string scene = write("tiny.xml", kTinyScene);
  ASSERT_EQ(run("render " + scene + " --exposure 2 -o " + (dir_ / "clamped.exr").string()).status, 0);
  CommandResult r = run("render " + scene + " --exposure 2 --tonemap reinhard -o " + (dir_ / "rolled.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const columba::Image exr = columba::readEXR((dir_ / "rolled.exr").string());
  EXPECT_EQ(exr.rgb, columba::readEXR((dir_ / "clamped.exr").string()).rgb);
  const columba::Image clamped = columba::readPNG((dir_ / "clamped.png").string());
  const columba::Image rolled = columba::readPNG((dir_ / "rolled.png").string());
  const float* c = exr.pixel(4, 4);
  const float luminance = 4.0f * (0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(clamped.pixel(4, 4)[k], std::min(1.0f, 4.0f * c[k]), 0.01f) << k;
    EXPECT_NEAR(rolled.pixel(4, 4)[k], 4.0f * c[k] / (1.0f + luminance), 0.01f) << k;
  }
  EXPECT_NE(run("render " + scene + " --tonemap aces -o " + (dir_ / "x.exr").string()).status, 0);
}

TEST_F(CliTest, MalformedScenesFailWithFileLineAndValueSlow) {
  struct Case {
    const char* name;
    std::string xml;
    std::vector<std::string> expected;  // fragments of the message
  };
  std::vector<Case> cases = {
      {"unknown_plugin.xml", "<scene version=\"3.0.0\">\n  <bsdf type=\"velvet\"/>\n</scene>\n", {":2", "velvet"}},
      {"bad_number.xml",
       "<scene version=\"3.0.0\">\n<sensor type=\"perspective\">\n  <float name=\"fov\" "
       "value=\"4o\"/>\n</sensor>\n</scene>\n",
       {":3", "4o"}},
      {"missing_file.xml",
       "<scene version=\"3.0.0\">\n<shape type=\"obj\">\n<string name=\"filename\" "
       "value=\"nowhere.obj\"/>\n</shape>\n</scene>\n",
       {":3", "nowhere.obj"}},
      {"missing_default.xml",
       "<scene version=\"3.0.0\">\n<sensor type=\"perspective\">\n<float name=\"fov\" "
       "value=\"$angle\"/>\n</sensor>\n</scene>\n",
       {":3", "angle"}},
      {"unknown_parameter.xml",
       "<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n<float name=\"radiancee\" "
       "value=\"1\"/>\n</emitter>\n</scene>\n",
       {":3", "radiancee"}},
      {"malformed.xml", "<scene version=\"3.0.0\">\n<shape type=\"sphere\">\n</scene>\n", {"malformed.xml"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::string scene = write(c.name, c.xml);
    CommandResult r = run("render " + scene + " -o " + (dir_ / "out.exr").string());
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(c.name), std::string::npos) << r.output;
    for (const std::string& fragment : c.expected) EXPECT_NE(r.output.find(fragment), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
  }
}

TEST_F(CliTest, AFailedRenderLeavesTheOldImageAlone) {
  std::string good = write("tiny.xml", kTinyScene);
  std::string out = (dir_ / "keep.exr").string();
  ASSERT_EQ(run("render " + good + " -o " + out).status, 0);
  auto before = fs::file_size(out);
  std::string bad = write("bad.xml",
                          "<scene version=\"3.0.0\">\n<integrator type=\"path\"><integer name=\"max_depth\" "
                          "value=\"x\"/></integrator></scene>");
  EXPECT_NE(run("render " + bad + " -o " + out).status, 0);
  EXPECT_EQ(fs::file_size(out), before);
  EXPECT_EQ(columba::readEXR(out).width, 8);
}

TEST_F(CliTest, BadCommandLineValuesAreRejected) {
  std::string scene = write("tiny.xml", kTinyScene);
  EXPECT_NE(run("render " + scene + " --spp 0").status, 0);
  EXPECT_NE(run("render " + scene + " -D novalue").status, 0);
  EXPECT_NE(run("render " + (dir_ / "absent.xml").string()).status, 0);
}

TEST_F(CliTest, AdaptiveSamplingReportsItsPlanAndRefusesPieces) {
  std::string scene = write("tiny.xml", kTinyScene), out = (dir_ / "img.exr").string();
  CommandResult r = run("render " + scene + " -o " + out + " --spp 8 --adaptive");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Adaptive sampling: 2 pilot samples per pixel"), std::string::npos) << r.output;
  EXPECT_NEAR(columba::readEXR(out).pixel(3, 3)[1], 0.5f, 0.1f);
  r = run("render " + scene + " -o " + out + " --spp 8 --target-error 1.5");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--target-error 1.5: give the relative RMSE to reach"), std::string::npos) << r.output;
  r = run("render " + scene + " -o " + out + " --spp 8 --adaptive --pass 1/2");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("cannot be combined with --part or --pass"), std::string::npos) << r.output;
}

double answeredSeconds(const CommandResult& r) {
  size_t at = r.output.find("answered=");
  return at == std::string::npos ? 1e9 : std::stod(r.output.substr(at + 9));
}

TEST_F(CliTest, InterruptWritesThePartialImageBesideTheOutput) {
  std::string scene = write("tiny.xml", kTinyScene);
  std::string out = (dir_ / "partial.exr").string();
  // A render far too long to finish; SIGINT after half a second.
  CommandResult r = renderAndSignal(scene + " -D res=64 --spp 1000000 -o " + out, "INT", 0.5);
  EXPECT_NE(r.output.find("status=130"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((dir_ / "partial.partial.exr").string()), std::string::npos) << r.output;
  EXPECT_EQ(columba::readEXR((dir_ / "partial.partial.exr").string()).width, 64);
  EXPECT_EQ(columba::readPNG((dir_ / "partial.partial.png").string()).width, 64);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliTest, SigtermAlsoWritesThePartialImage) {
  std::string scene = write("tiny.xml", kTinyScene);
  CommandResult r = renderAndSignal(scene + " --spp 16777216 -o " + (dir_ / "t.exr").string(), "TERM", 0.5);
  EXPECT_NE(r.output.find("status=143"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "t.partial.exr")) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "t.partial.png")) << r.output;
}

TEST_F(CliTest, CtrlCIsAnsweredWithinASecondAtAnySampleCount) {
  // Each pixel of this scene takes seconds at 2^24 samples.
  std::string scene = write("slow.xml", R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="8"/></integrator>
  <sensor type="perspective">
    <film type="hdrfilm"><integer name="width" value="2"/><integer name="height" value="2"/></film>
  </sensor>
  <shape type="sphere"><float name="radius" value="100"/><bsdf type="diffuse"/></shape>
  <emitter type="constant"><spectrum name="radiance" value="0.5"/></emitter>
</scene>
)");
  CommandResult r = renderAndSignal(scene + " --spp 16777216 -o " + (dir_ / "slow.exr").string(), "INT", 0.5);
  EXPECT_NE(r.output.find("status=130"), std::string::npos) << r.output;
  EXPECT_LT(answeredSeconds(r), 1.0) << r.output;
}

TEST_F(CliTest, ASignalWhileTheSceneLoadsEndsTheRenderAtOnce) {
  // Nested includes make the load long: 30 x 100 x 100 empty scenes read one after another (more
  // than a minute on two cores), with nothing rendered yet to save.
  auto includes = [](const std::string& file, int count) {
    std::string xml = "<scene version=\"3.0.0\">\n";
    for (int i = 0; i < count; ++i) xml += "<include filename=\"" + file + "\"/>\n";
    return xml + "</scene>\n";
  };
  write("empty.xml", "<scene version=\"3.0.0\"/>\n");
  write("hundred.xml", includes("empty.xml", 100));
  write("ten_thousand.xml", includes("hundred.xml", 100));
  std::string scene = write("slow_load.xml", includes("ten_thousand.xml", 30));
  // A sweep names its frame before loading it, after the handlers are in place.
  CommandResult r =
      renderAndSignal(scene + " --sweep x=1,2 -o " + (dir_ / "slow.exr").string(), "TERM", 0.3, "^Frame 0 ");
  EXPECT_NE(r.output.find("status=143"), std::string::npos) << r.output;
  EXPECT_LT(answeredSeconds(r), 1.0) << r.output;
  EXPECT_EQ(r.output.find("Stopping"), std::string::npos) << r.output;
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().string().find(".partial."), std::string::npos) << entry.path();
}

TEST_F(CliTest, AnInterruptedFeatherGenerationLeavesNoFile) {
  // Some minutes of writing; SIGINT after half a second (before the handlers, it kills the
  // process before its file is begun).
  const std::string out = (dir_ / "many.ply").string();
  CommandResult r = runShell(std::string(COLUMBA_BINARY) + " feather --single --barbs 16000000 -o " + out +
                             " & pid=$!; sleep 0.5; kill -INT $pid; wait $pid; echo status=$?");
  EXPECT_NE(r.output.find("status=130"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir_)) << r.output;
  r = run("feather --single --barbs 2000000000 -o " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("at most 16777215 barbs per side"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir_)) << r.output;
}

TEST_F(CliTest, TheBirdsBarbulesTakeFurtherParametersCheckedAsTheSceneWould) {
  const fs::path bird = dir_ / "bird";
  CommandResult r =
      run("feather --bird --feather-scale 3 --barbule profile_exponent=4 --barbule layers=parotia-occipital -o " +
          bird.string());
  ASSERT_EQ(r.status, 0) << r.output;
  std::stringstream xml;
  xml << std::ifstream(bird / "rock_dove.xml").rdbuf();
  EXPECT_NE(xml.str().find("<bsdf type=\"barbulebsdf\" id=\"dove-barbules\"><integer name=\"profile_exponent\" "
                           "value=\"4\"/><string name=\"layers\" value=\"parotia-occipital\"/></bsdf>"),
            std::string::npos)
      << xml.str().substr(0, 600);
  // Mistakes are refused before anything is written, naming the option.
  const fs::path refused = dir_ / "refused";
  for (const auto& [option, message] : std::vector<std::pair<std::string, std::string>>{
           {"profile_exponent=40", "--barbule profile_exponent: the cross-section's superellipse exponent"},
           {"colour=3", "--barbule: unknown parameter 'colour'"},
           {"height=0.5", "--barbule: each neck feather's cortex thickness comes from --height"},
           {"mu=0.1", "--barbule: 'mu' would have no effect"},
           {"preset=dove-green", "--barbule: 'preset' would have no effect"},
           {"layers=keratin", "--barbule layers:"},
           {"layers_1=keratin:0.1", "--barbule layers_1 would have no effect: no feather chooses"},
           {"trt_offsets=100", "--barbule trt_offsets: the TRT lobe's offset nodes must number 1 to 64"},
           {"layers_1=keratin:0.1 --purple-stack 2", "--purple-stack: the purple feathers choose layer stack 2"},
           {"b", "--barbule: give NAME=VALUE, not 'b'"},
           // Options of the other kinds of feather, which the bird would not use.
           {"b=0.1 --barbs 20", "--bird excludes --barbs"},
           {"b=0.1 --binary", "--bird excludes --binary"}}) {
    CommandResult bad = run("feather --bird --barbule " + option + " -o " + refused.string());
    EXPECT_NE(bad.status, 0) << option;
    EXPECT_NE(bad.output.find(message), std::string::npos) << option << ": " << bad.output;
    EXPECT_FALSE(fs::exists(refused)) << option;
  }
  // The BSDF's quadrature of the TRT lobe is one of its parameters too.
  const fs::path quadrature = dir_ / "quadrature";
  r = run("feather --bird --feather-scale 3 --barbule trt_offsets=16 --barbule trt_angles=4 -o " + quadrature.string());
  ASSERT_EQ(r.status, 0) << r.output;
  std::stringstream written;
  written << std::ifstream(quadrature / "rock_dove.xml").rdbuf();
  EXPECT_NE(
      written.str().find("<integer name=\"trt_offsets\" value=\"16\"/><integer name=\"trt_angles\" value=\"4\"/>"),
      std::string::npos)
      << written.str().substr(0, 600);
}

TEST_F(CliTest, AnInterruptedRenderNeverReplacesAFinishedImage) {
  std::string scene = write("tiny.xml", kTinyScene);
  std::string out = (dir_ / "keep.exr").string();
  ASSERT_EQ(run("render " + scene + " -o " + out).status, 0);
  const auto exrBefore = fs::file_size(out), pngBefore = fs::file_size(dir_ / "keep.png");
  CommandResult r = renderAndSignal(scene + " -D res=64 --spp 1000000 -o " + out, "INT", 0.5);
  EXPECT_NE(r.output.find("status=130"), std::string::npos) << r.output;
  EXPECT_EQ(columba::readEXR(out).width, 8);
  EXPECT_EQ(fs::file_size(out), exrBefore);
  EXPECT_EQ(fs::file_size(dir_ / "keep.png"), pngBefore);
  EXPECT_EQ(columba::readEXR((dir_ / "keep.partial.exr").string()).width, 64);
}

TEST_F(CliTest, TheExtensionChoosesTheOutputFormatSlow) {
  std::string scene = write("tiny.xml", kTinyScene);
  // A PNG name: the PNG, with the linear EXR beside it.
  CommandResult r = run("render " + scene + " -o " + (dir_ / "a.png").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(columba::readPNG((dir_ / "a.png").string()).width, 8);
  EXPECT_EQ(columba::readEXR((dir_ / "a.exr").string()).width, 8);
  EXPECT_FALSE(fs::exists(dir_ / "a.png.exr"));
  // Any letter case.
  ASSERT_EQ(run("render " + scene + " -o " + (dir_ / "b.EXR").string()).status, 0);
  EXPECT_EQ(columba::readEXR((dir_ / "b.EXR").string()).width, 8);
  EXPECT_TRUE(fs::exists(dir_ / "b.png"));
  EXPECT_FALSE(fs::exists(dir_ / "b.EXR.exr"));
  // Unknown extensions, no extension and directories fail before rendering.
  fs::create_directories(dir_ / "folder");
  fs::create_directories(dir_ / "folder.exr");
  for (std::string bad : {"c.jpg", "c", "folder", "folder.exr"}) {
    SCOPED_TRACE(bad);
    CommandResult failed = run("render " + scene + " -o " + (dir_ / bad).string());
    EXPECT_NE(failed.status, 0);
    EXPECT_NE(failed.output.find("cannot write '" + (dir_ / bad).string() + "'"), std::string::npos) << failed.output;
    EXPECT_EQ(failed.output.find("Rendering"), std::string::npos) << failed.output;
  }
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"a.exr", "a.png", "b.EXR", "b.png", "folder", "folder.exr", "tiny.xml"}));
}

TEST_F(CliTest, MontageWritesTheFormatItsNameAsksForSlow) {
  std::string scene = write("tiny.xml", kTinyScene);
  ASSERT_EQ(run("render " + scene + " -o " + (dir_ / "a.exr").string()).status, 0);
  CommandResult bad = run("montage -o " + (dir_ / "sheet.jpg").string() + " " + (dir_ / "a.exr").string());
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.output.find("'.jpg'"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir_ / "sheet.jpg"));
  CommandResult exr = run("montage -o " + (dir_ / "sheet.EXR").string() + " " + (dir_ / "a.png").string());
  ASSERT_EQ(exr.status, 0) << exr.output;
  EXPECT_GT(columba::readEXR((dir_ / "sheet.EXR").string()).width, 0);
  // Vector sheets for papers: the images embedded, the labels text.
  for (const char* name : {"sheet.pdf", "sheet.Svg"}) {
    CommandResult vector = run("montage -o " + (dir_ / "figures" / name).string() + " " + (dir_ / "a.png").string());
    ASSERT_EQ(vector.status, 0) << vector.output;
    std::ifstream in(dir_ / "figures" / name, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find(std::string(name) == "sheet.pdf" ? "%PDF-" : "<svg"), std::string::npos) << name;
  }
}

TEST_F(CliTest, CommandLineMistakesGetShortNamedMessagesSlow) {
  std::string scene = write("tiny.xml", kTinyScene);
  struct Case {
    std::string args, expected;
  };
  std::vector<Case> cases = {
      {"render " + scene + " --spp 0", "--spp must be between 1 and 16777216"},
      {"render " + scene + " --spp 16777217", "--spp must be between 1 and 16777216"},
      {"render " + scene + " --spp 2147483647", "--spp must be between 1 and 16777216"},
      {"render " + scene + " --threads 0", "--threads must be between 1 and"},
      {"rendr", "unknown command 'rendr' \u2014 did you mean 'render'?"},
      {"render --sp 4", "unknown option '--sp' for 'render' \u2014 did you mean '--spp'?"},
      {"--versoin", "unknown option '--versoin' for 'columba' \u2014 did you mean '--version'?"},
      {"bsdf --mu nan -o " + dir_.string(), "--mu: must be a finite number, not 'nan'"},
      {"bsdf --H nan -o " + dir_.string(), "--H: must be a finite number, not 'nan'"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    CommandResult r = run(c.args);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
    EXPECT_LT(r.output.size(), 300u) << r.output;
  }
  CommandResult version = run("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.output.rfind("columba ", 0), 0u) << version.output;
}

TEST_F(CliTest, UnusedDefinesAreNamedInAWarning) {
  std::string scene = write("tiny.xml", kTinyScene);
  CommandResult r = run("render -D sp=4 " + scene + " -D res=4 -o " + (dir_ / "w.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: -D sp=4"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("-D res"), std::string::npos) << r.output;
  EXPECT_EQ(columba::readEXR((dir_ / "w.exr").string()).width, 4);
}

TEST_F(CliTest, ImagesRecordHowTheyWereRendered) {
  std::string scene = write("tiny.xml", kTinyScene);
  ASSERT_EQ(run("render " + scene + " -D res=4 --spp 3 --seed 9 -o " + (dir_ / "m.exr").string()).status, 0);
  for (std::string file : {"m.exr", "m.png"}) {
    SCOPED_TRACE(file);
    // The metadata is stored as plain text in both formats.
    std::ifstream in(dir_ / file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    for (const std::string& text : {std::string("Columba "), scene, std::string("res=4"),
                                    std::string("Samples per pixel"), std::string("Seed"), std::string("Render time")})
      EXPECT_NE(bytes.find(text), std::string::npos) << text;
  }
}

TEST_F(CliTest, AFilmTooLargeForMemorySaysHowMuchItNeeds) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of shadow memory, which the address-space limit this test "
                  "sets forbids";
#endif
  std::string scene = write("huge.xml", R"(<scene version="3.0.0">
  <sensor type="perspective"><film type="hdrfilm"><integer name="width" value="46341"/>
    <integer name="height" value="46341"/></film></sensor>
</scene>
)");
  CommandResult r = runShell("ulimit -v 4000000; " + std::string(COLUMBA_BINARY) + " render " + scene + " -o " +
                             (dir_ / "huge.exr").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("46341 x 46341 pixels needs 24.0 GiB"), std::string::npos) << r.output;
}

TEST_F(CliTest, DefaultSceneIsAGeneratedRockDoveSlow) {
  std::string out = (dir_ / "default.exr").string();
  CommandResult r = run("render -D width=40 -D height=30 -D spp=2 -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("default scene"), std::string::npos) << r.output;
  columba::Image img = columba::readEXR(out);
  EXPECT_EQ(img.width, 40);
  // Thousands of feathers, copies of templates of thousands of barb segments, were generated and loaded.
  size_t at = r.output.find(" primitives");
  ASSERT_NE(at, std::string::npos) << r.output;
  size_t start = r.output.rfind(' ', at - 1) + 1;
  EXPECT_GT(std::stol(r.output.substr(start, at - start)), 100000) << r.output;
}

TEST_F(CliTest, BSDFGoniometerWritesPlotsWithTheirDataSlow) {
  CommandResult r =
      run("bsdf --preset dove-green --mode specular,plane,hemisphere --angles 0,30 --res 32 --spectral "
          "--bins 4 -o " +
          dir_.string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* file : {"bsdf_specular.png", "bsdf_specular.csv", "bsdf_plane_theta0.png", "bsdf_plane_theta30.png",
                           "bsdf_plane.csv", "bsdf_hemisphere_theta0.exr", "bsdf_hemisphere_theta30.png", "bsdf.json"})
    EXPECT_TRUE(fs::exists(dir_ / file)) << file;
  // The CSV starts with its units, the parameters and what keratin's index is below 400 nm, then
  // the columns.
  std::ifstream csv(dir_ / "bsdf_specular.csv");
  std::string units, parameters, extrapolation, columns;
  std::getline(csv, units);
  std::getline(csv, parameters);
  std::getline(csv, extrapolation);
  std::getline(csv, columns);
  EXPECT_NE(units.find("dimensionless"), std::string::npos) << units;
  EXPECT_NE(parameters.find("height 0.58 um"), std::string::npos) << parameters;
  EXPECT_NE(extrapolation.find("below 400 nm keratin's index extrapolates"), std::string::npos) << extrapolation;
  EXPECT_EQ(columns, "wavelength_nm,R_theta0,TRT_theta0,total_theta0,R_theta30,TRT_theta30,total_theta30");
  // The run's record: the version, every parameter and the peaks.
  std::stringstream json;
  json << std::ifstream(dir_ / "bsdf.json").rdbuf();
  for (const char* key : {"\"columba_version\"", "\"height_um\": 0.58", "\"preset\": \"dove-green\"", "\"R_peaks_nm\"",
                          "\"profile_exponent\": 2.0"})
    EXPECT_NE(json.str().find(key), std::string::npos) << key;
  // The spectral hemisphere: RGB plus four bins over the model's whole range, 300-830 nm, or over
  // --spectral-range; the EXR says which.
  columba::Image hemisphere = columba::readEXR((dir_ / "bsdf_hemisphere_theta30.exr").string());
  EXPECT_EQ(hemisphere.spectral.centres, (std::vector<float>{366.25f, 498.75f, 631.25f, 763.75f}));
  ASSERT_EQ(run("bsdf --preset dove-green --mode hemisphere --angles 30 --res 16 --spectral --bins 4 "
                "--spectral-range 400:700 -o " +
                (dir_ / "visible").string())
                .status,
            0);
  const columba::EXRImageFile visible =
      columba::readEXRFile((dir_ / "visible" / "bsdf_hemisphere_theta30.exr").string());
  EXPECT_EQ(visible.image.spectral.centres, (std::vector<float>{437.5f, 512.5f, 587.5f, 662.5f}));
  EXPECT_EQ(columba::metadataValue(visible.metadata, "Spectral channels"),
            "4 bins of 75 nm over 400-700 nm (S0.<centre>nm)");
  for (const char* range : {"200:700", "700:400", "400"}) {
    CommandResult wrong = run(std::string("bsdf --mode hemisphere --spectral --spectral-range ") + range + " -o " +
                              (dir_ / "wrong").string());
    EXPECT_NE(wrong.status, 0) << range;
    EXPECT_NE(
        wrong.output.find("--spectral-range '" + std::string(range) + "': give LO:HI in nm, 300 <= LO < HI <= 830"),
        std::string::npos)
        << wrong.output;
    EXPECT_FALSE(fs::exists(dir_ / "wrong")) << range;
  }
  // Parameter mistakes get short messages naming the option.
  CommandResult bad = run("bsdf --H 0 --mode specular -o " + dir_.string());
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.output.find("--H: the barbule spacing must be positive"), std::string::npos) << bad.output;
  CommandResult preset = run("bsdf --preset dove-blue -o " + dir_.string());
  EXPECT_NE(preset.output.find("dove-green, dove-purple"), std::string::npos) << preset.output;
  CommandResult exponent = run("bsdf --profile-exponent 20 --mode specular -o " + dir_.string());
  EXPECT_NE(exponent.status, 0);
  EXPECT_NE(exponent.output.find("--profile-exponent: the cross-section's superellipse exponent must lie in [2, 16]"),
            std::string::npos)
      << exponent.output;
}

TEST_F(CliTest, MontageTakesOneLabelPerImageSlow) {
  columba::Image tile(4, 4);
  const std::string a = (dir_ / "a.png").string(), b = (dir_ / "b.png").string();
  columba::writePNG(a, tile);
  columba::writePNG(b, tile);
  const std::string sheet = (dir_ / "sheet.png").string();
  CommandResult plain = run("montage -o " + sheet + " " + a + " " + b);
  ASSERT_EQ(plain.status, 0) << plain.output;
  const int plainHeight = columba::readPNG(sheet).height;
  // Long labels wrap: the sheet grows by their extra lines.
  CommandResult labelled =
      run("montage -o " + sheet +
          " --label 'a rather long caption that cannot fit in one line of a small tile' --label b " + a + " " + b);
  ASSERT_EQ(labelled.status, 0) << labelled.output;
  EXPECT_GT(columba::readPNG(sheet).height, plainHeight);
  std::string labels = write("labels.txt", "first\nsecond\n");
  EXPECT_EQ(run("montage -o " + sheet + " --labels " + labels + " " + a + " " + b).status, 0);
  CommandResult mismatch = run("montage -o " + sheet + " --label only-one " + a + " " + b);
  EXPECT_NE(mismatch.status, 0);
  EXPECT_NE(mismatch.output.find("1 labels for 2 images"), std::string::npos) << mismatch.output;
}

// Every command that writes makes the directories its outputs go in, as `mkdir -p` does; a file
// where a directory should be is still refused before any work, naming the path.
TEST_F(CliTest, RenderMakesTheDirectoriesOfItsOutputs) {
  std::string scene = write("tiny.xml", kTinyScene);
  CommandResult r = run("render " + scene + " -o " + (dir_ / "out/figures/x.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "out/figures/x.exr"));
  EXPECT_TRUE(fs::exists(dir_ / "out/figures/x.png"));
  // Frames whose directories vary with the sweep; the manifest goes where they part.
  CommandResult sweep =
      run("render " + scene + " --sweep res=4,6 --frames '" + (dir_ / "frames/r{res}/img.exr").string() + "'");
  ASSERT_EQ(sweep.status, 0) << sweep.output;
  for (const char* res : {"4", "6"}) EXPECT_TRUE(fs::exists(dir_ / "frames" / ("r" + std::string(res)) / "img.exr"));
  EXPECT_TRUE(fs::exists(dir_ / "frames/manifest.json"));
  // A piece of a split render.
  CommandResult part = run("render " + scene + " --part 1/2 -o " + (dir_ / "parts/p.exr").string());
  ASSERT_EQ(part.status, 0) << part.output;
  EXPECT_TRUE(fs::exists(dir_ / "parts/p.part1of2.exr"));
  // A file in the way.
  write("taken", "");
  const std::string blocked = (dir_ / "taken/sub/x.exr").string();
  CommandResult refused = run("render " + scene + " -o " + blocked);
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.output.find("cannot write '" + blocked + "': '" + (dir_ / "taken").string() +
                                "' is a file, not a directory"),
            std::string::npos)
      << refused.output;
}

TEST_F(CliTest, BsdfMakesItsOutputDirectory) {
  const fs::path out = dir_ / "green/spectra";
  CommandResult r = run("bsdf --mode specular --res 16 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "bsdf_specular.csv"));
  EXPECT_TRUE(fs::exists(out / "bsdf.json"));
  const std::string file = write("file", "");
  CommandResult refused = run("bsdf --mode specular -o " + file);
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.output.find("'" + file + "' is a file, not a directory"), std::string::npos) << refused.output;
}

TEST_F(CliTest, MontageMakesTheDirectoryOfItsSheet) {
  columba::Image tile(4, 4);
  const std::string a = (dir_ / "a.png").string();
  columba::writePNG(a, tile);
  const fs::path sheet = dir_ / "out/figures/sheet.png";
  CommandResult r = run("montage -o " + sheet.string() + " " + a);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(sheet));
  // Checked before the images are read.
  CommandResult refused = run("montage -o " + (dir_ / "a.png/sheet.png").string() + " " + a);
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.output.find("'" + a + "' is a file, not a directory"), std::string::npos) << refused.output;
}

TEST_F(CliTest, MontageOfFewerImagesThanColumnsIsOneRowWide) {
  columba::Image tile(4, 4);
  const std::string a = (dir_ / "a.png").string(), b = (dir_ / "b.png").string();
  columba::writePNG(a, tile);
  columba::writePNG(b, tile);
  const std::string sheet = (dir_ / "sheet.png").string();
  ASSERT_EQ(run("montage --tile 40 -o " + sheet + " " + a + " " + b).status, 0);
  EXPECT_EQ(columba::readPNG(sheet).width, 12 + 2 * (40 + 12));  // 2 tiles, not the 4 columns
}

TEST_F(CliTest, MergeMakesTheDirectoryOfTheMergedImage) {
  std::string scene = write("tiny.xml", kTinyScene);
  std::string pieces;
  for (int k = 1; k <= 2; ++k) {
    ASSERT_EQ(run("render " + scene + " --part " + std::to_string(k) + "/2 -o " + (dir_ / "p.exr").string()).status, 0);
    pieces += " " + (dir_ / ("p.part" + std::to_string(k) + "of2.exr")).string();
  }
  const fs::path merged = dir_ / "merged/deep/m.exr";
  CommandResult r = run("merge" + pieces + " -o " + merged.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(merged));
  EXPECT_TRUE(fs::exists(dir_ / "merged/deep/m.png"));
  // Still never over one of its pieces.
  CommandResult over = run("merge" + pieces + " -o " + (dir_ / "p.part1of2.exr").string());
  EXPECT_NE(over.status, 0);
  EXPECT_NE(over.output.find("which the merge reads"), std::string::npos) << over.output;
}

TEST_F(CliTest, SlurmMakesItsOutputDirectory) {
  std::string scene = write("tiny.xml", kTinyScene);
  const fs::path out = dir_ / "jobs/tiny";
  CommandResult r = run("slurm " + scene + " --parts 2 --out-dir " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "manifest.json"));
  EXPECT_TRUE(fs::is_directory(out / "parts"));
  EXPECT_TRUE(fs::is_directory(out / "logs"));
  const std::string file = write("file", "");
  CommandResult refused = run("slurm " + scene + " --parts 2 --out-dir " + file + "/job");
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.output.find("'" + file + "' is a file, not a directory"), std::string::npos) << refused.output;
}

namespace {
// The rows of a CSV file without its comment lines, the header first, each split at commas.
std::vector<std::vector<std::string>> csvRows(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}
}  // namespace

TEST_F(CliTest, BsdfMeasuresBarbulesOfArmsAndOneArmReflectsAsTheEllipse) {
  // One arm is the ellipse barbule with its upper half reflective: the same R in the mirror
  // direction, through the other model's code; barbulearms has no TRT.
  const std::string shape = " --b 0.25 --mu -0.35 --H 1.25 --height 0.58 --mode specular --angles 0,30 -o ";
  CommandResult arms = run("bsdf --arm-tilts 0 --profile-exponent 2" + shape + (dir_ / "arms").string());
  ASSERT_EQ(arms.status, 0) << arms.output;
  EXPECT_NE(arms.output.find("barbulearms | arm_tilts 0 deg"), std::string::npos) << arms.output;
  CommandResult ellipse = run("bsdf --phi_0 -1.5707964 --phi_1 1.5707964" + shape + (dir_ / "ellipse").string());
  ASSERT_EQ(ellipse.status, 0) << ellipse.output;
  const auto a = csvRows(dir_ / "arms" / "bsdf_specular.csv"), e = csvRows(dir_ / "ellipse" / "bsdf_specular.csv");
  ASSERT_EQ(a.size(), e.size());
  ASSERT_EQ(a[0], e[0]);  // wavelength_nm, then R, TRT and total per angle
  int compared = 0;
  for (size_t i = 1; i < a.size(); ++i)
    for (size_t column : {size_t(1), size_t(4)}) {
      const double r = std::stod(a[i][column]), expected = std::stod(e[i][column]);
      EXPECT_NEAR(r, expected, 1e-3 * expected + 1e-7) << a[0][column] << " at " << a[i][0] << " nm";
      EXPECT_EQ(std::stod(a[i][column + 1]), 0.0);
      compared += expected > 0.0;
    }
  EXPECT_GT(compared, 500);
  // Flat arms warn that point values at a face's normal are spikes; the ellipse's own options are
  // refused, naming them.
  CommandResult flat = run("bsdf --arm-tilts -30,0,30 --mode plane --angles 0 -o " + (dir_ / "flat").string());
  EXPECT_EQ(flat.status, 0) << flat.output;
  EXPECT_NE(flat.output.find("are spikes, not readings"), std::string::npos) << flat.output;
  CommandResult arc = run("bsdf --arm-tilts 0 --phi_0 0 -o " + (dir_ / "arc").string());
  EXPECT_NE(arc.status, 0);
  EXPECT_NE(arc.output.find("--phi_0: has no effect on barbules of arms"), std::string::npos) << arc.output;
  CommandResult tilt = run("bsdf --arm-tilts 0,95 -o " + (dir_ / "tilt").string());
  EXPECT_NE(tilt.status, 0);
  EXPECT_NE(tilt.output.find("--arm-tilts: '95'"), std::string::npos) << tilt.output;
}

// Values that would leave the range the films' arithmetic holds, or have no effect, are refused or
// warned about, naming the option (a Cauchy b of 1e10 wrote thousands of nan cells with status 0).
TEST_F(CliTest, BsdfRefusesIndicesBeyondAnyMaterialAndSaysWhatHasNoEffect) {
  CommandResult r = run("bsdf --film-cauchy-a 1.5 --film-cauchy-b 1e10 --mode specular -o " + (dir_ / "b").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--film-cauchy-b: the film's index reaches 111113 between 300 and 830 nm; an index "
                          "above 100 is no material's"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "b"));
  r = run("bsdf --film-ior 150 --mode specular -o " + (dir_ / "n").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--film-ior: the film's index reaches 150"), std::string::npos) << r.output;
  r = run("bsdf --arm-tilts '' --mode specular -o " + (dir_ / "arms").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--arm-tilts: gives no arm"), std::string::npos) << r.output;
  // A layer given in nm is read in micrometres: measured all the same, with a warning.
  r = run("bsdf --layers 'keratin:0.1, melanin:300' --mode specular --angles 0 -o " + (dir_ / "nm").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: --layers: layer 2 is 300 um thick, implausible"), std::string::npos) << r.output;
  // The largest index accepted keeps every spectrum finite.
  r = run("bsdf --film-cauchy-a 1.5 --film-cauchy-b 8.8e6 --mode specular --angles 0,60 -o " +
          (dir_ / "edge").string());
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream csv(dir_ / "edge" / "bsdf_specular.csv");
  const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  EXPECT_GT(text.size(), 1000u);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
}

// Emitted light that would overflow the image's float sums is refused where the scene gives it;
// a render whose pixels are not all finite all the same fails and writes nothing (an emitter of
// 1e37 wrote an all-NaN EXR with status 0).
// --spectral's bins cover the whole range the film renders unless --spectral-range narrows it,
// and the EXR says which (they stopped at 400-700 nm while the renderer draws 360-830).
TEST_F(CliTest, SpectralBinsCoverTheRenderedRangeOrTheOneAskedFor) {
  const std::string scene = write("tiny.xml", kTinyScene);
  const std::string out = (dir_ / "s.exr").string();
  CommandResult r = run("render " + scene + " --spectral --bins 4 -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  columba::EXRImageFile file = columba::readEXRFile(out);
  EXPECT_EQ(file.image.spectral.centres, (std::vector<float>{418.75f, 536.25f, 653.75f, 771.25f}));
  EXPECT_NE(columba::metadataValue(file.metadata, "Spectral channels").find("4 bins of 117.5 nm over 360-830 nm"),
            std::string::npos);
  r = run("render " + scene + " --spectral --bins 3 --spectral-range 400:700 -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(columba::readEXR(out).spectral.centres, (std::vector<float>{450.0f, 550.0f, 650.0f}));
  r = run("render " + scene + " --spectral --spectral-range 300:700 -o " + (dir_ / "uv.exr").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--spectral-range 300-700 nm is not a range within the 360-830 nm this film renders"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "uv.exr"));
  r = run("render " + scene + " --spectral-range 400:700 -o " + (dir_ / "alone.exr").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--spectral-range requires --spectral"), std::string::npos) << r.output;
}

TEST_F(CliTest, ARenderNeverWritesANonFinitePixel) {
  const std::string scene = write("bright.xml", kTinyScene);
  const std::string out = (dir_ / "bright.exr").string();
  for (const char* value : {"1e37", "1e35"}) {
    CommandResult r = run("render " + scene + " -D res=4 -D radiance=" + value + " -o " + out);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("bright.xml:8"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("parameter 'radiance' of <emitter> 'constant' is emitted light that reaches"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
  CommandResult r = run("render " + scene + " -D res=4 -D radiance=1e29 -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  const columba::Image image = columba::readEXR(out);
  for (float v : image.rgb) ASSERT_TRUE(std::isfinite(v) && v > 1e28f) << v;
  // A texture's emitted values are the file's: 1e37 overflows, and nothing is written.
  columba::Image hot(2, 2);
  std::fill(hot.rgb.begin(), hot.rgb.end(), 1e37f);
  columba::writeEXR((dir_ / "hot.exr").string(), hot);
  const std::string textured = write("textured.xml", R"(<scene version="3.0.0">
  <sensor type="perspective">
    <transform name="to_world"><lookat origin="0,0,3" target="0,0,0" up="0,1,0"/></transform>
    <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/></film>
    <sampler type="independent"><integer name="sample_count" value="2"/></sampler>
  </sensor>
  <shape type="rectangle"><emitter type="area"><texture type="bitmap" name="radiance">
    <string name="filename" value="hot.exr"/></texture></emitter></shape>
</scene>
)");
  const std::string texturedOut = (dir_ / "textured.exr").string();
  r = run("render " + textured + " -o " + texturedOut);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("the render is not finite: 48 of its 48 RGB values are NaN or infinite"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(texturedOut));
  EXPECT_FALSE(fs::exists(dir_ / "textured.png"));
}

TEST_F(CliTest, BsdfWritesSpecularSpectraInPavosLayoutAndTheirConeCatches) {
  CommandResult r =
      run("bsdf --preset dove-green --mode specular --angles 0,30 --observer bluetit -o " + dir_.string());
  ASSERT_EQ(r.status, 0) << r.output;
  // pavo's layout: wl, then a spectrum a column, 1 nm over 300-700 nm, no comments; the same values as
  // the full table's total columns.
  const auto pavo = csvRows(dir_ / "bsdf_specular_pavo.csv");
  ASSERT_EQ(pavo.size(), 402u);
  EXPECT_EQ(pavo[0], (std::vector<std::string>{"wl", "total_theta0", "total_theta30"}));
  EXPECT_EQ(pavo[1][0], "300");
  EXPECT_EQ(pavo[401][0], "700");
  const auto full = csvRows(dir_ / "bsdf_specular.csv");
  ASSERT_EQ(full[0].back(), "total_theta30");
  EXPECT_EQ(full[1].back(), pavo[1].back());
  EXPECT_EQ(full[401].back(), pavo[401].back());
  // pavo's summary variables of each column, recomputed here from the pavo file as summary.rspec
  // would: B1 the sum, S8 (max - min) / mean, H1 the first wavelength of the maximum; and the
  // maximum over 400-700 nm, which for the green barbule at 0 degrees is the order at 404 nm.
  std::stringstream json;
  json << std::ifstream(dir_ / "bsdf.json").rdbuf();
  const nlohmann::json record = nlohmann::json::parse(json.str());
  for (size_t column = 1; column <= 2; ++column) {
    double sum = 0.0, largest = -1.0, smallest = 1e30, hue = 0.0, visiblePeak = 0.0, visibleLargest = -1.0;
    for (size_t row = 1; row < pavo.size(); ++row) {
      const double wl = std::stod(pavo[row][0]), v = std::stod(pavo[row][column]);
      sum += v;
      if (v > largest) largest = v, hue = wl;
      smallest = std::min(smallest, v);
      if (wl >= 400.0 && v > visibleLargest) visibleLargest = v, visiblePeak = wl;
    }
    const nlohmann::json& entry = record["specular"][column - 1];
    EXPECT_NEAR(entry["pavo_summary"]["B1"].get<double>(), sum, 1e-3 * sum);
    EXPECT_NEAR(entry["pavo_summary"]["S8"].get<double>(), (largest - smallest) / (sum / 401.0), 1e-3);
    EXPECT_EQ(entry["pavo_summary"]["H1_nm"].get<double>(), hue);
    EXPECT_EQ(entry["visible_peak_nm"].get<double>(), visiblePeak);
  }
  EXPECT_EQ(record["specular"][0]["visible_peak_nm"].get<double>(), 404.0);
  EXPECT_NE(r.output.find("colour summary of the total, pavo's summary.rspec over 300-700 nm"), std::string::npos);
  // Cone catches: relative catches sum to 1, the first angle is 0 JND from itself and the second is not.
  const auto catches = csvRows(dir_ / "bsdf_specular_catches.csv");
  ASSERT_EQ(catches.size(), 3u);
  EXPECT_EQ(catches[0], (std::vector<std::string>{"light_theta_deg", "UVS", "SWS", "MWS", "LWS", "relative_UVS",
                                                  "relative_SWS", "relative_MWS", "relative_LWS", "dS_jnd"}));
  for (size_t row = 1; row < 3; ++row) {
    double sum = 0.0;
    for (size_t c = 5; c < 9; ++c) sum += std::stod(catches[row][c]);
    EXPECT_NEAR(sum, 1.0, 1e-5);
  }
  EXPECT_EQ(std::stod(catches[1][9]), 0.0);
  EXPECT_GT(std::stod(catches[2][9]), 1.0);
  // An unknown observer, or one without the specular spectra it measures, is refused.
  CommandResult unknown = run("bsdf --mode specular --observer budgie -o " + dir_.string());
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.output.find("unknown observer 'budgie' (known: bluetit, avg.uv, avg.v; or a table, FILE.csv)"),
            std::string::npos)
      << unknown.output;
  CommandResult withoutSpecular = run("bsdf --mode spectra --observer bluetit -o " + dir_.string());
  EXPECT_NE(withoutSpecular.status, 0);
  EXPECT_NE(withoutSpecular.output.find("add --mode specular"), std::string::npos) << withoutSpecular.output;
}

// A table of sensitivities whose largest is 1e308 (their area once overflowed): the catches of the
// blue tit's own curves so scaled are the built-in blue tit's, where the command failed naming no file.
TEST_F(CliTest, BsdfConeCatchesOfATableInHugeUnitsAreTheBuiltInObserversOwn) {
  const columba::Observer tit = columba::namedObserver("bluetit");
  float peak = 0.0f;
  for (const std::vector<float>& s : tit.sensitivities) peak = std::max(peak, *std::max_element(s.begin(), s.end()));
  std::ofstream table(dir_ / "huge.csv");
  table << "wl,UVS,SWS,MWS,LWS\n";
  for (size_t i = 0; i < tit.grid.count; ++i) {
    table << tit.grid.wavelength(i);
    for (const std::vector<float>& s : tit.sensitivities) table << "," << double(s[i]) / peak * 1e308;
    table << "\n";
  }
  table.close();
  const std::string common = "bsdf --preset dove-green --mode specular --angles 0,30 --observer ";
  CommandResult huge = run(common + (dir_ / "huge.csv").string() + " -o " + (dir_ / "huge").string());
  ASSERT_EQ(huge.status, 0) << huge.output;
  CommandResult builtIn = run(common + "bluetit -o " + (dir_ / "builtin").string());
  ASSERT_EQ(builtIn.status, 0) << builtIn.output;
  const auto a = csvRows(dir_ / "huge" / "bsdf_specular_catches.csv"),
             e = csvRows(dir_ / "builtin" / "bsdf_specular_catches.csv");
  ASSERT_EQ(a.size(), e.size());
  for (size_t row = 1; row < e.size(); ++row)
    for (size_t c = 1; c < e[row].size(); ++c)
      EXPECT_NEAR(std::stod(a[row][c]), std::stod(e[row][c]), 1e-4 * std::abs(std::stod(e[row][c])) + 1e-6)
          << e[0][c] << " at " << e[row][0] << " degrees";
}

TEST_F(CliTest, ConeChannelsOfASplitRenderMergeBitForBit) {
  // A bird observer's film rendered in two parts and merged: RGB and cone channels as the render in
  // one piece, and the merged EXR names the observer.
  const std::string scene = write("bird.xml", R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="30"/>
    <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="10"/>
      <string name="observer" value="avg.v"/></film>
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler></sensor>
  <emitter type="constant"/>
  <shape type="rectangle"><transform name="to_world"><scale value="1"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.6, 0.3"/></bsdf></shape>
</scene>)");
  const std::string whole = (dir_ / "whole.exr").string(), part = (dir_ / "parts/bird.exr").string();
  ASSERT_EQ(run("render " + scene + " -o " + whole).status, 0);
  for (const char* k : {"1/2", "2/2"}) ASSERT_EQ(run("render " + scene + " --part " + k + " -o " + part).status, 0);
  const std::string merged = (dir_ / "merged.exr").string();
  CommandResult r = run("merge " + (dir_ / "parts/bird.part1of2.exr").string() + " " +
                        (dir_ / "parts/bird.part2of2.exr").string() + " -o " + merged);
  ASSERT_EQ(r.status, 0) << r.output;
  const columba::EXRImageFile a = columba::readEXRFile(whole), b = columba::readEXRFile(merged);
  EXPECT_EQ(b.image.cones.names, (std::vector<std::string>{"VS", "SWS", "MWS", "LWS"}));
  EXPECT_EQ(a.image.cones.values, b.image.cones.values);
  EXPECT_EQ(a.image.rgb, b.image.rgb);
  EXPECT_EQ(columba::metadataValue(b.metadata, "Observer").rfind("avg.v: quantum catches of VS, SWS, MWS, LWS", 0), 0u)
      << columba::metadataValue(b.metadata, "Observer");
}
