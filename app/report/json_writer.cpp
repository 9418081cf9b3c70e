#include "app/report/json_writer.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>

namespace handover::app {

std::string JsonWriter::quote(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          o += buf;
        } else {
          o += c;
        }
    }
  }
  return o + "\"";
}

std::string JsonWriter::number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream os;
  os << std::setprecision(10) << v;
  return os.str();
}

void JsonWriter::prefix(const std::string& key) {
  if (!first_.back()) out_ << ",";
  first_.back() = false;
  out_ << "\n" << std::string(2 * (first_.size() - 1), ' ');
  if (!key.empty()) out_ << quote(key) << ": ";
}

JsonWriter& JsonWriter::beginObject(const std::string& key) {
  if (first_.size() > 1 || !key.empty() || !first_.back()) prefix(key);
  out_ << "{";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endObject() {
  first_.pop_back();
  out_ << "\n" << std::string(2 * (first_.size() - 1), ' ') << "}";
  return *this;
}

JsonWriter& JsonWriter::beginArray(const std::string& key) {
  prefix(key);
  out_ << "[";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  first_.pop_back();
  out_ << "]";
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& key, double v) {
  prefix(key);
  out_ << number(v);
  return *this;
}
JsonWriter& JsonWriter::value(const std::string& key, std::optional<double> v) {
  prefix(key);
  out_ << (v ? number(*v) : "null");
  return *this;
}
JsonWriter& JsonWriter::value(const std::string& key, int v) {
  prefix(key);
  out_ << v;
  return *this;
}
JsonWriter& JsonWriter::value(const std::string& key, bool v) {
  prefix(key);
  out_ << (v ? "true" : "false");
  return *this;
}
JsonWriter& JsonWriter::value(const std::string& key, const std::string& v) {
  prefix(key);
  out_ << quote(v);
  return *this;
}
JsonWriter& JsonWriter::element(const std::string& v) {
  if (!first_.back()) out_ << ", ";
  first_.back() = false;
  out_ << quote(v);
  return *this;
}

}  // namespace handover::app
