#include <gtest/gtest.h>

#include <unistd.h>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "io/feather_ply.h"

using namespace columba;

namespace {

// Two straight barbs; vertex i of barb b at (i * 0.01, b * 0.1, 0) with H = i + 1, mu = -0.35,
// height = 0.6 and normal +z.
struct Vertex {
  float x, y, z, H, mu, height, nx, ny, nz;
};

std::vector<Vertex> twoBarbs() {
  std::vector<Vertex> v;
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < kBarbVertices; ++i)
      v.push_back({i * 0.01f, b * 0.1f, 0.0f, float(i + 1), -0.35f, 0.6f, 0, 0, 2});
  return v;
}

class FeatherPlyTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("columba_ply_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
  }
  void TearDown() override {
    std::filesystem::remove_all(std::filesystem::temp_directory_path() /
                                ("columba_ply_test_" + std::to_string(getpid())));
  }

  // ASCII file: header (7 + vertex property lines), then one line per vertex and per face.
  std::string writeAscii(const std::string& name, const std::vector<Vertex>& v, size_t declaredVertices,
                         const std::string& normalNames = "out1 out2 out3", int facesIndices = kBarbVertices,
                         const std::string& listType = "uchar int") {
    std::ostringstream s;
    s.precision(9);
    std::istringstream names(normalNames);
    std::string n1, n2, n3;
    names >> n1 >> n2 >> n3;
    s << "ply\nformat ascii 1.0\ncomment test\nelement vertex " << declaredVertices << "\n"
      << "property float x\nproperty float y\nproperty float z\nproperty float H\nproperty float mu\n"
      << "property float height\nproperty float " << n1 << "\nproperty float " << n2 << "\nproperty float " << n3
      << "\nelement face " << v.size() / kBarbVertices << "\nproperty list " << listType
      << " vertex_indices\nend_header\n";
    for (const Vertex& x : v)
      s << x.x << " " << x.y << " " << x.z << " " << x.H << " " << x.mu << " " << x.height << " " << x.nx << " " << x.ny
        << " " << x.nz << "\n";
    for (size_t f = 0; f < v.size() / kBarbVertices; ++f) {
      s << facesIndices;
      for (int i = 0; i < facesIndices; ++i) s << " " << f * kBarbVertices + size_t(i);
      s << "\n";
    }
    std::string p = path(name);
    std::ofstream(p) << s.str();
    return p;
  }
  static constexpr int kHeaderLines = 16;  // of writeAscii

  std::string writeBinary(const std::string& name, const std::vector<Vertex>& v, size_t truncateBytes = 0) {
    std::ostringstream s;
    s << "ply\nformat binary_little_endian 1.0\nelement vertex " << v.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty float H\n"
      << "property double mu\nproperty float height\nproperty float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << v.size() / kBarbVertices << "\nproperty list uint8 uint32 vertex_indices\n"
      << "element edge 1\nproperty int a\nend_header\n";
    auto put = [&](const auto& value) { s.write(reinterpret_cast<const char*>(&value), sizeof(value)); };
    for (const Vertex& x : v) {
      put(x.x);
      put(x.y);
      put(x.z);
      put(uint8_t(200));
      put(x.H);
      put(double(x.mu));
      put(x.height);
      put(x.nx);
      put(x.ny);
      put(x.nz);
    }
    for (size_t f = 0; f < v.size() / kBarbVertices; ++f) {
      put(uint8_t(kBarbVertices));
      for (int i = 0; i < kBarbVertices; ++i) put(uint32_t(f * kBarbVertices + size_t(i)));
    }
    put(int32_t(7));
    std::string bytes = s.str();
    bytes.resize(bytes.size() - truncateBytes);
    std::string p = path(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

  // The InputError message of reading `file`, or "" if it loaded.
  static std::string errorOf(const std::string& file) {
    try {
      readFeatherPly(file);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

}  // namespace

TEST_F(FeatherPlyTest, ReadsAsciiWithPerVertexParameters) {
  FeatherPlyData d = readFeatherPly(writeAscii("a.ply", twoBarbs(), 128));
  ASSERT_EQ(d.positions.size(), 128u);
  ASSERT_EQ(d.barbCount(), 2u);
  EXPECT_TRUE(d.barbsAreSequential());
  EXPECT_FLOAT_EQ(d.positions[64 + 3].x, 0.03f);
  EXPECT_FLOAT_EQ(d.positions[64 + 3].y, 0.1f);
  EXPECT_FLOAT_EQ(d.normals[5].z, 1.0f);  // normalised
  ASSERT_EQ(d.barbuleH.size(), 128u);
  EXPECT_FLOAT_EQ(d.barbuleH[70], 7.0f);
  EXPECT_FLOAT_EQ(d.barbuleMu[70], -0.35f);
  EXPECT_FLOAT_EQ(d.barbuleHeight[70], 0.6f);
  EXPECT_EQ(d.firstFaceLine, kHeaderLines + 128 + 1);
}

TEST_F(FeatherPlyTest, BinaryWithOtherTypesAndExtraDataMatchesAscii) {
  FeatherPlyData a = readFeatherPly(writeAscii("a.ply", twoBarbs(), 128));
  FeatherPlyData b = readFeatherPly(writeBinary("b.ply", twoBarbs()));
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_EQ(a.positions[i], b.positions[i]);
    EXPECT_EQ(a.normals[i], b.normals[i]);
    EXPECT_EQ(a.barbuleH[i], b.barbuleH[i]);
    EXPECT_FLOAT_EQ(a.barbuleMu[i], b.barbuleMu[i]);
  }
  EXPECT_EQ(a.barbIndices, b.barbIndices);
}

TEST_F(FeatherPlyTest, AcceptsNxNyNzAndOtherIndexTypes) {
  FeatherPlyData d = readFeatherPly(writeAscii("n.ply", twoBarbs(), 128, "nx ny nz", kBarbVertices, "uint8 int32"));
  EXPECT_EQ(d.barbCount(), 2u);
  EXPECT_FLOAT_EQ(d.normals[0].z, 1.0f);
}

TEST_F(FeatherPlyTest, ReportsAWrongIndexCountAtItsLine) {
  std::string f = writeAscii("count.ply", twoBarbs(), 128, "out1 out2 out3", 63);
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":" + std::to_string(kHeaderLines + 128 + 1)), std::string::npos) << err;
  EXPECT_NE(err.find("63 vertex indices"), std::string::npos) << err;
}

