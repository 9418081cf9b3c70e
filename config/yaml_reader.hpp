// Strict YAML reading: every key is checked, every value is typed, and every
// error names the file, the dotted key and the line. Used by the scenario
// parser and by every config loader. Not real-time safe (start-up only).
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "config/input_error.hpp"

namespace handover {

/// A YAML node together with where it came from (file and dotted key path).
/// Reading through a YamlReader records which keys were consumed, so that
/// finish() can reject unknown keys with the right line.
class YamlReader {
 public:
  /// Loads a file (at most kMaxYamlBytes, config/bounded_file.hpp); throws
  /// InputError naming the file on I/O or syntax errors, on a file too large and
  /// on a key repeated within one map (yaml-cpp would silently keep one).
  static YamlReader loadFile(const std::string& path);
  /// Parses text (tests, overrides); `origin` is used in messages as the file.
  /// Duplicate keys are refused as in loadFile.
  static YamlReader loadString(const std::string& text, const std::string& origin);

  YamlReader(YAML::Node node, std::string file, std::string path);

  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  /// Dotted key of this node from the document root ("" for the root).
  const std::string& path() const { return path_; }
  /// 1-based line of this node in its file (0 if unknown).
  int line() const;

  bool isMap() const { return node_.IsMap(); }
  bool isSequence() const { return node_.IsSequence(); }
  bool isNull() const { return !node_ || node_.IsNull(); }
  bool has(const std::string& key) const;
  std::size_t size() const { return node_.size(); }

  /// Child of a map (marks the key as used). Throws when missing.
  YamlReader child(const std::string& key) const;
  /// Child of a map if present (marks the key as used).
  std::optional<YamlReader> optionalChild(const std::string& key) const;
  /// i-th element of a sequence.
  YamlReader at(std::size_t i) const;
  /// Keys of a map in file order.
  std::vector<std::string> keys() const;

  // typed scalar access; messages name file, key, line and the bad value
  double asDouble() const;
  int asInt() const;
  bool asBool() const;
  std::string asString() const;
  /// One of `allowed`, else an error listing them.
  std::string asEnum(std::initializer_list<const char*> allowed) const;
  /// A sequence of exactly n numbers.
  Eigen::VectorXd asVector(int n) const;
  /// A sequence of numbers of any length in [min_n, max_n].
  Eigen::VectorXd asVectorRange(int min_n, int max_n) const;

  // key shortcuts with defaults
  double getDouble(const std::string& key) const { return child(key).asDouble(); }
  double getDouble(const std::string& key, double def) const;
  int getInt(const std::string& key, int def) const;
  bool getBool(const std::string& key, bool def) const;
  std::string getString(const std::string& key) const { return child(key).asString(); }
  std::string getString(const std::string& key, const std::string& def) const;

  /// Checks that a number lies in [lo, hi]; throws naming key and range.
  double checkRange(double value, double lo, double hi) const;
  /// Throws InputError "file:line: key: message".
  [[noreturn]] void fail(const std::string& message) const;
  /// Rejects any key of this map that was not read (call after reading).
  void finish() const;
  /// Rejects keys of this map that are not in `allowed` (no read needed).
  void allowOnly(std::initializer_list<const char*> allowed) const;

 private:
  std::string childPath(const std::string& key) const;
  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::shared_ptr<std::set<std::string>> used_;  // keys read from this map
};

/// Applies "a.b.c: value" overrides onto a YAML document (scenario `set:`).
/// Each dotted key must already exist in `doc` (no typos slip through); the
/// value type must match the existing value's kind. Throws InputError naming
/// `origin` and the key otherwise.
void applyOverrides(YAML::Node doc, const YamlReader& overrides, const std::string& target_file);

}  // namespace handover
