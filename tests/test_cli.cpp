#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "render/image.h"

namespace fs = std::filesystem;

namespace {
struct CommandResult {
  int status = -1;
  std::string output;  // stdout and stderr
};

CommandResult run(const std::string& args) {
  CommandResult r;
  std::string command = std::string(COLUMBA_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
  int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("columba_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

const char* kTinyScene = R"(<scene version="3.0.0">
  <default name="res" value="8"/>
  <sensor type="perspective">
    <film type="hdrfilm"><integer name="width" value="$res"/><integer name="height" value="$res"/></film>
    <sampler type="independent"><integer name="sample_count" value="2"/></sampler>
  </sensor>
  <emitter type="constant"><spectrum name="radiance" value="0.5"/></emitter>
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

TEST_F(CliTest, MalformedScenesFailWithFileLineAndValue) {
  struct Case {
    const char* name;
    std::string xml;
    std::vector<std::string> expected;  // fragments of the message
  };
  std::vector<Case> cases = {
      {"unknown_plugin.xml", "<scene version=\"3.0.0\">\n  <bsdf type=\"velvet\"/>\n</scene>\n", {":2", "velvet"}},
      {"bad_number.xml",
       "<scene version=\"3.0.0\">\n<sensor type=\"perspective\">\n  <float name=\"fov\" value=\"4o\"/>\n</sensor>\n</scene>\n",
       {":3", "4o"}},
      {"missing_file.xml",
       "<scene version=\"3.0.0\">\n<shape type=\"obj\">\n<string name=\"filename\" value=\"nowhere.obj\"/>\n</shape>\n</scene>\n",
       {":3", "nowhere.obj"}},
      {"missing_default.xml",
       "<scene version=\"3.0.0\">\n<sensor type=\"perspective\">\n<float name=\"fov\" value=\"$angle\"/>\n</sensor>\n</scene>\n",
       {":3", "angle"}},
      {"unknown_parameter.xml", "<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n<float name=\"radiancee\" value=\"1\"/>\n</emitter>\n</scene>\n",
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
  std::string bad = write("bad.xml", "<scene version=\"3.0.0\">\n<integrator type=\"path\"><integer name=\"max_depth\" value=\"x\"/></integrator></scene>");
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

TEST_F(CliTest, InterruptWritesThePartialImageAndFails) {
  std::string scene = write("tiny.xml", kTinyScene);
  std::string out = (dir_ / "partial.exr").string();
  // A render far too long to finish; SIGINT after half a second.
  std::string script = std::string(COLUMBA_BINARY) + " render " + scene + " -D res=64 --spp 1000000 -o " + out +
                       " >/dev/null 2>&1 & pid=$!; sleep 0.5; kill -INT $pid; wait $pid; echo status=$?";
  FILE* pipe = popen(("sh -c '" + script + "'").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[256] = {0};
  std::string output;
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  pclose(pipe);
  EXPECT_NE(output.find("status=130"), std::string::npos) << output;
  columba::Image img = columba::readEXR(out);
  EXPECT_EQ(img.width, 64);
}

TEST_F(CliTest, DefaultSceneIsAGeneratedNeck) {
  std::string out = (dir_ / "default.exr").string();
  CommandResult r = run("render -D width=40 -D height=30 -D spp=2 -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("default scene"), std::string::npos) << r.output;
  columba::Image img = columba::readEXR(out);
  EXPECT_EQ(img.width, 40);
  // Hundreds of thousands of barb segments were generated and loaded.
  size_t at = r.output.find(" primitives");
  ASSERT_NE(at, std::string::npos) << r.output;
  size_t start = r.output.rfind(' ', at - 1) + 1;
  EXPECT_GT(std::stol(r.output.substr(start, at - start)), 100000) << r.output;
}
