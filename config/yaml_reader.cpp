#include "config/yaml_reader.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "config/bounded_file.hpp"

namespace handover {

namespace {

std::string describe(const YAML::Node& n) {
  if (!n || !n.IsDefined()) return "nothing";
  if (n.IsNull()) return "null";
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "an unknown node";
}

// yaml-cpp keeps every entry of a map with a repeated key and lookups return
// the first: refuse the repetition, naming the second occurrence's line
void rejectDuplicateKeys(const YAML::Node& n, const std::string& origin, const std::string& path) {
  if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) rejectDuplicateKeys(n[i], origin, path + "[" + std::to_string(i) + "]");
    return;
  }
  if (!n.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& kv : n) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("<a non-scalar key>");
    const std::string child = path.empty() ? key : path + "." + key;
    if (!seen.insert(key).second) {
      YamlReader(kv.first, origin, child).fail("duplicate key '" + key + "' (each key may appear once in a map)");
    }
    rejectDuplicateKeys(kv.second, origin, child);
  }
}

}  // namespace

YamlReader::YamlReader(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)),
      file_(std::move(file)),
      path_(std::move(path)),
      used_(std::make_shared<std::set<std::string>>()) {}

YamlReader YamlReader::loadFile(const std::string& path) {
  return loadString(readBoundedFile(path, kMaxYamlBytes, "YAML file"), path);
}

YamlReader YamlReader::loadString(const std::string& text, const std::string& origin) {
  try {
    YAML::Node root = YAML::Load(text);
    rejectDuplicateKeys(root, origin, "");
    return YamlReader(root, origin, "");
  } catch (const YAML::Exception& e) {
    std::ostringstream os;
    os << origin << ":" << (e.mark.line + 1) << ": YAML syntax error: " << e.msg;
    throw InputError(os.str());
  }
}

int YamlReader::line() const {
  if (!node_ || !node_.IsDefined()) return 0;
  const auto mark = node_.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

void YamlReader::fail(const std::string& message) const {
  std::ostringstream os;
  os << file_;
  if (line() > 0) os << ":" << line();
  os << ": ";
  if (!path_.empty()) os << "key '" << path_ << "': ";
  os << message;
  throw InputError(os.str());
}

std::string YamlReader::childPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool YamlReader::has(const std::string& key) const {
  if (!node_.IsMap()) return false;
  const YAML::Node c = node_[key];
  return c.IsDefined();
}

YamlReader YamlReader::child(const std::string& key) const {
  if (!node_.IsMap()) fail("expected a map, got " + describe(node_));
  const YAML::Node c = node_[key];
  if (!c.IsDefined()) fail("missing required key '" + key + "'");
  used_->insert(key);
  YamlReader r(c, file_, childPath(key));
  // a present key with no value points at its parent's line: keep it useful
  return r;
}

std::optional<YamlReader> YamlReader::optionalChild(const std::string& key) const {
  if (isNull()) return std::nullopt;
  if (!node_.IsMap()) fail("expected a map, got " + describe(node_));
  const YAML::Node c = node_[key];
  if (!c.IsDefined()) return std::nullopt;
  used_->insert(key);
  return YamlReader(c, file_, childPath(key));
}

YamlReader YamlReader::at(std::size_t i) const {
  if (!node_.IsSequence()) fail("expected a list, got " + describe(node_));
  if (i >= node_.size()) fail("index " + std::to_string(i) + " out of range");
  return YamlReader(node_[i], file_, path_ + "[" + std::to_string(i) + "]");
}

std::vector<std::string> YamlReader::keys() const {
  std::vector<std::string> out;
  if (!node_.IsMap()) return out;
  for (const auto& kv : node_) out.push_back(kv.first.Scalar());
  return out;
}

double YamlReader::asDouble() const {
  if (!node_.IsScalar()) fail("expected a number, got " + describe(node_));
  double v = 0.0;
  try {
    v = node_.as<double>();
  } catch (const YAML::Exception&) {
    fail("expected a number, got " + describe(node_));
  }
  if (!std::isfinite(v)) fail("expected a finite number, got " + describe(node_));
  return v;
}

int YamlReader::asInt() const {
  if (!node_.IsScalar()) fail("expected an integer, got " + describe(node_));
  try {
    return node_.as<int>();
  } catch (const YAML::Exception&) {
    fail("expected an integer, got " + describe(node_));
  }
}

bool YamlReader::asBool() const {
  if (!node_.IsScalar()) fail("expected true or false, got " + describe(node_));
  try {
    return node_.as<bool>();
  } catch (const YAML::Exception&) {
    fail("expected true or false, got " + describe(node_));
  }
}

std::string YamlReader::asString() const {
  if (!node_.IsScalar()) fail("expected a string, got " + describe(node_));
  return node_.Scalar();
}

std::string YamlReader::asEnum(std::initializer_list<const char*> allowed) const {
  const std::string s = asString();
  std::string list;
  for (const char* a : allowed) {
    if (s == a) return s;
    list += list.empty() ? a : std::string(" | ") + a;
  }
  fail("'" + s + "' is not one of: " + list);
}

Eigen::VectorXd YamlReader::asVectorRange(int min_n, int max_n) const {
  if (!node_.IsSequence()) fail("expected a list of numbers, got " + describe(node_));
  const int n = static_cast<int>(node_.size());
  if (n < min_n || n > max_n) {
    std::ostringstream os;
    os << "expected ";
    if (min_n == max_n) os << min_n;
    else os << min_n << " to " << max_n;
    os << " numbers, got " << n;
    fail(os.str());
  }
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = at(static_cast<std::size_t>(i)).asDouble();
  return v;
}

Eigen::VectorXd YamlReader::asVector(int n) const { return asVectorRange(n, n); }

double YamlReader::getDouble(const std::string& key, double def) const {
  auto c = optionalChild(key);
  return c ? c->asDouble() : def;
}
int YamlReader::getInt(const std::string& key, int def) const {
  auto c = optionalChild(key);
  return c ? c->asInt() : def;
}
bool YamlReader::getBool(const std::string& key, bool def) const {
  auto c = optionalChild(key);
  return c ? c->asBool() : def;
}
std::string YamlReader::getString(const std::string& key, const std::string& def) const {
  auto c = optionalChild(key);
  return c ? c->asString() : def;
}

double YamlReader::checkRange(double value, double lo, double hi) const {
  if (value < lo || value > hi) {
    std::ostringstream os;
    os << "value " << value << " is out of range [" << lo << ", " << hi << "]";
    fail(os.str());
  }
  return value;
}

void YamlReader::finish() const {
  if (!node_.IsMap()) return;
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    if (!used_->count(k)) {
      YamlReader(kv.first, file_, childPath(k)).fail("unknown key '" + k + "'");
    }
  }
}

