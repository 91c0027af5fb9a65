#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/ply_file.h"

using namespace columba;

namespace {

// Element `a` (2 records) has one property of every scalar type and a list; element `empty`
// has none; element `b` has one record.
const char* const kHeaderBody =
    "element a 2\nproperty char i8\nproperty uchar u8\nproperty short i16\nproperty ushort u16\n"
    "property int i32\nproperty uint u32\nproperty float f32\nproperty double f64\n"
    "property list uchar int items\nelement empty 0\nproperty float unused\nelement b 1\nproperty float "
    "w\nend_header\n";

class PlyFileTest : public ::testing::Test {
 protected:
  static std::filesystem::path dir() {
    return std::filesystem::temp_directory_path() / ("columba_ply_file_test_" + std::to_string(getpid()));
  }
  void TearDown() override { std::filesystem::remove_all(dir()); }
  static std::string write(const std::string& name, const std::string& content) {
    std::filesystem::create_directories(dir());
    std::string p = (dir() / name).string();
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }

  static std::string ascii() {
    return std::string("ply\nformat ascii 1.0\n") + kHeaderBody +
           "-128 255 -32768 65535 -2147483648 4294967295 0.5 1e-300 3 7 -8 9\n"
           "1 2 3 4 5 6 7 8 0\n"
           "2.25\n";
  }
  static std::string binary() {
    std::ostringstream s;
    s << "ply\nformat binary_little_endian 1.0\n" << kHeaderBody;
    auto put = [&](const auto& value) { s.write(reinterpret_cast<const char*>(&value), sizeof(value)); };
    put(int8_t(-128));
    put(uint8_t(255));
    put(int16_t(-32768));
    put(uint16_t(65535));
    put(int32_t(-2147483647 - 1));
    put(uint32_t(4294967295u));
    put(0.5f);
    put(1e-300);
    put(uint8_t(3));
    put(int32_t(7));
    put(int32_t(-8));
    put(int32_t(9));
    put(int8_t(1));
    put(uint8_t(2));
    put(int16_t(3));
    put(uint16_t(4));
    put(int32_t(5));
    put(uint32_t(6));
    put(7.0f);
    put(8.0);
    put(uint8_t(0));
    put(2.25f);
    return s.str();
  }
};

void expectRecords(PlyReader& ply) {
  ASSERT_EQ(ply.elements().size(), 3u);
  const PlyElement& a = ply.elements()[0];
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.count, 2u);
  EXPECT_EQ(a.line, 3);
  EXPECT_EQ(a.findScalar("f64"), 7);
  EXPECT_EQ(a.findScalar("items"), -1);  // a list
  EXPECT_EQ(a.properties[8].type, PlyType::Int32);
  EXPECT_EQ(a.properties[8].countType, PlyType::UInt8);
  EXPECT_FALSE(isIntegerType(a.properties[6].type));

  ply.next();
  EXPECT_EQ(&ply.element(), &a);
  EXPECT_EQ(ply.index(), 0u);
  const double expected[] = {-128, 255, -32768, 65535, -2147483648.0, 4294967295.0, 0.5, 1e-300};
  for (size_t k = 0; k < 8; ++k) EXPECT_EQ(ply.scalar(k), expected[k]) << a.properties[k].name;
  EXPECT_EQ(ply.list(8), (std::vector<double>{7, -8, 9}));
  ply.next();
  EXPECT_EQ(ply.index(), 1u);
  EXPECT_EQ(ply.scalar(7), 8.0);
  EXPECT_TRUE(ply.list(8).empty());
  ply.next();  // past the empty element
  EXPECT_EQ(ply.element().name, "b");
  EXPECT_EQ(ply.scalar(0), 2.25);
  ply.finish();
  EXPECT_THROW(ply.next(), std::logic_error);
}

}  // namespace

TEST_F(PlyFileTest, StreamsAsciiRecordsOfEveryType) {
  PlyReader ply(write("a.ply", ascii()), "PLY file");
  expectRecords(ply);
  EXPECT_EQ(ply.endHeaderLine(), 17);
}

TEST_F(PlyFileTest, StreamsBinaryRecordsOfEveryType) {
  PlyReader ply(write("b.ply", binary()), "PLY file");
  expectRecords(ply);
}

TEST_F(PlyFileTest, ErrorsNameTheRecord) {
  std::string f = write("a.ply", ascii());
  PlyReader ascii(f, "PLY file");
  ascii.next();
  ascii.next();
  try {
    ascii.fail("bad");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), f + ":19: a 1: bad");
  }

  std::string g = write("b.ply", binary());
  PlyReader binary(g, "PLY file");
  binary.next();
  try {
    binary.vertexIndex(-1, 10);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), g + ": a 0: vertex index -1 is out of range (the file has 10 vertices)");
  }
  EXPECT_EQ(binary.vertexIndex(9, 10), 9u);
  try {
    binary.vertexIndexList(binary.elements()[2]);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), g + ":15: element b has no list property 'vertex_indices'");
  }
}

TEST_F(PlyFileTest, ReportsDataAfterTheLastRecord) {
  std::string f = write("extra.ply", ascii() + "\n4.5\n");
  PlyReader ply(f, "PLY file");
  for (int i = 0; i < 3; ++i) ply.next();
  try {
    ply.finish();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(f + ":22"), std::string::npos) << e.what();
  }
}

TEST_F(PlyFileTest, CountsTheFileCannotHoldAreRejectedBeforeReading) {
  // A few bytes of data under a header that declares a billion records of 12 bytes.
  const std::string header =
      "element vertex 1000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (const char* format : {"ascii", "binary_little_endian"}) {
    SCOPED_TRACE(format);
    std::string f = write("huge.ply", std::string("ply\nformat ") + format + " 1.0\n" + header + std::string(28, '1'));
    try {
      PlyReader ply(f, "PLY file");
      FAIL() << "no error";
    } catch (const InputError& e) {
      std::string message = e.what();
      EXPECT_NE(message.find(f + ":3:"), std::string::npos) << message;
      EXPECT_NE(message.find("declares 1000000000 vertex records"), std::string::npos) << message;
      EXPECT_NE(message.find("the file has 28 bytes left"), std::string::npos) << message;
    }
  }
  // Exactly enough data passes: three binary floats, and an ASCII record without a line break.
  EXPECT_NO_THROW(PlyReader(write("one.ply",
                                  "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                                  "property float y\nproperty float z\nend_header\n" +
                                      std::string(12, '\0')),
                            "PLY file"));
  EXPECT_NO_THROW(PlyReader(write("one.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                  "property float y\nproperty float z\nend_header\n1 2 3"),
                            "PLY file"));
}

TEST_F(PlyFileTest, BinaryRecordsWithoutPropertiesAreRejected) {
  // They would take no bytes, so no file size bounds how many there are.
  std::string f =
      write("empty.ply", "ply\nformat binary_little_endian 1.0\nelement nothing 1000000000000000000\nend_header\n");
  EXPECT_THROW(PlyReader(f, "PLY file"), InputError);
}
