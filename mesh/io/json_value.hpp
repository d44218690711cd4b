// A small JSON reader (RFC 8259: objects, arrays, strings, numbers, true, false, null) for the
// descriptions dtlab reads (a parametric patch: algorithms/surface/patch_description.hpp). The whole
// text is parsed at once; ParseError names the line and what was expected. Strings keep their
// escapes decoded except \u (refused by name: no description needs it). Nesting is bounded.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace dtlab {

struct JsonValue {
  using Array = std::vector<JsonValue>;
  using Object = std::map<std::string, JsonValue>;
  std::variant<std::nullptr_t, bool, double, std::string, std::shared_ptr<Array>, std::shared_ptr<Object>> value;

  bool is_number() const { return std::holds_alternative<double>(value); }
  bool is_string() const { return std::holds_alternative<std::string>(value); }
  bool is_array() const { return std::holds_alternative<std::shared_ptr<Array>>(value); }
  bool is_object() const { return std::holds_alternative<std::shared_ptr<Object>>(value); }
  double number() const { return std::get<double>(value); }
  const std::string& string() const { return std::get<std::string>(value); }
  const Array& array() const { return *std::get<std::shared_ptr<Array>>(value); }
  const Object& object() const { return *std::get<std::shared_ptr<Object>>(value); }
};

// `file_name` names the text in errors.
JsonValue parse_json(const std::string& text, const std::string& file_name);
JsonValue read_json(const std::string& path);

}  // namespace dtlab
