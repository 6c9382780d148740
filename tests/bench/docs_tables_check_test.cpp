// antumbra docs-tables --check and its diagnostics: an edited number fails with the file
// and line; bad inputs (malformed or missing results, a missing scenario, an unknown
// kind, unclosed markers) are located. And the check over the repository itself.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>

#include "docs_tables.hpp"
#include "docs_tables_test_support.hpp"

using namespace antumbra::app::docs;
using namespace docs_tables_test;
namespace fs = std::filesystem;

namespace {

// A scratch root with its own results, removed afterwards.
class DocsTablesScratch : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("antumbra-docs-tables-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  DocumentResult process(const std::string& text, bool check = true) {
    ResultCache results(root_);
    return process_document(text, "README.md", results, check);
  }

  fs::path root_;
};

TEST(DocsTablesCheck, PassesOnTheGeneratedDocumentAndNamesAnEditedDigit) {
  const std::string generated = read(kFixtures / "expected.md");
  ResultCache results(kFixtures);
  const auto clean = process_document(generated, "README.md", results, true);
  EXPECT_TRUE(clean.diagnostics.empty()) << diagnostics_text(clean.diagnostics);
  EXPECT_EQ(clean.differing, 0u);
  EXPECT_EQ(clean.text, generated);

  // One digit of the moving table's 64-light row, typed over.
  auto lines = split_lines(generated);
  std::size_t row = 0;
  while (row < lines.size() && lines[row].rfind("| 64 (64), atrium |", 0) != 0) ++row;
  ASSERT_LT(row, lines.size());
  const std::size_t digit = lines[row].find_first_of("0123456789", 20);
  lines[row][digit] = lines[row][digit] == '9' ? '8' : '9';
  const auto edited = process_document(join_lines(lines), "README.md", results, true);
  ASSERT_EQ(edited.diagnostics.error_count(), 1u) << diagnostics_text(edited.diagnostics);
  const auto& d = edited.diagnostics[0];
  EXPECT_EQ(d.code, "DT010");
  EXPECT_EQ(d.file, "README.md");
  EXPECT_EQ(d.line, static_cast<int>(row + 1));
  EXPECT_EQ(d.column, static_cast<int>(digit + 1));
  EXPECT_EQ(d.message,
            "table 'moving' differs from what results/moving.json generates (run make "
            "docs-tables)");
  EXPECT_EQ(d.excerpt, lines[row]);
  EXPECT_EQ(edited.diagnostics[1].message, "generated: " + split_lines(generated)[row]);
  EXPECT_EQ(edited.differing, 1u);
}

TEST(DocsTablesCheck, ARemovedRowDiffersToo) {
  auto lines = split_lines(read(kFixtures / "expected.md"));
  std::size_t row = 0;
  while (row < lines.size() && lines[row].rfind("| PCSS 11 |", 0) != 0) ++row;
  ASSERT_LT(row, lines.size());
  lines.erase(lines.begin() + static_cast<long>(row));
  ResultCache results(kFixtures);
  const auto edited = process_document(join_lines(lines), "README.md", results, true);
  ASSERT_EQ(edited.diagnostics.error_count(), 1u) << diagnostics_text(edited.diagnostics);
  EXPECT_EQ(edited.diagnostics[0].line, static_cast<int>(row + 1));
}

TEST_F(DocsTablesScratch, MissingResultsFileIsAnErrorAtTheMarker) {
  const auto result = process("Intro.\n" + kDynamicRegion);
  ASSERT_EQ(result.diagnostics.size(), 1u) << diagnostics_text(result.diagnostics);
  const auto& d = result.diagnostics[0];
  EXPECT_EQ(d.code, "DT003");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 37);  // the kind
  EXPECT_NE(d.message.find("results/dynamic.json, which does not exist"), std::string::npos);
}

TEST_F(DocsTablesScratch, MalformedResultsAreLocatedInTheirFile) {
  write(root_ / "results/dynamic.json", "{\n  \"commit\": \"abc\",\n  \"device\": ,\n}\n");
  const auto result = process(kDynamicRegion);
  ASSERT_TRUE(result.diagnostics.has_errors());
  const auto& d = result.diagnostics[0];
  EXPECT_EQ(d.code, "FG001");
  EXPECT_EQ(d.file, "results/dynamic.json");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 13);
}

TEST_F(DocsTablesScratch, ResultsWithoutTheirDriverAreRefused) {
  write(root_ / "results/dynamic.json", R"({"commit": "abc", "device": "GPU", "scenarios": []})");
  const auto result = process(kDynamicRegion);
  ASSERT_EQ(result.diagnostics.size(), 1u) << diagnostics_text(result.diagnostics);
  EXPECT_EQ(result.diagnostics[0].code, "DT004");
  EXPECT_NE(result.diagnostics[0].message.find("driver"), std::string::npos);
}

TEST_F(DocsTablesScratch, AMissingScenarioIsNamedAtTheScenariosArray) {
  auto json = nlohmann::json::parse(read(kFixtures / "results/dynamic.json"));
  json["scenarios"].erase(4);  // dynamic/pcss-11/1080p/16l/nocache
  const std::string text = json.dump(1);
  write(root_ / "results/dynamic.json", text);
  const auto result = process(kDynamicRegion);
  ASSERT_EQ(result.diagnostics.size(), 1u) << diagnostics_text(result.diagnostics);
  const auto& d = result.diagnostics[0];
  EXPECT_EQ(d.code, "DT005");
  EXPECT_EQ(d.file, "results/dynamic.json");
  EXPECT_EQ(d.pointer, "/scenarios");
  const auto before = text.substr(0, text.find("\"scenarios\""));
  EXPECT_EQ(d.line, 1 + std::count(before.begin(), before.end(), '\n'));
  EXPECT_NE(d.message.find("\"dynamic/pcss-11/1080p/16l/nocache\""), std::string::npos);
  // The region is left as it was.
  EXPECT_EQ(result.text, kDynamicRegion);
}

