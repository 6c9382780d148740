#include "antumbra/editor/edit_script_check.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/fg/registry.hpp"

namespace antumbra::editor {
namespace {

using base::Json;

// What a key's value must be. `at`: a viewport position ([x, y], a light's name or
// {"over": [x, y, z]}); `port`: a pass's port, [pass, port].
enum class Kind {
  number,
  integer,
  boolean,
  string,
  vec2,
  vec3,
  at,
  any,
  string_or_null,
  plane,
  port
};

const std::vector<std::string>& plane_names() {
  static const std::vector<std::string> kNames{"horizontal", "vertical"};
  return kNames;
}

struct Key {
  const char* name;
  Kind kind;
  bool required = false;
};

struct Action {
  std::vector<Key> keys;
};

const std::map<std::string, Action, std::less<>>& do_actions() {
  static const std::map<std::string, Action, std::less<>> kActions = {
      {"frames", {{{"count", Kind::integer}}}},
      {"set-light",
       {{{"light", Kind::string, true},
         {"position", Kind::vec3},
         {"color", Kind::vec3},
         {"intensity", Kind::number},
         {"range", Kind::number},
         {"size", Kind::number},
         {"castsShadows", Kind::boolean},
         {"direction", Kind::vec3},
         {"angle", Kind::number},
         {"innerAngle", Kind::number}}}},
      {"add-light", {{{"position", Kind::vec3}}}},
      {"duplicate-light", {{{"light", Kind::string, true}}}},
      {"delete-light", {{{"light", Kind::string, true}}}},
      {"undo", {}},
      {"redo", {}},
      {"apply-fix", {}},
      {"save", {}},
      {"set-param",
       {{{"pass", Kind::string, true}, {"name", Kind::string, true}, {"value", Kind::any, true}}}},
      {"save-graph", {}},
      {"add-pass", {{{"type", Kind::string, true}, {"name", Kind::string}}}},
      {"remove-pass", {{{"pass", Kind::string, true}}}},
      {"rename-pass", {{{"pass", Kind::string, true}, {"to", Kind::string, true}}}},
      {"connect", {{{"from", Kind::port, true}, {"to", Kind::port, true}}}},
      {"disconnect", {{{"pass", Kind::string, true}, {"port", Kind::string, true}}}},
      {"bind",
       {{{"pass", Kind::string, true},
         {"port", Kind::string, true},
         {"resource", Kind::string, true}}}},
      {"create-resource", {{{"pass", Kind::string, true}, {"port", Kind::string, true}}}},
      {"write-file",
       {{{"path", Kind::string, true}, {"text", Kind::string}, {"from", Kind::string}}}},
      {"reload", {}},
      {"mark-memory", {}},
      {"camera",
       {{{"reset", Kind::boolean},
         {"pivot", Kind::string},
         {"orbit", Kind::vec2},
         {"look", Kind::vec2},
         {"dolly", Kind::number},
         {"move", Kind::vec3},
         {"metres", Kind::number}}}},
      {"click", {{{"at", Kind::at, true}}}},
      {"viewport-drag",
       {{{"from", Kind::at, true},
         {"to", Kind::at, true},
         {"plane", Kind::plane},
         {"steps", Kind::integer},
         {"tolerance", Kind::number}}}},
  };
  return kActions;
}

const std::map<std::string, Action, std::less<>>& expectations() {
  static const std::map<std::string, Action, std::less<>> kActions = {
      {"warning", {}},
      {"no-warning", {}},
      {"layers-needed", {{{"value", Kind::integer, true}}}},
      {"reload-ok", {}},
      {"reload-failed", {{{"code", Kind::string}, {"line", Kind::integer}}}},
      {"file-contains", {{{"path", Kind::string, true}, {"text", Kind::string, true}}}},
      {"file-lacks", {{{"path", Kind::string, true}, {"text", Kind::string, true}}}},
      {"selected", {{{"light", Kind::string_or_null, true}}}},
      {"light-at",
       {{{"light", Kind::string, true},
         {"position", Kind::vec3, true},
         {"tolerance", Kind::number}}}},
      {"dirty", {{{"value", Kind::boolean, true}}}},
      {"refused", {{{"code", Kind::string}}}},
      {"memory-within", {{{"percent", Kind::number}, {"extraAllocations", Kind::integer}}}},
  };
  return kActions;
}

bool numbers(const Json& v, std::size_t count) {
  return v.is_array() && v.size() == count &&
         std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_number(); });
}

bool fits(const Json& v, Kind kind) {
  switch (kind) {
    case Kind::number:
      return v.is_number();
    case Kind::integer:
      return v.is_number_integer();
    case Kind::boolean:
      return v.is_boolean();
    case Kind::string:
      return v.is_string();
    case Kind::string_or_null:
      return v.is_string() || v.is_null();
    case Kind::vec2:
      return numbers(v, 2);
    case Kind::vec3:
      return numbers(v, 3);
    case Kind::at:
      return numbers(v, 2) || v.is_string() ||
             (v.is_object() && v.size() == 1 && v.contains("over") && numbers(v["over"], 3));
    case Kind::plane:
      return v.is_string() && std::find(plane_names().begin(), plane_names().end(),
                                        v.get<std::string>()) != plane_names().end();
    case Kind::port:
      return v.is_array() && v.size() == 2 && v[0].is_string() && v[1].is_string();
    case Kind::any:
      return true;
  }
  return false;
}

