#include "config/yaml_reader.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "config/bounded_file.hpp"
#include "tests/support/temp_path.hpp"

namespace handover {
namespace {

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlReader, MessagesNameFileKeyAndLine) {
  const YamlReader r = YamlReader::loadString("a:\n  b: 1\n  c: hello\n", "demo.yaml");
  const std::string msg = errorOf([&] { r.child("a").child("c").asDouble(); });
  EXPECT_NE(msg.find("demo.yaml:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("a.c"), std::string::npos) << msg;
  EXPECT_NE(msg.find("hello"), std::string::npos) << msg;
}

TEST(YamlReader, UnknownKeyRejectedWithItsLine) {
  const YamlReader r = YamlReader::loadString("a: 1\nbogus: 2\n", "demo.yaml");
  EXPECT_EQ(r.getInt("a", 0), 1);
  const std::string msg = errorOf([&] { r.finish(); });
  EXPECT_NE(msg.find("demo.yaml:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bogus"), std::string::npos) << msg;
}

TEST(YamlReader, SyntaxErrorNamesFileAndLine) {
  const std::string msg = errorOf([] { YamlReader::loadString("a: [1, 2\nb: 3\n", "broken.yaml"); });
  EXPECT_NE(msg.find("broken.yaml:"), std::string::npos) << msg;
}

TEST(YamlReader, VectorLengthAndRangeChecked) {
  const YamlReader r = YamlReader::loadString("v: [1, 2]\nx: 5\n", "demo.yaml");
  EXPECT_NE(errorOf([&] { r.child("v").asVector(3); }).find("expected 3 numbers, got 2"), std::string::npos);
  EXPECT_NE(errorOf([&] { r.checkRange(r.getDouble("x"), 0, 1); }).find("out of range"), std::string::npos);
}

TEST(ApplyOverrides, TwoSectionsBothApplyAndTheDocumentKeepsItsShape) {
  YAML::Node doc = YAML::Load("tracking:\n  k: 1\n  w: 2\nposture:\n  k: 10\n");
  const YamlReader ov = YamlReader::loadString("tracking.k: 4\nposture.k: 20\n", "scenario.yaml");
  applyOverrides(doc, ov, "controller.yaml");
  EXPECT_EQ(doc["tracking"]["k"].as<double>(), 4.0);
  EXPECT_EQ(doc["tracking"]["w"].as<double>(), 2.0);
  EXPECT_EQ(doc["posture"]["k"].as<double>(), 20.0);
  EXPECT_EQ(doc.size(), 2u);
}

TEST(ApplyOverrides, UnknownDottedKeyNamesScenarioAndKey) {
  YAML::Node doc = YAML::Load("tracking:\n  k: 1\n");
  const YamlReader ov = YamlReader::loadString("tracking.kk: 4\n", "scenario.yaml");
  const std::string msg = errorOf([&] { applyOverrides(doc, ov, "controller.yaml"); });
  EXPECT_NE(msg.find("scenario.yaml:1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tracking.kk"), std::string::npos) << msg;
  EXPECT_NE(msg.find("controller.yaml"), std::string::npos) << msg;
}


// yaml-cpp keeps both entries of a repeated key and lookups see the first:
// the reader refuses the repetition at the second occurrence's line
TEST(YamlReader, DuplicateKeyRefusedAtItsLine) {
  try {
    YamlReader::loadString("a: 1\nb:\n  c: 2\n  d: 3\n  c: 4\n", "dup.yaml");
    FAIL() << "duplicate accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dup.yaml:5:"), std::string::npos) << m;
    EXPECT_NE(m.find("'b.c'"), std::string::npos) << m;
    EXPECT_NE(m.find("duplicate"), std::string::npos) << m;
  }
  // the same key in two different maps is fine, also inside lists
  EXPECT_NO_THROW(YamlReader::loadString("a: {x: 1}\nb: {x: 2}\nl:\n  - {x: 1}\n  - {x: 2}\n", "ok.yaml"));
  EXPECT_THROW(YamlReader::loadString("l:\n  - {x: 1, x: 2}\n", "dup_in_list.yaml"), InputError);
}

TEST(YamlReader, OversizeInputRefusedUnreadNamingTheFile) {
  // /dev/zero never ends: the reader stops one byte past the bound
  try {
    YamlReader::loadFile("/dev/zero");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("/dev/zero:", 0), 0u) << m;
    EXPECT_NE(m.find("larger than"), std::string::npos) << m;
  }
  const std::string big = handover::test::uniqueTempPath("big.yaml");
  {
    std::ofstream out(big);
    out << "a: \"" << std::string(kMaxYamlBytes, 'x') << "\"\n";
  }
  EXPECT_THROW(YamlReader::loadFile(big), InputError);
  EXPECT_THROW(YamlReader::loadFile(::testing::TempDir()), InputError);  // a folder
}

TEST(ApplyOverrides, ScalarDocumentIsAnInputErrorNotAFault) {
  YAML::Node doc = YAML::Load("root:x:0:0:root:/root:/bin/bash");
  const YamlReader over = YamlReader::loadString("a.b: 1\n", "sc.yaml");
  EXPECT_THROW(applyOverrides(doc, over, "/etc/passwd"), InputError);
}

}  // namespace
}  // namespace handover
