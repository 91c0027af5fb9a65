// Scene files built to exhaust or confuse the loader get located errors, quickly.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>
#include "builtin/builtin_plugins.h"
#include "support/temp_dir_test.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene_loader.h"

using namespace columba;
namespace fs = std::filesystem;

namespace {

ParsedScene load(const std::string& xml, const Defines& defines = {}) {
  return loadSceneString(xml, "hostile.xml", fs::temp_directory_path().string(), defines, builtinPlugins());
}

// The message of the InputError that loading `xml` throws ("" if none).
std::string loadError(const std::string& xml, const Defines& defines = {}) {
  try {
    load(xml, defines);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

class HostileSceneFiles : public columba::testing::TempDirTest {};

}  // namespace

TEST(HostileScenes, DeepNestingIsAnErrorNotAStackOverflow) {
  const int depth = 10000;
  std::string xml = "<scene version=\"3.0.0\">\n";
  for (int i = 0; i < depth; ++i) xml += "<bsdf type=\"twosided\">";
  for (int i = 0; i < depth; ++i) xml += "</bsdf>";
  xml += "\n</scene>\n";
  std::string message = loadError(xml);
  EXPECT_NE(message.find("hostile.xml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("nested more than 64"), std::string::npos) << message;
}

TEST(HostileScenes, SixtyFourLevelsAreStillRead) {
  // A chain of exactly 64 plug-ins gets past the depth check to the factories.
  std::string chain = "<scene version=\"3.0.0\">\n";
  for (int i = 0; i < 64; ++i) chain += "<bsdf type=\"twosided\">";
  for (int i = 0; i < 64; ++i) chain += "</bsdf>";
  chain += "\n</scene>\n";
  std::string message = loadError(chain);
  EXPECT_EQ(message.find("nested more than"), std::string::npos) << message;
  EXPECT_NE(message.find("hostile.xml:2"), std::string::npos) << message;  // twosided in twosided is refused
}

TEST(HostileScenes, DollarSubstitutionIsLinear) {
  std::string dollars;
  for (int i = 0; i < 4096; ++i) dollars += "$ ";  // 8 KB
  std::string xml =
      "<scene version=\"3.0.0\">\n<default name=\"a\" value=\"1\"/>\n"
      "<integrator type=\"path\"><string name=\"x\" value=\"" +
      dollars + "\"/></integrator>\n</scene>\n";
  auto start = std::chrono::steady_clock::now();
  std::string message = loadError(xml);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.5);
  EXPECT_NE(message.find("unknown parameter 'x'"), std::string::npos) << message;  // the $ were left alone
}

TEST(HostileScenes, UndefinedVariableMessagesAreShort) {
  std::string name(20000, 'q');
  std::string message = loadError("<scene version=\"3.0.0\">\n<integrator type=\"path\"><string name=\"x\" value=\"$" +
                                  name + "\"/></integrator>\n</scene>\n");
  EXPECT_NE(message.find("undefined variable '$qqqq"), std::string::npos) << message.substr(0, 300);
  EXPECT_NE(message.find("hostile.xml:2"), std::string::npos);
  EXPECT_LT(message.size(), 400u) << message.substr(0, 300);
}

TEST(HostileScenes, LongestKnownNameWinsAndDefinesOverrideDefaults) {
  std::string xml =
      "<scene version=\"3.0.0\">\n<default name=\"d\" value=\"1\"/>\n<default name=\"dd\" value=\"2\"/>\n"
      "<integrator type=\"path\"><integer name=\"max_depth\" value=\"$dd$d\"/></integrator>\n</scene>\n";
  EXPECT_EQ(loadError(xml), "");
  // $dd$d reads as 2 then 1 (= 21), or with -D d=3 as 23; -D dd=4 gives 41: both are valid depths.
  EXPECT_EQ(loadError(xml, {{"d", "3"}}), "");
  EXPECT_NE(loadError(xml, {{"dd", "x"}}).find("'x1'"), std::string::npos) << loadError(xml, {{"dd", "x"}});
}

TEST(HostileScenes, UnusedDefinesAreReported) {
  std::string xml =
      "<scene version=\"3.0.0\">\n<default name=\"depth\" value=\"3\"/>\n<default name=\"spp\" value=\"4\"/>\n"
      "<integrator type=\"path\"><integer name=\"max_depth\" value=\"$depth\"/></integrator>\n</scene>\n";
  ParsedScene scene = load(xml, {{"depth", "5"}, {"sp", "4"}, {"spp", "8"}});
  // `spp` overrides a <default> that no value uses: it has no effect either.
  EXPECT_EQ(scene.unusedDefines, (std::vector<std::string>{"sp", "spp"}));
}

TEST(HostileScenes, VariableNamesAreChecked) {
  EXPECT_NE(
      loadError("<scene version=\"3.0.0\">\n<default name=\"a-b\" value=\"3\"/>\n</scene>\n").find("hostile.xml:2"),
      std::string::npos);
  EXPECT_THROW(load("<scene version=\"3.0.0\"/>", {{"a b", "1"}}), std::runtime_error);
}

TEST(HostileScenes, NumbersBeyondFloatRangeAreRejected) {
  for (std::string element :
       {"<point name=\"position\" value=\"1e39, 0, 0\"/>", "<point name=\"position\" x=\"-1e39\"/>"}) {
    std::string message =
        loadError("<scene version=\"3.0.0\">\n<emitter type=\"point\">\n" + element + "\n</emitter>\n</scene>\n");
    EXPECT_NE(message.find("hostile.xml:3"), std::string::npos) << message;
    EXPECT_NE(message.find("out of the range of a float"), std::string::npos) << message;
  }
  std::string message = loadError(
      "<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n"
      "<spectrum name=\"radiance\" value=\"400:1, 500:4e38\"/>\n</emitter>\n</scene>\n");
  EXPECT_NE(message.find("'4e38'"), std::string::npos) << message;
  message = loadError(
      "<scene version=\"3.0.0\">\n<shape type=\"sphere\">\n<transform name=\"to_world\">\n"
      "<scale value=\"1e300\"/></transform>\n</shape>\n</scene>\n");
  EXPECT_NE(message.find("hostile.xml:4"), std::string::npos) << message;
}

TEST_F(HostileSceneFiles, SpectrumFilesMustBeRegularFiles) {
  std::string fifo = (dir_ / "pipe.spd").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (std::string file : {std::string("/dev/zero"), fifo, (dir_ / "nowhere.spd").string(), dir_.string()}) {
    std::string message = loadError(
        "<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n<spectrum name=\"radiance\" "
        "filename=\"" +
        file + "\"/>\n</emitter>\n</scene>\n");
    EXPECT_NE(message.find("hostile.xml:3"), std::string::npos) << message;
    EXPECT_NE(message.find("not a regular file"), std::string::npos) << message;
    EXPECT_NE(message.find(file), std::string::npos) << message;
  }
}

TEST_F(HostileSceneFiles, IncludeCycleNamesTheFileThatStartsIt) {
  std::string top = write("top.xml", "<scene version=\"3.0.0\">\n  <include filename=\"middle.xml\"/>\n</scene>\n");
  write("middle.xml", "<scene version=\"3.0.0\">\n\n  <include filename=\"top.xml\"/>\n</scene>\n");
  try {
    loadSceneFile(top, {}, builtinPlugins());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    std::string message = e.what();
    // Reported where the cycle closes, naming the file it returns to, with the whole chain.
    EXPECT_NE(message.find("middle.xml:3"), std::string::npos) << message;
    EXPECT_NE(message.find("including '" + (dir_ / "top.xml").string() + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("top.xml -> " + fs::weakly_canonical(dir_ / "middle.xml").string() + " -> "),
              std::string::npos)
        << message;
  }
}

TEST(HostileScenes, NegativeEmissionIsRejected) {
  for (std::string value : {std::string("<float name=\"radiance\" value=\"-1\"/>"),
                            std::string("<rgb name=\"radiance\" value=\"1, -0.5, 0\"/>"),
                            std::string("<spectrum name=\"radiance\" value=\"400:1, 500:-0.25, 600:1\"/>"),
                            std::string("<spectrum name=\"radiance\" value=\"-3\"/>")}) {
    SCOPED_TRACE(value);
    std::string message =
        loadError("<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n" + value + "\n</emitter>\n</scene>\n");
    EXPECT_NE(message.find("hostile.xml:3"), std::string::npos) << message;
    EXPECT_NE(message.find("cannot be negative"), std::string::npos) << message;
  }
  // Zero is dark, not negative.
  EXPECT_EQ(loadError("<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n<spectrum name=\"radiance\" "
                      "value=\"400:0, 500:2\"/>\n</emitter>\n</scene>\n"),
            "");
}

// As spreadsheet programs save text: line 1 was "invalid number '<BOM>400' for the wavelength".
TEST_F(HostileSceneFiles, ASpectrumFileMayStartWithAByteOrderMark) {
  std::string file = write("bom.spd",
                           "\xEF\xBB\xBF"
                           "400 1\n500 2\n");
  EXPECT_EQ(loadError("<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n<spectrum name=\"radiance\" "
                      "filename=\"" +
                      file + "\"/>\n</emitter>\n</scene>\n"),
            "");
}

TEST_F(HostileSceneFiles, NegativeEmissionFromAFileIsRejected) {
  std::string file = write("light.spd", "400 1\n500 -2\n");
  std::string message = loadError(
      "<scene version=\"3.0.0\">\n<emitter type=\"constant\">\n<spectrum name=\"radiance\" "
      "filename=\"" +
      file + "\"/>\n</emitter>\n</scene>\n");
  EXPECT_NE(message.find("hostile.xml:3"), std::string::npos) << message;
  EXPECT_NE(message.find("lowest value is -2"), std::string::npos) << message;
}
