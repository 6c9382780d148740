// The position-tracking JSON parser: values, positions and every error code.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/json_document.hpp"

namespace antumbra::base {
namespace {

Diagnostic parse_error(std::string_view text) {
  auto r = parse_json(text, "x.json");
  EXPECT_FALSE(r.ok()) << text;
  if (r.ok() || r.diagnostics().empty()) return {};
  return r.diagnostics()[0];
}

Diagnostic parse_error_with(std::string_view text, const JsonParseOptions& options) {
  auto r = parse_json(text, "x.json", options);
  EXPECT_FALSE(r.ok()) << text;
  if (r.ok() || r.diagnostics().empty()) return {};
  return r.diagnostics()[0];
}

TEST(JsonParser, ParsesValuesAndKeepsKeyOrder) {
  auto r = parse_json(R"({"b": 1, "a": [true, null, -2.5e1, "x\u00e9"], "c": {}})", "x.json");
  ASSERT_TRUE(r.ok()) << r.diagnostics().to_text();
  const Json& j = r->root();
  EXPECT_EQ(j.begin().key(), "b");
  EXPECT_EQ(j["a"][2].get<double>(), -25.0);
  EXPECT_EQ(j["a"][3].get<std::string>(), "x\xC3\xA9");
  EXPECT_TRUE(j["a"][1].is_null());
}

TEST(JsonParser, RecordsValueAndKeyPositions) {
  auto r = parse_json("{\n  \"passes\": [\n    {\"name\": \"a\"}\n  ]\n}", "x.json");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->position("/passes").line, 2);
  EXPECT_EQ(r->position("/passes").column, 13);
  EXPECT_EQ(r->position("/passes/0/name").line, 3);
  EXPECT_EQ(r->position("/passes/0/name").column, 14);
  EXPECT_EQ(r->key_position("/passes/0/name").column, 6);
  // Missing pointers fall back to the nearest ancestor.
  EXPECT_EQ(r->position("/passes/0/type").line, 3);
  EXPECT_EQ(r->position("/passes/0/type").column, 5);
}

TEST(JsonParser, PointerEscaping) {
  EXPECT_EQ(pointer_append("/a", "b/c~d"), "/a/b~1c~0d");
  EXPECT_EQ(pointer_append("", std::size_t{3}), "/3");
}

TEST(JsonParser, SyntaxErrorsCarryPosition) {
  const Diagnostic d = parse_error("{\n  \"a\": 1,\n}");
  EXPECT_EQ(d.code, codes::graph::kJsonSyntax);
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 1);
  EXPECT_NE(d.message.find("trailing"), std::string::npos);
  EXPECT_EQ(parse_error("[1,]").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("[1 2]").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("{\"a\" 1}").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("// c\n{}").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("01").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("\"\\x\"").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("\"\\ud800\"").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("nul").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("1e999").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("{} {}").code, codes::graph::kJsonSyntax);
  EXPECT_EQ(parse_error("\"a\nb\"").code, codes::graph::kJsonSyntax);
}

TEST(JsonParser, EmptyFile) {
  EXPECT_EQ(parse_error("").code, codes::graph::kJsonEmpty);
  const Diagnostic d = parse_error(" \n \t\n");
  EXPECT_EQ(d.code, codes::graph::kJsonEmpty);
  EXPECT_EQ(d.line, 3);
}

TEST(JsonParser, InvalidUtf8) {
  for (std::string_view bad : {"\"\xFF\"", "\"\xC0\xAF\"", "\"\xED\xA0\x80\"", "\"\xE2\x82\""}) {
    EXPECT_EQ(parse_error(bad).code, codes::graph::kJsonInvalidUtf8) << bad;
  }
  auto ok = parse_json("\"\xF0\x9F\x98\x80\"", "x.json");
  EXPECT_TRUE(ok.ok());
}

TEST(JsonParser, DuplicateKeyPointsAtSecondKey) {
  const Diagnostic d = parse_error("{\"a\": 1,\n \"a\": 2}");
  EXPECT_EQ(d.code, codes::graph::kJsonDuplicateKey);
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 2);
  EXPECT_EQ(d.pointer, "/a");
  EXPECT_EQ(parse_error(R"({"passes": [{"params": {"order": 1, "order": 2}}]})").pointer,
            "/passes/0/params/order");
}

TEST(JsonParser, SyntaxErrorsPointAtTheInnermostValue) {
  EXPECT_EQ(parse_error(R"({"a": {"b": [1, 2,]}})").pointer, "/a/b");
  EXPECT_EQ(parse_error(R"({"passes": [{"name": "x" "type": "y"}]})").pointer, "/passes/0");
  EXPECT_EQ(parse_error(R"({"a": 1,})").pointer, "");
  EXPECT_EQ(parse_error(R"({"a": tru})").pointer, "/a");
}

TEST(JsonParser, DepthLimit) {
  const std::string deep = std::string(300, '[') + std::string(300, ']');
  EXPECT_EQ(parse_error(deep).code, codes::graph::kJsonTooDeep);
  auto ok = parse_json(deep, "x.json", JsonParseOptions{400});
  EXPECT_TRUE(ok.ok());
}

// A file past the size limit is refused by its size, before a byte is read: a sparse file
// of 65 MiB costs no disk.
TEST(JsonParser, SizeLimit) {
  const std::filesystem::path big =
      std::filesystem::temp_directory_path() / "antumbra_json_size_limit.json";
  { std::ofstream(big) << "{}"; }
  std::filesystem::resize_file(big, (std::uintmax_t{65} << 20));
  auto r = load_json_file(big.string());
  std::filesystem::remove(big);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics()[0].code, codes::graph::kJsonTooLarge);
  EXPECT_NE(r.diagnostics()[0].message.find("the JSON is 68157440 bytes; a JSON file may hold at "
                                            "most 67108864 bytes"),
            std::string::npos)
      << r.diagnostics()[0].message;
  JsonParseOptions small;
  small.max_bytes = 4;
  EXPECT_EQ(parse_error_with("{\"a\": 1}", small).code, codes::graph::kJsonTooLarge);
  EXPECT_TRUE(parse_json("{}", "x.json", small).ok());
}

TEST(JsonParser, ByteOrderMarkIsSkipped) {
  auto r = parse_json("\xEF\xBB\xBF{\"a\": 1}", "x.json");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->position("/a").column, 7);
}

TEST(JsonParser, MissingFile) {
  auto r = load_json_file("/nonexistent/graph.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics()[0].code, codes::graph::kFileUnreadable);
}

TEST(JsonParser, DirectoryIsNotReadAsAnEmptyFile) {
  auto r = load_json_file(ANTUMBRA_FG_TEST_DATA);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics()[0].code, codes::graph::kFileUnreadable);
  EXPECT_NE(r.diagnostics()[0].message.find("directory"), std::string::npos);
}

TEST(Diagnostics, FormatsLikeACompiler) {
  Diagnostic d{"FG033", Severity::error, "too big", "g.json", "/passes/1/params/x", 4, 7};
  EXPECT_EQ(format_text(d), "g.json:4:7: error[FG033]: too big (at /passes/1/params/x)");
  EXPECT_EQ(to_json(d)["line"], 4);
}

}  // namespace
}  // namespace antumbra::base