TEST_F(DocsTablesScratch, AMissingNumberIsNamedByItsPointer) {
  auto json = nlohmann::json::parse(read(kFixtures / "results/dynamic.json"));
  json["scenarios"][1]["frame"].erase("medianMs");
  write(root_ / "results/dynamic.json", json.dump(1));
  const auto result = process(kDynamicRegion);
  ASSERT_EQ(result.diagnostics.size(), 1u) << diagnostics_text(result.diagnostics);
  EXPECT_EQ(result.diagnostics[0].pointer, "/scenarios/1/frame/medianMs");
  EXPECT_GT(result.diagnostics[0].line, 0);
}

TEST_F(DocsTablesScratch, UnknownKindAndMalformedMarkersAreLocated) {
  const auto unknown = process(
      "\n<!-- generated by make docs-tables: movin from results/x.json; do not edit -->\n"
      "<!-- end generated -->\n");
  ASSERT_EQ(unknown.diagnostics.size(), 1u) << diagnostics_text(unknown.diagnostics);
  EXPECT_EQ(unknown.diagnostics[0].code, "DT002");
  EXPECT_EQ(unknown.diagnostics[0].line, 2);
  EXPECT_EQ(unknown.diagnostics[0].column, 37);
  EXPECT_NE(unknown.diagnostics[0].message.find("'movin'"), std::string::npos);

  const auto malformed = process("<!-- generated by make docs-tables: moving -->\n");
  ASSERT_EQ(malformed.diagnostics.size(), 1u) << diagnostics_text(malformed.diagnostics);
  EXPECT_EQ(malformed.diagnostics[0].code, "DT001");
  EXPECT_NE(malformed.diagnostics[0].message.find("malformed marker"), std::string::npos);
}

TEST_F(DocsTablesScratch, UnclosedAndStrayMarkersAreErrors) {
  const auto unclosed = process("a\n" + kDynamicRegion.substr(0, kDynamicRegion.find('\n') + 1));
  ASSERT_EQ(unclosed.diagnostics.size(), 1u) << diagnostics_text(unclosed.diagnostics);
  EXPECT_EQ(unclosed.diagnostics[0].code, "DT001");
  EXPECT_EQ(unclosed.diagnostics[0].line, 2);
  EXPECT_NE(unclosed.diagnostics[0].message.find("unclosed marker"), std::string::npos);

  const auto twice =
      process(kDynamicRegion.substr(0, kDynamicRegion.find('\n') + 1) + kDynamicRegion);
  ASSERT_FALSE(twice.diagnostics.empty());
  EXPECT_EQ(twice.diagnostics[0].line, 1);

  const auto stray = process("a\n<!-- end generated -->\n");
  ASSERT_EQ(stray.diagnostics.size(), 1u);
  EXPECT_EQ(stray.diagnostics[0].line, 2);
  // Inside a fence a marker is text.
  EXPECT_TRUE(process("```\n" + kDynamicRegion + "```\n").diagnostics.empty());
}

// process_tree over a copy: it rewrites only the regions, after which check passes.
TEST_F(DocsTablesScratch, TreeRewritesTheRegionsThenChecks) {
  fs::copy(kFixtures / "results", root_ / "results");
  const std::string doc = "# Page\n\n" + kDynamicRegion + "after\n";
  write(root_ / "docs/page.md", doc);
  write(root_ / "README.md", "No tables.\n");
  EXPECT_EQ(process_tree(root_, true).differing, 1u);
  const auto rewritten = process_tree(root_, false);
  EXPECT_TRUE(rewritten.diagnostics.empty()) << diagnostics_text(rewritten.diagnostics);
  EXPECT_EQ(rewritten.rewritten, std::vector<std::string>{"docs/page.md"});
  EXPECT_EQ(read(root_ / "README.md"), "No tables.\n");
  const auto page = read(root_ / "docs/page.md");
  EXPECT_EQ(page.rfind("# Page\n\n<!-- generated", 0), 0u);
  EXPECT_EQ(page.substr(page.size() - 29), "<!-- end generated -->\nafter\n");
  const auto checked = process_tree(root_, true);
  EXPECT_TRUE(checked.diagnostics.empty()) << diagnostics_text(checked.diagnostics);
  EXPECT_EQ(checked.regions, 1u);
}

// THE check: every generated table of README.md and docs/*.md is what the committed
// results under docs/results/ generate. A number typed over fails here with its file and
// line; `make docs-tables` regenerates them.
TEST(DocsTablesRepository, CommittedTablesAreWhatTheirResultsGenerate) {
  const auto tree = process_tree(kSource, true);
  EXPECT_FALSE(tree.diagnostics.has_errors()) << diagnostics_text(tree.diagnostics);
  EXPECT_EQ(tree.differing, 0u);
  EXPECT_GT(tree.regions, 0u) << "README.md and docs/*.md hold no generated table";
}

}  // namespace
