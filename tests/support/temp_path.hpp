// Scratch file paths for tests.
//
// ctest runs every test of a binary as its own process, several at once, so
// a fixed name under ::testing::TempDir() is shared by concurrent tests: one
// test's file is overwritten by another's before it is read. A path made
// here carries the suite, the test and the process id, so no two running
// tests share it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace handover::test {

// TempDir()/<suite>.<test>.<pid>.<name>; `name` may contain '/' (a subfolder).
inline std::string uniqueTempPath(const std::string& name) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string prefix = info != nullptr ? std::string(info->test_suite_name()) + "." + info->name() : "no_test";
  std::string dir = ::testing::TempDir();
  if (dir.empty() || dir.back() != '/') dir += '/';
  return dir + prefix + "." + std::to_string(::getpid()) + "." + name;
}

/// Writes `text` to uniqueTempPath(name) and returns that path.
inline std::string writeTempFile(const std::string& name, const std::string& text) {
  const std::string path = uniqueTempPath(name);
  std::ofstream(path) << text;
  return path;
}

}  // namespace handover::test
