#include <gtest/gtest.h>

#include "support/error_test_support.h"

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include "core/illuminant.h"
#include "scene/scene_loader.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::expectContains;

namespace {

// Stand-in plug-ins: each reads the parameters its factory was told about and keeps them.
struct TestObject : Object {
  std::string tag, type, id;
  std::map<std::string, float> floats;
  std::map<std::string, int> ints;
  std::map<std::string, bool> bools;
  std::map<std::string, std::string> strings;
  std::map<std::string, Vec3> vectors;
  std::map<std::string, SpectralDistribution> spectra;
  std::map<std::string, Transform> transforms;
  std::vector<std::shared_ptr<TestObject>> children;
};

enum class Param { Float, Int, Bool, String, Path, Vector, Reflectance, Radiance, Transform };
using Schema = std::vector<std::pair<std::string, Param>>;

std::vector<std::string> creationLog;

PluginFactory reader(Schema schema, bool takesChildren = true) {
  return [schema, takesChildren](const Properties& props) {
    auto obj = std::make_shared<TestObject>();
    obj->tag = props.tag;
    obj->type = props.type;
    obj->id = props.id;
    for (const auto& [name, kind] : schema) {
      if (!props.has(name)) continue;
      switch (kind) {
        case Param::Float:
          obj->floats[name] = props.getFloat(name);
          break;
        case Param::Int:
          obj->ints[name] = props.getInt(name);
          break;
        case Param::Bool:
          obj->bools[name] = props.getBool(name, false);
          break;
        case Param::String:
          obj->strings[name] = props.getString(name);
          break;
        case Param::Path:
          obj->strings[name] = props.getPath(name);
          break;
        case Param::Vector:
          obj->vectors[name] = props.getVector(name, Vec3());
          break;
        case Param::Reflectance:
          obj->spectra[name] = props.getSpectrum(name, 0.5f, SpectrumUse::Reflectance);
          break;
        case Param::Radiance:
          obj->spectra[name] = props.getSpectrum(name, 0.0f, SpectrumUse::Emission);
          break;
        case Param::Transform:
          obj->transforms[name] = props.getTransform(name);
          break;
      }
    }
    if (takesChildren) obj->children = props.children<TestObject>();
    creationLog.push_back(props.tag + ":" + props.type + (props.id.empty() ? "" : "#" + props.id));
    return obj;
  };
}

const PluginRegistry& testRegistry() {
  static const PluginRegistry registry = [] {
    PluginRegistry r;
    r.add("bsdf", "probe",
          reader({{"count", Param::Int},
                  {"scale", Param::Float},
                  {"flag", Param::Bool},
                  {"label", Param::String},
                  {"dir", Param::Vector},
                  {"color", Param::Reflectance},
                  {"glow", Param::Radiance},
                  {"to_world", Param::Transform},
                  {"file", Param::Path}}));
    r.add("bsdf", "diffuse", reader({{"reflectance", Param::Reflectance}}));
    r.add("bsdf", "twosided", reader({}));
    r.add("shape", "mesh", reader({{"to_world", Param::Transform}}));
    r.add("emitter", "area", reader({{"radiance", Param::Radiance}}, false));
    r.add("integrator", "path", reader({{"max_depth", Param::Int}, {"spp", Param::Int}}));

    // The plug-ins of the reference scenes, with the parameters they use.
    r.add("integrator", "direct",
          reader({{"emitter_samples", Param::Int}, {"bsdf_samples", Param::Int}, {"samples_per_pass", Param::Int}}));
    r.add("sensor", "perspective",
          reader({{"fov", Param::Float}, {"fov_axis", Param::String}, {"to_world", Param::Transform}}));
    r.add("sensor", "bsdfvisualizer", reader({}));
    r.add("film", "hdrfilm",
          reader({{"width", Param::Int},
                  {"height", Param::Int},
                  {"pixel_format", Param::String},
                  {"component_format", Param::String}}));
    r.add("rfilter", "gaussian", reader({}, false));
    r.add("sampler", "ldsampler", reader({{"sample_count", Param::Int}}, false));
    Schema barbule = {{"film_ior", Param::String}, {"ext_ior", Param::String}, {"height", Param::Float},
                      {"b", Param::Float},         {"phi_0", Param::Float},    {"phi_1", Param::Float},
                      {"mu", Param::Float},        {"H", Param::Float}};
    r.add("bsdf", "barbulebsdf", reader(barbule, false));
    r.add("bsdf", "barbulebsdfev", reader(barbule, false));
    r.add("bsdf", "roughplastic",
          reader({{"diffuse_reflectance", Param::Reflectance},
                  {"specular_reflectance", Param::Reflectance},
                  {"alpha", Param::Float}}));
    r.add("shape", "obj", reader({{"filename", Param::Path}, {"to_world", Param::Transform}}));
    // The reference feather PLY files were never published, so the name is read as plain text.
    r.add("shape", "feather",
          reader({{"filename", Param::String},
                  {"barbwidth", Param::Float},
                  {"ramuswidth", Param::Float},
                  {"to_world", Param::Transform}}));
    r.add("shape", "rectangle", reader({{"to_world", Param::Transform}}));
    r.add("shape", "disk", reader({{"to_world", Param::Transform}}));
    r.add("emitter", "constant", reader({{"radiance", Param::Radiance}}, false));
    return r;
  }();
  return registry;
}

// A directory the test scenes' relative paths resolve against, with one small spectrum file:
// data/sample.spd, two (wavelength nm, value) lines.
class DataDirectory {
 public:
  DataDirectory() : dir_(std::filesystem::temp_directory_path() / ("columba_xml_data_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_ / "data");
    std::ofstream(dir_ / "data" / "sample.spd") << "249.7909 0.0300\n253.6204 0.0284\n";
  }
  ~DataDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  std::string path() const { return dir_.string(); }

 private:
  std::filesystem::path dir_;
};

const std::string& dataDir() {
  static const DataDirectory dir;
  static const std::string path = dir.path();
  return path;
}

ParsedScene load(const std::string& xml, const Defines& defines = {}, const std::string& baseDir = dataDir()) {
  creationLog.clear();
  return loadSceneString(xml, "test.xml", baseDir, defines, testRegistry());
}

std::shared_ptr<TestObject> only(const ParsedScene& scene) {
  EXPECT_EQ(scene.objects.size(), 1u);
  return std::dynamic_pointer_cast<TestObject>(scene.objects.at(0));
}

// The message of the InputError that loading `xml` throws ("" if none).
std::string errorOf(const std::string& xml, const Defines& defines = {}) {
  try {
    load(xml, defines);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string probe(const std::string& body) {
  return "<scene version=\"3.0.0\">\n<bsdf type=\"probe\">\n" + body + "\n</bsdf>\n</scene>\n";
}

void expectMatrixNear(const Matrix4& m, const double (&expected)[4][4], double tol = 1e-6) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(m.m[i][j], expected[i][j], tol) << "element " << i << "," << j;
}

}  // namespace

TEST(XmlLoader, ReadsEveryParameterKind) {
  auto p = only(load(probe(R"(<integer name="count" value="-7"/>
<float name="scale" value="+2.5e-1"/>
<boolean name="flag" value="true"/>
<string name="label" value="a b"/>
<vector name="dir" x="1" z="3"/>)")));
  EXPECT_EQ(p->ints.at("count"), -7);
  EXPECT_FLOAT_EQ(p->floats.at("scale"), 0.25f);
  EXPECT_TRUE(p->bools.at("flag"));
  EXPECT_EQ(p->strings.at("label"), "a b");
  EXPECT_EQ(p->vectors.at("dir"), Vec3(1, 0, 3));
}

TEST(XmlLoader, FloatParameterAcceptsAnInteger) {
  EXPECT_FLOAT_EQ(only(load(probe(R"(<integer name="scale" value="3"/>)")))->floats.at("scale"), 3.0f);
}

TEST(XmlLoader, WrongKindNamesParameterAndLine) {
  expectContains(errorOf(probe(R"(<string name="scale" value="big"/>)")),
                 {"test.xml:3", "'scale'", "<float>", "<string>"});
  expectContains(errorOf(probe(R"(<float name="count" value="3"/>)")), {"test.xml:3", "'count'", "<integer>"});
}

TEST(XmlLoader, SubstitutesDefaults) {
  auto p = only(load(R"(<scene version="3.0.0">
<default name="spp" value="64"/>
<default name="s" value="S"/>
<integrator type="path">
  <integer name="spp" value="$spp"/>
  <integer name="max_depth" value="1$s$spp" />
</integrator>
</scene>)",
                     {{"s", "2"}}));
  EXPECT_EQ(p->ints.at("spp"), 64);
  // "$s" and "$spp" are both defined: the longest name wins at each '$'; -D s=2 overrides "S".
  EXPECT_EQ(p->ints.at("max_depth"), 1264);
}

TEST(XmlLoader, DefinesOverrideDefaults) {
  auto p = only(load(R"(<scene version="3.0.0">
<default name="spp" value="64"/>
<integrator type="path"><integer name="spp" value="$spp"/></integrator>
</scene>)",
                     {{"spp", "16"}, {"unused", "1"}}));
  EXPECT_EQ(p->ints.at("spp"), 16);
}

TEST(XmlLoader, VariableFollowedByOtherCharacters) {
  std::string xml = R"(<scene version="3.0.0">
<bsdf type="probe"><string name="label" value="meshes/la$o0.obj"/></bsdf>
</scene>)";
  EXPECT_EQ(only(load(xml, {{"o", "-1"}}))->strings.at("label"), "meshes/la-10.obj");
  EXPECT_EQ(only(load(xml, {{"o", "03"}}))->strings.at("label"), "meshes/la030.obj");
}

TEST(XmlLoader, UndefinedVariableNamesFileLineAndName) {
  expectContains(errorOf(R"(<scene version="3.0.0">
<default name="spp" value="64"/>
<integrator type="path">
  <integer name="spp" value="$res"/>
</integrator>
</scene>)"),
                 {"test.xml:4", "$res"});
}

TEST(XmlLoader, UnknownPluginTypeNamesFileLineAndType) {
  expectContains(errorOf(R"(<scene version="3.0.0">

  <bsdf type="nonsense"/>
</scene>)"),
                 {"test.xml:3", "unknown <bsdf> plug-in type 'nonsense'"});
}

TEST(XmlLoader, MitsubaPluginsColumbaLacksAreNamedWithWhy) {
  expectContains(errorOf(R"(<scene version="3.0.0">
  <integrator type="prbvolpath"/>
</scene>)"),
                 {"test.xml:2", "<integrator type='prbvolpath'>: a Mitsuba plug-in Columba does not have",
                  "differentiable rendering is not supported; use 'volpath'"});
  expectContains(errorOf(R"(<scene version="3.0.0">
  <shape type="mesh">
    <bsdf type="diffuse"><texture name="reflectance" type="volume"/></bsdf>
  </shape>
</scene>)"),
                 {"test.xml:3", "<texture type='volume'>", "Columba has 'bitmap', 'checkerboard', 'mesh_attribute'"});
}

TEST(XmlLoader, BadNumbersAreErrors) {
  for (const char* bad : {"1.5x", "", "abc", "nan", "inf", "1e999"})
    expectContains(errorOf(probe(std::string("\n<float name=\"scale\" value=\"") + bad + "\"/>")),
                   {"test.xml:4", "'scale'", (std::string("'") + bad + "'").c_str()});
  expectContains(errorOf(probe(R"(<integer name="count" value="2.0"/>)")), {"test.xml:3", "'count'", "'2.0'"});
  expectContains(errorOf(probe(R"(<boolean name="flag" value="yes"/>)")), {"test.xml:3", "'flag'", "'yes'"});
}

TEST(XmlLoader, DuplicateParameterIsAnError) {
  expectContains(errorOf(probe("<float name=\"scale\" value=\"1\"/>\n<float name=\"scale\" value=\"2\"/>")),
                 {"test.xml:4", "duplicate parameter 'scale'", "test.xml:3"});
}

TEST(XmlLoader, UnknownParameterIsAnError) {
  expectContains(errorOf(probe("<float name=\"scale\" value=\"1\"/>\n<float name=\"sclae\" value=\"2\"/>")),
                 {"test.xml:4", "unknown parameter 'sclae' for <bsdf> 'probe'"});
}

TEST(XmlLoader, UnreadNestedPluginIsAnError) {
  expectContains(errorOf(R"(<scene version="3.0.0">
<emitter type="area">
  <bsdf type="diffuse"/>
</emitter>
</scene>)"),
                 {"test.xml:3", "unexpected nested <bsdf> 'diffuse'", "<emitter> 'area'"});
}

TEST(XmlLoader, UnexpectedAttributeAndElementAreErrors) {
  expectContains(errorOf(probe(R"(<float name="scale" valeu="1"/>)")), {"test.xml:3", "'valeu'"});
  expectContains(errorOf(probe(R"(<colour name="scale" value="1"/>)")), {"test.xml:3", "<colour>"});
}

TEST(XmlLoader, GetPathResolvesAgainstBaseDirAndReportsMissingFiles) {
  auto p = only(load(probe(R"(<string name="file" value="data/sample.spd"/>)")));
  EXPECT_TRUE(std::filesystem::equivalent(p->strings.at("file"), dataDir() + "/data/sample.spd"));
  expectContains(errorOf(probe("\n<string name=\"file\" value=\"data/missing.spd\"/>")),
                 {"test.xml:4", "'file'", "data/missing.spd"});
}

namespace {

// A main scene file that includes parts/part.xml, whose probe names the file `x.txt`.
class FileLookup : public columba::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    for (const char* sub : {"parts/assets", "extra", "later"}) std::filesystem::create_directories(dir_ / sub);
    write("main.xml",
          "<scene version=\"3.0.0\">\n"
          "  <path value=\"extra\"/>\n"
          "  <path value=\"later\"/>\n"
          "  <include filename=\"parts/part.xml\"/>\n"
          "</scene>\n");
    write("parts/part.xml",
          "<scene version=\"3.0.0\">\n"
          "  <path value=\"assets\"/>\n"
          "  <bsdf type=\"probe\"><string name=\"file\" value=\"x.txt\"/></bsdf>\n"
          "</scene>\n");
  }
  // The file the probe's `x.txt` leads to, relative to the test's directory.
  std::string found() {
    ParsedScene scene = loadSceneFile((dir_ / "main.xml").string(), {}, testRegistry());
    auto probe = std::dynamic_pointer_cast<TestObject>(scene.objects.at(0));
    return std::filesystem::relative(probe->strings.at("file"), dir_).string();
  }
  std::string loadError() {
    try {
      loadSceneFile((dir_ / "main.xml").string(), {}, testRegistry());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

}  // namespace

// The including file's directory, the main file's, the <path>s (the latest declared first, each
// relative to the file declaring it), then the working directory.
TEST_F(FileLookup, RelativeNamesAreLookedForInMitsubasOrder) {
  for (const char* where : {"parts/x.txt", "x.txt", "parts/assets/x.txt", "later/x.txt", "extra/x.txt"})
    write(where, "");
  EXPECT_EQ(found(), "parts/x.txt");
  std::filesystem::remove(dir_ / "parts/x.txt");
  EXPECT_EQ(found(), "x.txt");
  std::filesystem::remove(dir_ / "x.txt");
  EXPECT_EQ(found(), "parts/assets/x.txt");
  std::filesystem::remove(dir_ / "parts/assets/x.txt");
  EXPECT_EQ(found(), "later/x.txt");
  std::filesystem::remove(dir_ / "later/x.txt");
  EXPECT_EQ(found(), "extra/x.txt");
  std::filesystem::remove(dir_ / "extra/x.txt");
  const std::string d = dir_.string();
  const std::string looked = "(looked for '" + d + "/parts/x.txt', '" + d + "/x.txt', '" + d +
                             "/parts/assets/x.txt', '" + d + "/later/x.txt', '" + d + "/extra/x.txt' and 'x.txt')";
  expectContains(loadError(), {"part.xml:3", "'file'", looked.c_str()});
}

TEST_F(FileLookup, IncludesAreFoundThroughPaths) {
  write("extra/common.xml", "<scene version=\"3.0.0\">\n  <bsdf type=\"diffuse\" id=\"common\"/>\n</scene>\n");
  write("main.xml",
        "<scene version=\"3.0.0\">\n  <path value=\"extra\"/>\n  <include filename=\"common.xml\"/>\n"
        "  <shape type=\"mesh\"><ref id=\"common\"/></shape>\n</scene>\n");
  ParsedScene scene = loadSceneFile((dir_ / "main.xml").string(), {}, testRegistry());
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(std::dynamic_pointer_cast<TestObject>(scene.objects[1])->children.at(0), scene.objects[0]);
}

TEST_F(FileLookup, BadPathsNameFileLineAndValue) {
  write("main.xml", "<scene version=\"3.0.0\">\n\n  <path value=\"nowhere\"/>\n</scene>\n");
  expectContains(loadError(), {"main.xml:3", "<path> 'nowhere'", "not found"});
  write("main.xml",
        "<scene version=\"3.0.0\">\n  <bsdf type=\"probe\">\n    <path value=\"extra\"/>\n  </bsdf>\n</scene>\n");
  expectContains(loadError(), {"main.xml:3", "<path>", "only allowed directly inside <scene>"});
  write("main.xml", "<scene version=\"3.0.0\">\n  <path valeu=\"extra\"/>\n</scene>\n");
  expectContains(loadError(), {"main.xml:2", "'valeu'"});
}

TEST(XmlLoader, ReferencesShareTheObject) {
  auto scene = load(R"(<scene version="3.0.0">
<bsdf type="diffuse" id="white"/>
<shape type="mesh"><ref id="white"/></shape>
<shape type="mesh"><ref name="bsdf" id="white"/></shape>
</scene>)");
  ASSERT_EQ(scene.objects.size(), 3u);
  for (int i : {1, 2}) {
    auto shape = std::dynamic_pointer_cast<TestObject>(scene.objects[i]);
    ASSERT_EQ(shape->children.size(), 1u);
    EXPECT_EQ(shape->children[0], scene.objects[0]);
  }
  expectContains(errorOf(R"(<scene version="3.0.0">
<shape type="mesh">
  <ref id="nothing"/>
</shape>
</scene>)"),
                 {"test.xml:3", "'nothing'"});
  expectContains(errorOf(R"(<scene version="3.0.0">
<bsdf type="diffuse" id="a"/>
<bsdf type="diffuse" id="a"/>
</scene>)"),
                 {"test.xml:3", "duplicate id 'a'", "test.xml:2"});
}

TEST(XmlLoader, ReferencesMayComeBeforeTheirIds) {
  // As in Mitsuba: the id is declared further on, at the top level or nested in another plug-in;
  // the plug-in is built when first needed, once.
  auto scene = load(R"(<scene version="3.0.0">
<shape type="mesh"><ref id="later"/><ref id="inner"/></shape>
<bsdf type="diffuse" id="later"/>
<shape type="mesh"><bsdf type="twosided" id="inner"/></shape>
</scene>)");
  EXPECT_EQ(creationLog,
            (std::vector<std::string>{"bsdf:diffuse#later", "bsdf:twosided#inner", "shape:mesh", "shape:mesh"}));
  ASSERT_EQ(scene.objects.size(), 3u);
  auto first = std::dynamic_pointer_cast<TestObject>(scene.objects[0]);
  auto second = std::dynamic_pointer_cast<TestObject>(scene.objects[2]);
  ASSERT_EQ(first->children.size(), 2u);
  EXPECT_EQ(first->children[0], scene.objects[1]);
  ASSERT_EQ(second->children.size(), 1u);
  EXPECT_EQ(first->children[1], second->children[0]);
}

TEST(XmlLoader, ReferenceCyclesAreErrors) {
  expectContains(errorOf(R"(<scene version="3.0.0">
<bsdf type="twosided" id="a"><ref id="b"/></bsdf>
<bsdf type="twosided" id="b">
  <ref id="a"/>
</bsdf>
</scene>)"),
                 {"test.xml:4", "<ref> to 'a' closes a cycle", "test.xml:2"});
  expectContains(errorOf(R"(<scene version="3.0.0">
<bsdf type="twosided" id="self">
  <bsdf type="twosided"><ref id="self"/></bsdf>
</bsdf>
</scene>)"),
                 {"test.xml:3", "<ref> to 'self' closes a cycle"});
}

TEST(XmlLoader, TheFirstDefaultOfANameHolds) {
  const std::string xml = R"(<scene version="3.0.0">
<default name="spp" value="4"/>
<default name="spp" value="8"/>
<integrator type="path"><integer name="spp" value="$spp"/></integrator>
</scene>)";
  EXPECT_EQ(only(load(xml))->ints.at("spp"), 4);
  EXPECT_EQ(only(load(xml, {{"spp", "16"}}))->ints.at("spp"), 16);
}

TEST(XmlLoader, TopLevelFilmsSamplersAndFiltersAreThereToBeReferenced) {
  ::testing::internal::CaptureStderr();
  auto scene = load(R"(<scene version="3.0.0">
<sampler type="ldsampler" id="sampler"><integer name="sample_count" value="4"/></sampler>
<rfilter type="gaussian"/>
<film type="hdrfilm" id="film"><ref id="filter"/></film>
<rfilter type="gaussian" id="filter"/>
<sensor type="perspective"><ref id="film"/><ref id="sampler"/></sensor>
</scene>)");
  std::string warnings = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(scene.objects.size(), 1u);
  auto sensor = std::dynamic_pointer_cast<TestObject>(scene.objects[0]);
  EXPECT_EQ(sensor->tag, "sensor");
  ASSERT_EQ(sensor->children.size(), 2u);
  EXPECT_EQ(sensor->children[0]->tag, "film");
  EXPECT_EQ(sensor->children[1]->tag, "sampler");
  // The unnamed filter can never be used.
  expectContains(warnings, {"test.xml:3", "<rfilter> without an id is never used"});
}

TEST(XmlLoader, NestedPluginsComeFirstAndInDocumentOrder) {
  auto scene = load(R"(<scene version="3.0.0">
<shape type="mesh">
  <bsdf type="twosided"><bsdf type="diffuse" id="inner"/></bsdf>
  <emitter type="area"/>
</shape>
<integrator type="path"/>
<shape type="mesh"><ref id="inner"/></shape>
</scene>)");
  EXPECT_EQ(creationLog, (std::vector<std::string>{"bsdf:diffuse#inner", "bsdf:twosided", "emitter:area", "shape:mesh",
                                                   "integrator:path", "shape:mesh"}));
  ASSERT_EQ(scene.objects.size(), 3u);
  auto shape = std::dynamic_pointer_cast<TestObject>(scene.objects[0]);
  ASSERT_EQ(shape->children.size(), 2u);
  EXPECT_EQ(shape->children[0]->type, "twosided");
  EXPECT_EQ(shape->children[1]->type, "area");
  EXPECT_EQ(std::dynamic_pointer_cast<TestObject>(scene.objects[1])->type, "path");
  auto inner = shape->children[0]->children.at(0);
  EXPECT_EQ(std::dynamic_pointer_cast<TestObject>(scene.objects[2])->children.at(0), inner);
}

TEST(XmlLoader, SpectrumForms) {
  auto p = only(load(probe(R"(<spectrum name="color" value="400:0.2, 500:0.6 600:0.4"/>
<spectrum name="glow" value="30"/>)")));
  // A single value for an emitter is D65 of that luminance (Mitsuba's convention).
  EXPECT_FLOAT_EQ(p->spectra.at("glow").eval(555.0f), 30.0f * d65(555.0f));
  const SpectralDistribution& color = p->spectra.at("color");
  EXPECT_NEAR(color.eval(450.0f), 0.4f, 1e-6f);
  EXPECT_NEAR(color.eval(575.0f), 0.45f, 1e-6f);
  EXPECT_NEAR(color.eval(380.0f), 0.2f, 1e-6f);

  auto q = only(load(probe(R"(<float name="color" value="0.25"/>
<spectrum name="glow" filename="data/sample.spd"/>)")));
  EXPECT_FLOAT_EQ(q->spectra.at("color").eval(500.0f), 0.25f);
  // The file's two lines: 249.7909 0.0300 and 253.6204 0.0284.
  const SpectralDistribution& melanin = q->spectra.at("glow");
  EXPECT_NEAR(melanin.eval(249.7909f), 0.0300f, 1e-6f);
  EXPECT_NEAR(melanin.eval(0.5f * (249.7909f + 253.6204f)), 0.0292f, 1e-5f);

  expectContains(errorOf(probe("\n<spectrum name=\"color\" value=\"500:0.2, 400:0.3\"/>")), {"test.xml:4", "increase"});
  expectContains(errorOf(probe("\n<spectrum name=\"color\" value=\"400:0.2, 500:x\"/>")), {"test.xml:4", "'x'"});
}

TEST(XmlLoader, RGBIsClampedOnlyForReflectance) {
  auto p = only(load(probe(R"(<rgb name="color" value="2, 2, 2"/>
<rgb name="glow" value="2"/>)")));
  EXPECT_FLOAT_EQ(p->spectra.at("color").eval(550.0f), 1.0f);
  EXPECT_FLOAT_EQ(p->spectra.at("glow").eval(550.0f), 2.0f * d65(550.0f));
  auto q = only(load(probe(R"(<rgb name="color" value="0.9, 0.1, 0.1"/>)")));
  EXPECT_GT(q->spectra.at("color").eval(650.0f), 0.5f);
  EXPECT_LT(q->spectra.at("color").eval(450.0f), 0.2f);
}

TEST(XmlLoader, TransformOperationsComposeInOrder) {
  auto p = only(load(probe(R"(<transform name="to_world">
  <translate x="1" y="2" z="3"/>
  <rotate z="1" angle="90"/>
  <scale value="2"/>
</transform>)")));
  // p -> translate: (x+1, y+2, z+3) -> rotate z 90: (-(y+2), x+1, z+3) -> scale 2.
  const double expected[4][4] = {{0, -2, 0, -4}, {2, 0, 0, 2}, {0, 0, 2, 6}, {0, 0, 0, 1}};
  expectMatrixNear(p->transforms.at("to_world").matrix(), expected);
}

TEST(XmlLoader, TransformOperandForms) {
  auto p = only(load(probe(R"(<transform name="to_world">
  <scale y="3"/>
  <translate value="1 2, 3"/>
  <rotate value="1, 0, 0" angle="180"/>
</transform>)")));
  const double expected[4][4] = {{1, 0, 0, 1}, {0, -3, 0, -2}, {0, 0, -1, -3}, {0, 0, 0, 1}};
  expectMatrixNear(p->transforms.at("to_world").matrix(), expected);
}

TEST(XmlLoader, RotateAxisThatIsNotUnitLengthIsKeptAndWarnedAbout) {
  ::testing::internal::CaptureStderr();
  auto p = only(load(probe(R"(<transform name="to_world">
  <rotate x="1" y="1" angle="90"/>
</transform>)")));
  std::string warnings = ::testing::internal::GetCapturedStderr();
  // Mitsuba's matrix for k = (1, 1, 0), 90 degrees: [[1, 1, 1], [1, 1, -1], [-1, 1, 0]].
  const double expected[4][4] = {{1, 1, 1, 0}, {1, 1, -1, 0}, {-1, 1, 0, 0}, {0, 0, 0, 1}};
  expectMatrixNear(p->transforms.at("to_world").matrix(), expected);
  expectContains(warnings, {"warning", "test.xml:4", "<rotate>", "length 1.41421"});
  // A unit axis is silent; a zero axis is an error naming the line.
  ::testing::internal::CaptureStderr();
  load(probe(R"(<transform name="to_world"><rotate z="1" angle="30"/></transform>)"));
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  expectContains(errorOf(probe("\n<transform name=\"to_world\"><rotate angle=\"30\"/></transform>")),
                 {"test.xml:4", "non-zero axis"});
}

TEST(XmlLoader, LookAtFollowedByTranslate) {
  auto p = only(load(probe(R"(<transform name="to_world">
  <lookat origin="3, 0, 4" target="0 0 0" up="0, 1, 0"/>
  <translate z="1"/>
</transform>)")));
  // dir = (-0.6, 0, -0.8), left = up x dir = (-0.8, 0, 0.6), up' = dir x left = (0, 1, 0).
  const double expected[4][4] = {{-0.8, 0, -0.6, 3}, {0, 1, 0, 0}, {0.6, 0, -0.8, 5}, {0, 0, 0, 1}};
  expectMatrixNear(p->transforms.at("to_world").matrix(), expected);
}

TEST(XmlLoader, LookAtWithoutUpTakesTheFrameOfTheViewDirection) {
  // As Mitsuba 3: up is the first axis of the Duff et al. (2017) frame around the direction. For
  // d = (1, 0, 0): sign = 1, a = -1 / (1 + 0) = -1, b = 0, so up = (1 + d.x^2 a, b, -d.x) = (0, 0, -1);
  // left = up x d = (0, -1, 0), up' = d x left = (0, 0, -1).
  const double alongX[4][4] = {{0, 0, 1, 1}, {-1, 0, 0, 2}, {0, -1, 0, 3}, {0, 0, 0, 1}};
  for (const char* up : {"", " up=\"0, 0, 0\""}) {
    auto p = only(load(probe(std::string(R"(<transform name="to_world"><lookat origin="1, 2, 3" target="4, 2, 3")") +
                             up + "/></transform>")));
    expectMatrixNear(p->transforms.at("to_world").matrix(), alongX);
  }
  // d = (0, 0, 1): a = -1/2, b = 0, up = (1, 0, 0); left = (0, -1, 0), up' = (1, 0, 0).
  auto p = only(load(probe(R"(<transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 2"/></transform>)")));
  const double alongZ[4][4] = {{0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  expectMatrixNear(p->transforms.at("to_world").matrix(), alongZ);
  expectContains(
      errorOf(probe("<transform name=\"to_world\">\n<lookat origin=\"1, 1, 1\" target=\"1, 1, 1\"/>\n</transform>")),
      {"test.xml:4", "origin equals target"});
}

TEST(XmlLoader, MatrixElement) {
  auto p = only(load(probe(R"(<transform name="to_world">
  <matrix value="1 2 0 4  0 1 0 5  0 0 2 6  0 0 0 1"/>
  <matrix value="0 -1 0  1 0 0  0 0 1"/>
</transform>)")));
  const double expected[4][4] = {{0, -1, 0, -5}, {1, 2, 0, 4}, {0, 0, 2, 6}, {0, 0, 0, 1}};
  expectMatrixNear(p->transforms.at("to_world").matrix(), expected);
  expectContains(errorOf(probe("<transform name=\"to_world\">\n<matrix value=\"1 2 3\"/>\n</transform>")),
                 {"test.xml:4", "16"});
  expectContains(errorOf(probe("<transform name=\"to_world\">\n<scale x=\"0\"/>\n</transform>")),
                 {"test.xml:4", "<scale>"});
}

TEST(XmlLoader, MalformedXmlReportsLine) {
  expectContains(errorOf("<scene version=\"3.0.0\">\n<bsdf type=\"diffuse\">\n</shape>\n</scene>"),
                 {"test.xml:3", "malformed XML"});
  expectContains(errorOf("<scene>\n</scene>"), {"test.xml:1", "'version'"});
  expectContains(errorOf("<scene version=\"3.0.0\">\n<float name=\"x\" value=\"1\"/>\n</scene>"),
                 {"test.xml:2", "<float>"});
}

TEST(XmlLoader, MissingSceneFileNamesThePath) {
  try {
    loadSceneFile("/nonexistent/dir/scene.xml", {}, testRegistry());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.xml"), std::string::npos) << e.what();
  }
}

TEST(XmlLoader, IncludeReadsAnotherFileInPlace) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("columba_xml_include_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "part.xml") << "<scene version=\"3.0.0\">\n"
                                             "  <bsdf type=\"diffuse\" id=\"shared\"/>\n"
                                             "  <bsdf type=\"nonsense\"/>\n"
                                             "</scene>\n";
  std::ofstream(dir / "main.xml") << "<scene version=\"3.0.0\">\n"
                                     "  <include filename=\"sub/part.xml\"/>\n"
                                     "</scene>\n";
  try {
    loadSceneFile((dir / "main.xml").string(), {}, testRegistry());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    expectContains(e.what(), {"part.xml:3", "'nonsense'"});
  }
  std::ofstream(dir / "sub" / "part.xml") << "<scene version=\"3.0.0\">\n"
                                             "  <bsdf type=\"diffuse\" id=\"shared\"/>\n"
                                             "</scene>\n";
  std::ofstream(dir / "main.xml") << "<scene version=\"3.0.0\">\n"
                                     "  <include filename=\"sub/part.xml\"/>\n"
                                     "  <shape type=\"mesh\"><ref id=\"shared\"/></shape>\n"
                                     "</scene>\n";
  ParsedScene scene = loadSceneFile((dir / "main.xml").string(), {}, testRegistry());
  fs::remove_all(dir);
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(std::dynamic_pointer_cast<TestObject>(scene.objects[1])->children.at(0), scene.objects[0]);
}

namespace {

// The paper's own scene files, kept beside the repository (COLUMBA_SHARED_DIR) and not part of it.
const std::string kReferenceScenes = std::string(COLUMBA_SHARED_DIR) + "/reference/scenes/";

// Why the reference scene tests cannot run here ("" when they can).
std::string referenceScenesMissing() {
  if (std::filesystem::is_directory(kReferenceScenes)) return "";
  return "the reference scene files are not available (looked in " + kReferenceScenes + ")";
}

#define SKIP_WITHOUT_REFERENCE_SCENES()                                                         \
  do {                                                                                          \
    if (std::string reason = referenceScenesMissing(); !reason.empty()) GTEST_SKIP() << reason; \
  } while (false)

ParsedScene loadReference(const std::string& name, const Defines& defines = {}) {
  return loadSceneFile(kReferenceScenes + name, defines, testRegistry());
}

std::shared_ptr<TestObject> object(const ParsedScene& scene, size_t i) {
  return std::dynamic_pointer_cast<TestObject>(scene.objects.at(i));
}

}  // namespace

TEST(XmlLoader, ReferenceSceneNeck) {
  SKIP_WITHOUT_REFERENCE_SCENES();
  ParsedScene scene = loadReference("neck.xml", {{"spp", "8"}});
  ASSERT_EQ(scene.objects.size(), 6u);
  const char* types[] = {"path", "perspective", "barbulebsdf", "feather", "constant", "rectangle"};
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(object(scene, i)->type, types[i]);

  auto sensor = object(scene, 1);
  ASSERT_EQ(sensor->children.size(), 2u);
  auto film = sensor->children[0];
  EXPECT_EQ(film->ints.at("width"), 1024);
  EXPECT_EQ(film->ints.at("height"), 768);
  ASSERT_EQ(film->children.size(), 1u);
  EXPECT_EQ(film->children[0]->type, "gaussian");
  EXPECT_EQ(sensor->children[1]->ints.at("sample_count"), 8);
  Vec3 eye = sensor->transforms.at("to_world").point(Vec3(0, 0, 0));
  EXPECT_NEAR(eye.z, 0.61f, 1e-6f);

  auto feather = object(scene, 3);
  EXPECT_EQ(feather->children.at(0), scene.objects[2]);
  EXPECT_FLOAT_EQ(feather->floats.at("barbwidth"), 0.015f);
  // scale 0.1, then translate x by 0.08.
  Vec3 p = feather->transforms.at("to_world").point(Vec3(1, 1, 1));
  EXPECT_NEAR(p.x, 0.18f, 1e-6f);
  EXPECT_NEAR(p.y, 0.1f, 1e-6f);

  auto light = object(scene, 5);
  ASSERT_EQ(light->children.size(), 2u);
  EXPECT_NEAR(light->children[0]->spectra.at("reflectance").eval(650.0f), 0.78f, 1e-6f);
  EXPECT_FLOAT_EQ(light->children[1]->spectra.at("radiance").eval(650.0f), 10.0f * d65(650.0f));
  // scale (0.5, 0.05, 0.5), rotate 180 degrees about y, translate z by 1.
  Vec3 corner = light->transforms.at("to_world").point(Vec3(1, 1, 0));
  EXPECT_NEAR(corner.x, -0.5f, 1e-6f);
  EXPECT_NEAR(corner.y, 0.05f, 1e-6f);
  EXPECT_NEAR(corner.z, 1.0f, 1e-6f);
}

TEST(XmlLoader, ReferenceSceneSimulation1) {
  SKIP_WITHOUT_REFERENCE_SCENES();
  ParsedScene scene = loadReference("simulation1.xml");
  ASSERT_EQ(scene.objects.size(), 4u);
  auto integrator = object(scene, 0);
  EXPECT_EQ(integrator->ints.at("samples_per_pass"), 64);
  EXPECT_EQ(integrator->ints.at("bsdf_samples"), 0);
  EXPECT_EQ(object(scene, 1)->children.at(0)->ints.at("width"), 720);
  auto surface = object(scene, 2);
  ASSERT_EQ(surface->children.size(), 1u);
  auto bsdf = surface->children[0];
  EXPECT_EQ(bsdf->type, "barbulebsdfev");
  EXPECT_FLOAT_EQ(bsdf->floats.at("phi_1"), 2.64f);
  EXPECT_EQ(bsdf->strings.at("film_ior"), "keratin");
  auto disk = object(scene, 3);
  EXPECT_EQ(disk->children.at(0)->type, "area");
  Vec3 centre = disk->transforms.at("to_world").point(Vec3(0, 0, 0));
  EXPECT_NEAR(centre.x, 0.3f, 1e-6f);
  EXPECT_NEAR(centre.y, -0.3f, 1e-6f);
  EXPECT_NEAR(centre.z, 1.0f, 1e-6f);
}

TEST(XmlLoader, EveryReferenceSceneLoads) {
  SKIP_WITHOUT_REFERENCE_SCENES();
  for (const char* name : {"simulation2.xml", "simulation3.xml"})
    EXPECT_EQ(loadReference(name).objects.size(), 4u) << name;
  for (const char* o : {"-1", "00", "06"}) {
    ParsedScene la = loadReference("la.xml", {{"o", o}});
    ASSERT_EQ(la.objects.size(), 6u);
    std::string mesh = object(la, 0)->strings.at("filename");
    EXPECT_NE(mesh.find(std::string("meshes/la") + o + "0.obj"), std::string::npos) << mesh;
  }
  expectContains(
      [] {
        try {
          loadReference("la.xml");
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"la.xml:7", "$o0"});
}