TEST_F(FeatherPlyTest, ReportsAnIndexOutOfRange) {
  std::string f = writeAscii("range.ply", twoBarbs(), 128);
  std::string text;
  {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  text.replace(text.rfind(" 127\n"), 5, " 128\n");
  std::ofstream(f) << text;
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":" + std::to_string(kHeaderLines + 128 + 2)), std::string::npos) << err;
  EXPECT_NE(err.find("out of range"), std::string::npos) << err;
}

TEST_F(FeatherPlyTest, ReportsNonFiniteValues) {
  for (const char* bad : {"nan", "inf", "1e39"}) {
    std::vector<Vertex> v = twoBarbs();
    std::string f = writeAscii("nan.ply", v, 128);
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    in.close();
    std::string text = ss.str();
    // Line of vertex 10: replace its y.
    size_t pos = 0;
    for (int l = 0; l < kHeaderLines + 10; ++l) pos = text.find('\n', pos) + 1;
    size_t y = text.find(' ', pos) + 1;
    text.replace(y, text.find(' ', y) - y, bad);
    std::ofstream(f) << text;
    std::string err = errorOf(f);
    EXPECT_NE(err.find(f + ":" + std::to_string(kHeaderLines + 11)), std::string::npos) << bad << ": " << err;
    EXPECT_NE(err.find("'y'"), std::string::npos) << err;
  }
}

TEST_F(FeatherPlyTest, ReportsMissingPropertiesAtTheElementLine) {
  std::string f = writeAscii("nonormal.ply", twoBarbs(), 128, "a b c");
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":4"), std::string::npos) << err;
  EXPECT_NE(err.find("normal"), std::string::npos) << err;

  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 0\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\nelement face 0\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string g = path("nox.ply");
  std::ofstream(g) << text;
  err = errorOf(g);
  EXPECT_NE(err.find(g + ":3"), std::string::npos) << err;
  EXPECT_NE(err.find("'x'"), std::string::npos) << err;
}

