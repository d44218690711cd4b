// The JSON reader (json_value.hpp): recursive descent, depth bounded.
#include "mesh/io/json_value.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "kernel/error.hpp"

namespace dtlab {
namespace {

constexpr int kMaxDepth = 64;

class Parser {
 public:
  Parser(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  JsonValue document() {
    JsonValue v = value(0);
    skip();
    if (pos_ != text_.size()) fail("text after the JSON value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    std::uint64_t line = 1;
    for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i) line += text_[i] == '\n';
    throw ParseError(file_, line, what);
  }
  void skip() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) ++pos_;
  }
  bool eat(char c) {
    skip();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!eat(c)) fail(std::string("expected '") + c + "'");
  }
  bool word(const char* w) {
    const std::string s(w);
    if (text_.compare(pos_, s.size(), s) == 0) {
      pos_ += s.size();
      return true;
    }
    return false;
  }
  std::string string() {
    expect('"');
    std::string s;
    while (true) {
      if (pos_ >= text_.size()) fail("unterminated string");
      const char c = text_[pos_++];
      if (c == '"') return s;
      if (c != '\\') {
        s += c;
        continue;
      }
      if (pos_ >= text_.size()) fail("unterminated string");
      const char e = text_[pos_++];
      switch (e) {
        case '"': case '\\': case '/': s += e; break;
        case 'n': s += '\n'; break;
        case 't': s += '\t'; break;
        case 'r': s += '\r'; break;
        case 'b': s += '\b'; break;
        case 'f': s += '\f'; break;
        default: fail(std::string("unsupported escape \\") + e);
      }
    }
  }
  JsonValue value(int depth) {
    if (depth > kMaxDepth) fail("nested deeper than " + std::to_string(kMaxDepth));
    skip();
    if (pos_ >= text_.size()) fail("expected a value, found the end");
    const char c = text_[pos_];
    JsonValue v;
    if (c == '{') {
      ++pos_;
      auto object = std::make_shared<JsonValue::Object>();
      if (!eat('}')) {
        do {
          skip();
          const std::string key = string();
          if (object->contains(key)) fail("key \"" + key + "\" given twice");
          expect(':');
          (*object)[key] = value(depth + 1);
        } while (eat(','));
        expect('}');
      }
      v.value = object;
    } else if (c == '[') {
      ++pos_;
      auto array = std::make_shared<JsonValue::Array>();
      if (!eat(']')) {
        do array->push_back(value(depth + 1));
        while (eat(','));
        expect(']');
      }
      v.value = array;
    } else if (c == '"') {
      v.value = string();
    } else if (word("true")) {
      v.value = true;
    } else if (word("false")) {
      v.value = false;
    } else if (word("null")) {
      v.value = nullptr;
    } else {
      const char* begin = text_.c_str() + pos_;
      char* end = nullptr;
      const double x = std::strtod(begin, &end);
      if (end == begin) fail("expected a value");
      pos_ += static_cast<std::size_t>(end - begin);
      v.value = x;
    }
    return v;
  }

  const std::string& text_;
  const std::string& file_;
  std::size_t pos_ = 0;
};

}  // namespace

JsonValue parse_json(const std::string& text, const std::string& file_name) { return Parser(text, file_name).document(); }

JsonValue read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_json(text.str(), path);
}

}  // namespace dtlab