const char* expected(Kind kind) {
  switch (kind) {
    case Kind::number:
      return "a number";
    case Kind::integer:
      return "an integer";
    case Kind::boolean:
      return "true or false";
    case Kind::string:
      return "a string";
    case Kind::string_or_null:
      return "a light's name or null";
    case Kind::vec2:
      return "[x, y] (numbers)";
    case Kind::vec3:
      return "[x, y, z] (numbers)";
    case Kind::at:
      return "[x, y] pixels, a light's name or {\"over\": [x, y, z]}";
    case Kind::plane:
      return "\"horizontal\" or \"vertical\"";
    case Kind::port:
      return "[pass, port] (two strings)";
    case Kind::any:
      return "a value";
  }
  return "a value";
}

template <class Map>
std::vector<std::string> names_of(const Map& map) {
  std::vector<std::string> names;
  names.reserve(map.size());
  for (const auto& [name, unused] : map) names.push_back(name);
  return names;
}

void check_step(const base::JsonDocument& script, const Json& step, const std::string& pointer,
                base::Diagnostics& out) {
  const auto error = [&](const std::string& message, const std::string& at, bool at_key) {
    out.add(
        script.make(codes::editor::kScriptMalformed, base::Severity::error, message, at, at_key));
  };
  if (!step.is_object()) {
    error("a step must be an object with \"do\" or \"expect\"", pointer, false);
    return;
  }
  const bool is_do = step.contains("do");
  if (is_do == step.contains("expect")) {
    error("a step needs exactly one of \"do\" and \"expect\"", pointer, false);
    return;
  }
  const char* verb = is_do ? "do" : "expect";
  const auto& table = is_do ? do_actions() : expectations();
  const Json& name = step[verb];
  const std::string name_pointer = pointer + "/" + verb;
  if (!name.is_string()) {
    error(std::string("\"") + verb + "\" must name an action (a string)", name_pointer, false);
    return;
  }
  const auto action = table.find(name.get<std::string>());
  if (action == table.end()) {
    error(std::string("unknown ") + (is_do ? "action" : "expectation") + " '" +
              name.get<std::string>() + "'" +
              fg::did_you_mean(name.get<std::string>(), names_of(table)),
          name_pointer, false);
    return;
  }
  std::vector<std::string> allowed{verb, "comment"};
  for (const Key& key : action->second.keys) allowed.emplace_back(key.name);
  for (const auto& item : step.items()) {
    // Not a structured binding: clang (clang-tidy) cannot capture one in the lambda below.
    const std::string& key = item.key();
    const base::Json& value = item.value();
    std::string key_pointer = pointer;
    key_pointer += '/';
    key_pointer += key;
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      error(base::quote_name(name.get<std::string>()) + " has no key " + base::quote_name(key) +
                fg::did_you_mean(key, allowed),
            key_pointer, true);
      continue;
    }
    const auto spec = std::find_if(action->second.keys.begin(), action->second.keys.end(),
                                   [&](const Key& k) { return key == k.name; });
    if (spec != action->second.keys.end() && !fits(value, spec->kind)) {
      const std::string hint = spec->kind == Kind::plane && value.is_string()
                                   ? fg::did_you_mean(value.get<std::string>(), plane_names())
                                   : std::string();
      error(base::quote_name(key) + " must be " + expected(spec->kind) + hint, key_pointer, false);
    }
  }
  for (const Key& key : action->second.keys) {
    if (key.required && !step.contains(key.name)) {
      error(base::quote_name(name.get<std::string>()) + " needs " + base::quote_name(key.name),
            pointer, false);
    }
  }
}

}  // namespace

base::Diagnostics check_edit_script(const base::JsonDocument& script) {
  base::Diagnostics out;
  const Json& root = script.root();
  const auto error = [&](const std::string& message, const std::string& at, bool at_key) {
    out.add(
        script.make(codes::editor::kScriptMalformed, base::Severity::error, message, at, at_key));
  };
  if (!root.is_object()) {
    error("expected {\"steps\": [...]}", "", false);
    return out;
  }
  const std::vector<std::string> top{"steps", "description", "comment"};
  for (const auto& [key, unused] : root.items()) {
    if (std::find(top.begin(), top.end(), key) == top.end()) {
      error("unknown key '" + key + "'" + fg::did_you_mean(key, top), "/" + key, true);
    }
  }
  if (!root.contains("steps") || !root["steps"].is_array()) {
    error("expected {\"steps\": [...]}: the steps are missing or not an array",
          root.contains("steps") ? "/steps" : "", false);
    return out;
  }
  const Json& steps = root["steps"];
  for (std::size_t i = 0; i < steps.size(); ++i) {
    check_step(script, steps[i], "/steps/" + std::to_string(i), out);
  }
  return out;
}

}  // namespace antumbra::editor
