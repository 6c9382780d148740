#include "schema_subset.hpp"

#include <algorithm>

namespace antumbra::scene::test {
namespace {

using nlohmann::json;

class Validator {
 public:
  explicit Validator(const json& root) : root_(root) {}

  void check(const json& schema, const json& value, const std::string& pointer) {
    if (const auto it = schema.find("$ref"); it != schema.end()) {
      const std::string ref = it->get<std::string>();
      check(root_.at(json::json_pointer(ref.substr(1))), value, pointer);
    }
    if (const auto it = schema.find("oneOf"); it != schema.end()) check_one_of(*it, value, pointer);
    if (const auto it = schema.find("type"); it != schema.end() && !has_type(value, *it)) {
      fail(pointer, "is not of type " + it->get<std::string>());
      return;
    }
    if (const auto it = schema.find("const"); it != schema.end() && *it != value) {
      fail(pointer, "is not " + it->dump());
    }
    if (const auto it = schema.find("enum"); it != schema.end()) {
      if (std::find(it->begin(), it->end(), value) == it->end()) fail(pointer, "is no choice");
    }
    if (value.is_number()) check_bounds(schema, value.get<double>(), pointer);
    if (value.is_array()) check_array(schema, value, pointer);
    if (value.is_object()) check_object(schema, value, pointer);
  }

  std::vector<std::string> problems;

 private:
  static bool has_type(const json& value, const json& type) {
    const std::string t = type.get<std::string>();
    if (t == "integer") return value.is_number_integer();
    if (t == "number") return value.is_number();
    if (t == "boolean") return value.is_boolean();
    if (t == "string") return value.is_string();
    if (t == "array") return value.is_array();
    return t == "object" && value.is_object();
  }

  void fail(const std::string& pointer, const std::string& what) {
    problems.push_back((pointer.empty() ? "/" : pointer) + ": " + what);
  }

  void check_one_of(const json& branches, const json& value, const std::string& pointer) {
    int matches = 0;
    for (const json& branch : branches) {
      Validator inner(root_);
      inner.check(branch, value, pointer);
      if (inner.problems.empty()) ++matches;
    }
    if (matches != 1) fail(pointer, "matches " + std::to_string(matches) + " of oneOf");
  }

  void check_bounds(const json& schema, double v, const std::string& pointer) {
    if (schema.contains("minimum") && v < schema["minimum"].get<double>()) fail(pointer, "< min");
    if (schema.contains("maximum") && v > schema["maximum"].get<double>()) fail(pointer, "> max");
    if (schema.contains("exclusiveMinimum") && v <= schema["exclusiveMinimum"].get<double>())
      fail(pointer, "<= exclusive min");
    if (schema.contains("exclusiveMaximum") && v >= schema["exclusiveMaximum"].get<double>())
      fail(pointer, ">= exclusive max");
  }

  void check_array(const json& schema, const json& value, const std::string& pointer) {
    if (schema.contains("minItems") && value.size() < schema["minItems"].get<std::size_t>())
      fail(pointer, "has too few items");
    if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<std::size_t>())
      fail(pointer, "has too many items");
    if (const auto it = schema.find("items"); it != schema.end()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        check(*it, value[i], pointer + "/" + std::to_string(i));
      }
    }
  }

  void check_object(const json& schema, const json& value, const std::string& pointer) {
    for (const json& key : schema.value("required", json::array())) {
      if (!value.contains(key.get<std::string>())) fail(pointer, "lacks " + key.dump());
    }
    const json properties = schema.value("properties", json::object());
    const auto extra = schema.find("additionalProperties");
    const std::string base_pointer = pointer + "/";
    for (const auto& [key, member] : value.items()) {
      const std::string p = base_pointer + key;
      if (const auto it = properties.find(key); it != properties.end()) {
        check(*it, member, p);
      } else if (extra != schema.end() && extra->is_boolean() && !extra->get<bool>()) {
        fail(p, "is not an allowed key");
      } else if (extra != schema.end() && extra->is_object()) {
        check(*extra, member, p);
      }
    }
  }

  const json& root_;
};

}  // namespace

std::vector<std::string> schema_problems(const nlohmann::json& schema,
                                         const nlohmann::json& value) {
  Validator validator(schema);
  validator.check(schema, value, "");
  return validator.problems;
}

}  // namespace antumbra::scene::test
