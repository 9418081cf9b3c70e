#include "config/yaml_reader.hpp"

#include <gtest/gtest.h>

#include <functional>

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

}  // namespace
}  // namespace handover
