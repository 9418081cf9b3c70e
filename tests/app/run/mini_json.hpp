// A small strict JSON reader for tests: enough to check that a result file
// is well-formed JSON and to look keys up by type. Throws std::runtime_error
// with the byte offset on malformed input. Not for production use.
#pragma once

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace handover::testing {

struct Json {
  enum class Kind { Null, Bool, Number, String, Array, Object };
  Kind kind = Kind::Null;
  bool boolean = false;
  double number = 0.0;
  std::string text;
  std::vector<Json> items;              // Array
  std::map<std::string, Json> members;  // Object
  std::vector<std::string> order;       // Object: keys as written

  bool has(const std::string& key) const { return kind == Kind::Object && members.count(key) > 0; }
  const Json& at(const std::string& key) const {
    auto it = members.find(key);
    if (kind != Kind::Object || it == members.end()) throw std::runtime_error("no key '" + key + "'");
    return it->second;
  }
  bool isNull() const { return kind == Kind::Null; }
  bool isNumber() const { return kind == Kind::Number; }
};

class JsonReader {
 public:
  explicit JsonReader(const std::string& s) : s_(s) {}

  Json parseDocument() {
    Json v = parseValue();
    skipSpace();
    if (i_ != s_.size()) fail("trailing characters");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at byte " + std::to_string(i_));
  }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool consume(char c) {
    skipSpace();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!consume(c)) fail(std::string("expected '") + c + "'");
  }
  bool literal(const char* word) {
    const std::string w(word);
    if (s_.compare(i_, w.size(), w) == 0) {
      i_ += w.size();
      return true;
    }
    return false;
  }

  std::string parseString() {
    expect('"');
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
      if (c == '\\') {
        if (i_ >= s_.size()) fail("unterminated escape");
        const char e = s_[i_++];
        switch (e) {
          case '"': out += '"'; break;
          case '\\': out += '\\'; break;
          case '/': out += '/'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'n': out += '\n'; break;
          case 'r': out += '\r'; break;
          case 't': out += '\t'; break;
          case 'u':
            if (i_ + 4 > s_.size()) fail("short \\u escape");
            out += '?';  // tests never compare non-ASCII text
            i_ += 4;
            break;
          default: fail("bad escape");
        }
      } else {
        out += c;
      }
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return out;
  }

  Json parseValue() {
    skipSpace();
    if (i_ >= s_.size()) fail("unexpected end");
    Json v;
    const char c = s_[i_];
    if (c == '{') {
      ++i_;
      v.kind = Json::Kind::Object;
      if (consume('}')) return v;
      do {
        skipSpace();
        const std::string key = parseString();
        expect(':');
        if (v.members.count(key)) fail("duplicate key '" + key + "'");
        v.members[key] = parseValue();
        v.order.push_back(key);
      } while (consume(','));
      expect('}');
    } else if (c == '[') {
      ++i_;
      v.kind = Json::Kind::Array;
      if (consume(']')) return v;
      do v.items.push_back(parseValue());
      while (consume(','));
      expect(']');
    } else if (c == '"') {
      v.kind = Json::Kind::String;
      v.text = parseString();
    } else if (literal("true")) {
      v.kind = Json::Kind::Bool;
      v.boolean = true;
    } else if (literal("false")) {
      v.kind = Json::Kind::Bool;
    } else if (literal("null")) {
      v.kind = Json::Kind::Null;
    } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
      // JSON number grammar: -?int frac? exp?
      const std::size_t start = i_;
      if (s_[i_] == '-') ++i_;
      auto digits = [&] {
        const std::size_t d0 = i_;
        while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
        if (i_ == d0) fail("digit expected");
      };
      digits();
      if (i_ < s_.size() && s_[i_] == '.') {
        ++i_;
        digits();
      }
      if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
        ++i_;
        if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
        digits();
      }
      v.kind = Json::Kind::Number;
      v.number = std::strtod(s_.substr(start, i_ - start).c_str(), nullptr);
    } else {
      fail(std::string("unexpected '") + c + "'");
    }
    return v;
  }

  const std::string& s_;
  std::size_t i_ = 0;
};

inline Json parseJson(const std::string& text) { return JsonReader(text).parseDocument(); }

}  // namespace handover::testing