void YamlReader::allowOnly(std::initializer_list<const char*> allowed) const {
  if (!node_.IsMap()) fail("expected a map, got " + describe(node_));
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    bool ok = false;
    std::string list;
    for (const char* a : allowed) {
      ok = ok || k == a;
      list += list.empty() ? a : std::string(", ") + a;
    }
    if (!ok) YamlReader(kv.first, file_, childPath(k)).fail("unknown key '" + k + "' (allowed: " + list + ")");
  }
}

void applyOverrides(YAML::Node doc, const YamlReader& overrides, const std::string& target_file) {
  if (overrides.isNull()) return;
  if (!overrides.isMap()) overrides.fail("expected a map of dotted keys to values");
  if (!doc.IsMap()) overrides.fail(target_file + " is not a map of settings: nothing to override");
  for (const std::string& dotted : overrides.keys()) {
    const YamlReader value = overrides.child(dotted);
    // walk the dotted path; each step must exist already. yaml-cpp's
    // Node::operator= writes through to the node, so the walking handle is
    // rebound with reset(), never assigned.
    std::string part;
    std::stringstream ss(dotted);
    std::vector<std::string> parts;
    while (std::getline(ss, part, '.')) parts.push_back(part);
    if (parts.empty()) value.fail("empty override key");
    YAML::Node cur = doc;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      YAML::Node next = cur[parts[i]];
      if (!next.IsDefined() || !next.IsMap()) {
        value.fail("'" + dotted + "' does not name a setting of " + target_file);
      }
      cur.reset(next);
    }
    YAML::Node leaf = cur[parts.back()];
    if (!leaf.IsDefined()) value.fail("'" + dotted + "' does not name a setting of " + target_file);
    if (leaf.IsMap() != value.node().IsMap() || leaf.IsSequence() != value.node().IsSequence()) {
      value.fail("'" + dotted + "' has the wrong kind of value for " + target_file);
    }
    cur[parts.back()] = YAML::Clone(value.node());
  }
}

}  // namespace handover