TEST_F(FeatherPlyTest, ReportsFewerVertexLinesThanDeclared) {
  std::string f = writeAscii("fewer.ply", twoBarbs(), 129);
  std::string err = errorOf(f);
  // Vertex 128 is read from the first face line, which has too many values.
  EXPECT_NE(err.find(f + ":" + std::to_string(kHeaderLines + 129)), std::string::npos) << err;
  EXPECT_NE(err.find("vertex 128"), std::string::npos) << err;
}

TEST_F(FeatherPlyTest, ReportsTruncatedFiles) {
  std::vector<Vertex> v = twoBarbs();
  std::string f = writeAscii("cut.ply", v, 128);
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  in.close();
  std::string text = ss.str();
  text.resize(text.rfind('\n', text.size() - 2) + 1);  // drop the last face line
  std::ofstream(f) << text;
  std::string err = errorOf(f);
  EXPECT_NE(err.find("ends after 1 of the 2 face"), std::string::npos) << err;
  EXPECT_NE(err.find(f + ":" + std::to_string(kHeaderLines + 128 + 2)), std::string::npos) << err;

  std::string b = writeBinary("cut.bin.ply", v, 4 + 100);
  err = errorOf(b);
  EXPECT_NE(err.find("face 1"), std::string::npos) << err;
  EXPECT_NE(err.find("truncated"), std::string::npos) << err;
}

TEST_F(FeatherPlyTest, RejectsOtherFormatsAndMissingFiles) {
  std::string f = path("be.ply");
  std::ofstream(f) << "ply\nformat binary_big_endian 1.0\nend_header\n";
  EXPECT_NE(errorOf(f).find(f + ":2"), std::string::npos) << errorOf(f);
  EXPECT_NE(errorOf(path("missing.ply")).find("cannot open"), std::string::npos);
}

TEST_F(FeatherPlyTest, ReportsBarbuleValuesOutOfRangeWithTheirLineOrIndex) {
  struct Case {
    const char* name;
    float Vertex::*field;
    float value;
    const char* says;
  };
  for (const Case& c : {Case{"zeroH.ply", &Vertex::H, 0.0f, "H is 0"}, Case{"negH.ply", &Vertex::H, -0.5f, "H is -0.5"},
                        Case{"negHeight.ply", &Vertex::height, -0.25f, "height is -0.25"}}) {
    std::vector<Vertex> v = twoBarbs();
    v[70].*c.field = c.value;
    std::string f = writeAscii(c.name, v, 128);
    std::string err = errorOf(f);
    EXPECT_NE(err.find(f + ":" + std::to_string(kHeaderLines + 71)), std::string::npos) << err;
    EXPECT_NE(err.find(c.says), std::string::npos) << err;
    std::string b = writeBinary(std::string("bin") + c.name, v);
    err = errorOf(b);
    EXPECT_NE(err.find(b), std::string::npos) << err;
    EXPECT_NE(err.find("vertex 70"), std::string::npos) << err;
    EXPECT_NE(err.find(c.says), std::string::npos) << err;
  }
  // A zero thickness is valid (the BSDF's own applies).
  std::vector<Vertex> v = twoBarbs();
  v[3].height = 0.0f;
  EXPECT_EQ(errorOf(writeAscii("zeroHeight.ply", v, 128)), "");
}

TEST_F(FeatherPlyTest, UsesBarbuleValuesOnlyAllTogether) {
  // The original implementation reads H, mu and height only when all three are there.
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 64\nproperty float x\nproperty float y\n"
      "property float z\nproperty float H\nproperty float out1\nproperty float out2\n"
      "property float out3\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < kBarbVertices; ++i) text += std::to_string(0.01 * i) + " 0 0 0.7 0 0 1\n";
  text += "64";
  for (int i = 0; i < kBarbVertices; ++i) text += " " + std::to_string(i);
  text += "\n";
  std::string f = path("onlyH.ply");
  std::ofstream(f) << text;
  FeatherPlyData d = readFeatherPly(f);
  EXPECT_FALSE(d.hasBarbuleValues());
  EXPECT_TRUE(d.barbuleH.empty() && d.barbuleMu.empty() && d.barbuleHeight.empty());
  EXPECT_TRUE(readFeatherPly(writeAscii("all.ply", twoBarbs(), 128)).hasBarbuleValues());
}

