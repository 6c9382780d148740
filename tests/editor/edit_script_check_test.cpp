// Edit scripts are checked whole before they run: unknown actions and keys (with a
// did-you-mean), missing keys and wrong value types are located ED101 diagnostics.

#include "antumbra/editor/edit_script_check.hpp"

#include <string>

#include <gtest/gtest.h>

namespace antumbra::editor {
namespace {

base::Diagnostics check(const std::string& text) {
  const auto document = base::parse_json(text, "script.json");
  EXPECT_TRUE(document.ok()) << document.diagnostics().to_text();
  return check_edit_script(document.value());
}

TEST(EditScriptCheck, AValidScriptHasNoProblems) {
  const auto problems = check(R"({"description": "d", "steps": [
    {"do": "set-light", "light": "a", "intensity": 3, "position": [1, 2, 3]},
    {"do": "viewport-drag", "from": "a", "to": {"over": [1, 2, 3]}, "tolerance": 0.05},
    {"do": "click", "at": [10, 20]},
    {"expect": "selected", "light": null},
    {"expect": "light-at", "light": "a", "position": [1, 2, 3]},
    {"do": "undo", "comment": "why"}
  ]})");
  EXPECT_TRUE(problems.empty()) << problems.to_text();
}

TEST(EditScriptCheck, AMisspeltKeyIsRejectedWithASuggestion) {
  const auto problems = check(R"({"steps": [
    {"do": "set-light", "light": "a", "intensty": 3}
  ]})");
  ASSERT_EQ(problems.size(), 1u) << problems.to_text();
  const auto& d = problems[0];
  EXPECT_EQ(d.code, "ED101");
  EXPECT_EQ(d.pointer, "/steps/0/intensty");
  EXPECT_EQ(d.line, 2);
  EXPECT_GT(d.column, 0);
  EXPECT_NE(d.message.find("did you mean 'intensity'"), std::string::npos) << d.message;
}

TEST(EditScriptCheck, UnknownActionsMissingKeysAndWrongTypesAreAllReported) {
  const auto problems = check(R"({"steps": [
    {"do": "set-lite", "light": "a"},
    {"expect": "warnings"},
    {"do": "delete-light"},
    {"do": "set-light", "light": "a", "position": [1, 2]},
    {"do": "click", "at": {"over": [1, 2]}},
    {"do": "frames", "count": 1.5},
    {"do": "viewport-drag", "from": "a", "to": "b", "plane": "horizonal"},
    {"light": "a"},
    42
  ], "stepz": []})");
  ASSERT_EQ(problems.size(), 10u) << problems.to_text();
  EXPECT_NE(problems[0].message.find("did you mean 'steps'"), std::string::npos)
      << problems.to_text();
  EXPECT_NE(problems.to_text().find("unknown action 'set-lite'; did you mean 'set-light'"),
            std::string::npos)
      << problems.to_text();
  EXPECT_NE(problems.to_text().find("did you mean 'warning'"), std::string::npos);
  EXPECT_NE(problems.to_text().find("'delete-light' needs 'light'"), std::string::npos);
  EXPECT_NE(problems.to_text().find("'position' must be [x, y, z]"), std::string::npos);
  EXPECT_NE(problems.to_text().find("'at' must be"), std::string::npos);
  EXPECT_NE(problems.to_text().find("'count' must be an integer"), std::string::npos);
  EXPECT_NE(problems.to_text().find("'plane' must be \"horizontal\" or \"vertical\"; did you mean "
                                    "'horizontal'"),
            std::string::npos)
      << problems.to_text();
  for (const auto& d : problems) EXPECT_EQ(d.code, "ED101");
}

TEST(EditScriptCheck, GraphEditsAndARefusalAreChecked) {
  EXPECT_TRUE(check(R"({"steps": [
    {"do": "add-pass", "type": "blur"},
    {"do": "add-pass", "type": "blur", "name": "soften"},
    {"do": "rename-pass", "pass": "soften", "to": "blur2"},
    {"do": "connect", "from": ["lighting", "hdr"], "to": ["blur", "src"]},
    {"expect": "refused", "code": "FG071"},
    {"do": "bind", "pass": "blur", "port": "dst", "resource": "hdr"},
    {"expect": "refused"},
    {"do": "create-resource", "pass": "blur", "port": "dst"},
    {"do": "disconnect", "pass": "blur", "port": "src"},
    {"do": "remove-pass", "pass": "blur"}
  ]})")
                  .empty());
  const auto problems = check(R"({"steps": [
    {"do": "connect", "from": "lighting.hdr", "to": ["blur", "src"]},
    {"do": "rename-pass", "pass": "blur", "name": "x"},
    {"expect": "refused", "cod": "FG071"}
  ]})");
  ASSERT_EQ(problems.size(), 4u) << problems.to_text();
  EXPECT_NE(problems.to_text().find("'from' must be [pass, port] (two strings)"), std::string::npos)
      << problems.to_text();
  EXPECT_NE(problems.to_text().find("'rename-pass' needs 'to'"), std::string::npos);
  EXPECT_NE(problems.to_text().find("did you mean 'code'"), std::string::npos);
}

TEST(EditScriptCheck, AScriptWithoutStepsIsMalformed) {
  EXPECT_EQ(check(R"({"step": []})").size(), 2u);
  EXPECT_EQ(check(R"([1, 2])").size(), 1u);
}

}  // namespace
}  // namespace antumbra::editor
