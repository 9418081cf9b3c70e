// Minimal JSON emitter for result files (summary.json). Not real-time safe.
#pragma once

#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace handover::app {

/// Builds one JSON document; keys are written in insertion order so files
/// diff well. Non-finite numbers are written as null (JSON has no NaN).
class JsonWriter {
 public:
  JsonWriter& beginObject(const std::string& key = "");
  JsonWriter& endObject();
  JsonWriter& beginArray(const std::string& key = "");
  JsonWriter& endArray();
  JsonWriter& value(const std::string& key, double v);
  JsonWriter& value(const std::string& key, std::optional<double> v);
  JsonWriter& value(const std::string& key, int v);
  JsonWriter& value(const std::string& key, bool v);
  JsonWriter& value(const std::string& key, const std::string& v);
  JsonWriter& value(const std::string& key, const char* v) { return value(key, std::string(v)); }
  JsonWriter& element(const std::string& v);  ///< string element of an array
  std::string str() const { return out_.str(); }

  static std::string quote(const std::string& s);
  static std::string number(double v);

 private:
  void prefix(const std::string& key);
  std::ostringstream out_;
  std::vector<bool> first_{true};  // one flag per open container
};

}  // namespace handover::app