TEST_F(FeatherPlyTest, ReadsTheRecordedBarbWidth) {
  std::string f = writeAscii("bw.ply", twoBarbs(), 128);
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  in.close();
  const std::string text = ss.str();
  EXPECT_FALSE(readFeatherPly(f).barbWidth.has_value());
  auto withComment = [&](const std::string& comment) {
    std::string t = text;
    t.replace(t.find("comment test\n"), 13, comment + "\n");
    std::ofstream(f) << t;
  };
  withComment("comment barbwidth 0.0125");
  FeatherPlyData d = readFeatherPly(f);
  ASSERT_TRUE(d.barbWidth.has_value());
  EXPECT_FLOAT_EQ(*d.barbWidth, 0.0125f);
  for (const char* bad :
       {"comment barbwidth", "comment barbwidth -1", "comment barbwidth 0.01cm", "comment barbwidth 0.01 0.02"}) {
    withComment(bad);
    std::string err = errorOf(f);
    EXPECT_NE(err.find(f + ":3"), std::string::npos) << bad << ": " << err;
    EXPECT_NE(err.find("barb width"), std::string::npos) << err;
  }
}

namespace {

// One barb whose vertices carry a layer stack of `type`, vertex i's value given by `stack`.
std::string oneBarbWithStacks(const std::string& type, const std::function<std::string(int)>& stack) {
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 64\nproperty float x\nproperty float y\nproperty float z\n"
      "property " +
      type +
      " stack\nproperty float out1\nproperty float out2\nproperty float out3\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < kBarbVertices; ++i) text += std::to_string(0.01 * i) + " 0 0 " + stack(i) + " 0 0 1\n";
  text += "64";
  for (int i = 0; i < kBarbVertices; ++i) text += " " + std::to_string(i);
  return text + "\n";
}
constexpr int kStackHeaderLines = 13;  // of oneBarbWithStacks

}  // namespace

TEST_F(FeatherPlyTest, ReadsPerVertexLayerStacksAndWhereTheLargestIsChosen) {
  const std::string f = path("stacks.ply");
  std::ofstream(f) << oneBarbWithStacks("uchar", [](int i) { return std::to_string(i == 40 || i == 50 ? 3 : i % 2); });
  FeatherPlyData d = readFeatherPly(f);
  ASSERT_EQ(d.layerStack.size(), 64u);
  EXPECT_EQ(d.layerStack[7], 1);
  EXPECT_EQ(d.layerStack[8], 0);
  EXPECT_EQ(d.layerStack[50], 3);
  EXPECT_EQ(d.largestLayerStack, 3);
  EXPECT_EQ(d.largestLayerStackVertex, 40u);
  EXPECT_EQ(d.largestLayerStackLine, kStackHeaderLines + 41);
  EXPECT_FALSE(d.hasBarbuleValues());  // a stack needs no H, mu and height
  // Files without the property choose none.
  FeatherPlyData plain = readFeatherPly(writeAscii("plain.ply", twoBarbs(), 128));
  EXPECT_TRUE(plain.layerStack.empty());
  EXPECT_EQ(plain.largestLayerStack, -1);
}

TEST_F(FeatherPlyTest, RefusesLayerStacksThatAreNotWholeNumbersFrom0To255) {
  const std::string f = path("badstack.ply");
  for (const auto& [type, value] :
       {std::pair<std::string, std::string>{"float", "1.5"}, {"float", "-1"}, {"int", "256"}, {"float", "nan"}}) {
    std::ofstream(f) << oneBarbWithStacks(type, [&](int i) { return i == 9 ? value : std::string("0"); });
    const std::string err = errorOf(f);
    EXPECT_NE(err.find(f + ":" + std::to_string(kStackHeaderLines + 10)), std::string::npos) << value << ": " << err;
    EXPECT_NE(err.find("stack"), std::string::npos) << err;
  }
}
