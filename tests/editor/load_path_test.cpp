// The one load path's read and compile (fg/graph_source.hpp, docs/architecture.md "One
// load path") as every command and the editor use it: a file or text under a name, bad
// input located (missing file, bad JSON at line:column, a graph error at its JSON Pointer),
// the host's edit between read and compile, and the editor's document reading through it.

#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/editor/graph_document.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::fixture;

const fg::Registry& fake_registry() {
  static const fg::Registry kRegistry = testing::make_fake_registry();
  return kRegistry;
}

// The live fixture with one pass's type misspelt: a structure parse_graph accepts and
// the compiler refuses, at the pass's "type".
std::string with_unknown_type() {
  std::string text = testing::read(fixture("live_graph.json"));
  const auto at = text.find("\"type\": \"lighting\"");
  text.replace(at, 18, "\"type\": \"lightin\"");
  return text;
}

TEST(LoadPath, AMissingFileIsFG000WithTheSystemsReason) {
  const auto graph = fg::read_graph(fg::GraphSource::from_file("no/such/graph.json"));
  ASSERT_FALSE(graph.ok());
  const base::Diagnostic* d = graph.diagnostics().find(codes::graph::kFileUnreadable);
  ASSERT_NE(d, nullptr) << graph.diagnostics().to_text();
  EXPECT_EQ(d->file, "no/such/graph.json");
  EXPECT_NE(d->message.find("cannot open the file"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("No such file or directory"), std::string::npos) << d->message;
}

TEST(LoadPath, BadJsonIsLocatedAtLineAndColumnUnderTheTextsName) {
  const auto graph = fg::read_graph(
      fg::GraphSource::from_text("{ \"version\": 1,\n  \"passes\": [,\n", "edited/graph.json"));
  ASSERT_FALSE(graph.ok());
  ASSERT_EQ(graph.diagnostics().error_count(), 1u) << graph.diagnostics().to_text();
  const base::Diagnostic& d = *graph.diagnostics().begin();
  EXPECT_EQ(d.code.substr(0, 4), "FG00") << base::format_text(d);
  EXPECT_EQ(d.file, "edited/graph.json");
  EXPECT_EQ(d.line, 2);
  EXPECT_GT(d.column, 0);
}

TEST(LoadPath, AGraphErrorCarriesItsJsonPointerAndPosition) {
  const auto plan =
      fg::compile_graph(fg::GraphSource::from_text(with_unknown_type(), "g.json"), fake_registry());
  ASSERT_FALSE(plan.ok());
  const base::Diagnostic* d = plan.diagnostics().find(codes::graph::kUnknownPassType);
  ASSERT_NE(d, nullptr) << plan.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/passes/1/type");
  EXPECT_EQ(d->file, "g.json");
  EXPECT_EQ(d->line, 35);
  EXPECT_GT(d->column, 0);
  EXPECT_NE(d->message.find("did you mean 'lighting'"), std::string::npos) << d->message;
}

TEST(LoadPath, AFileAndItsTextUnderItsNameLoadAlike) {
  const std::string path = fixture("live_graph.json").string();
  const auto from_file = fg::compile_graph(fg::GraphSource::from_file(path), fake_registry());
  const auto from_text =
      fg::compile_graph(fg::GraphSource::from_text(testing::read(path), path), fake_registry());
  ASSERT_TRUE(from_file.ok()) << from_file.diagnostics().to_text();
  ASSERT_TRUE(from_text.ok()) << from_text.diagnostics().to_text();
  EXPECT_EQ(from_file->file, path);
  EXPECT_EQ(from_text->file, path);
  EXPECT_EQ(from_file.diagnostics().to_text(), from_text.diagnostics().to_text());
  EXPECT_EQ(from_file->passes.size(), from_text->passes.size());
}

// The host's edit (render --output, the editor's view) runs between read and compile, and
// what it breaks is reported like the file's own mistakes.
TEST(LoadPath, TheHostsEditRunsBeforeTheCompile) {
  const auto source = fg::GraphSource::from_file(fixture("live_graph.json").string());
  const auto hdr = fg::compile_graph(source, fake_registry(), {},
                                     [](fg::GraphDesc& graph) { graph.output = "hdr"; });
  ASSERT_TRUE(hdr.ok()) << hdr.diagnostics().to_text();
  EXPECT_EQ(hdr->resources.at(static_cast<std::size_t>(hdr->output)).name, "hdr");
  const auto buffer = fg::compile_graph(source, fake_registry(), {},
                                        [](fg::GraphDesc& graph) { graph.output = "table"; });
  ASSERT_FALSE(buffer.ok());
  const base::Diagnostic* d = buffer.diagnostics().find(codes::graph::kOutputNotImage);
  ASSERT_NE(d, nullptr) << buffer.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/output");
  EXPECT_GT(d->line, 0);
}

// The editor's document is read through the same path: the same located diagnostics.
TEST(LoadPath, TheEditorsDocumentReadsThroughIt) {
  const std::string bad = "{ \"version\": 1,\n  \"passes\": {}\n}\n";
  const auto document = GraphDocument::parse(bad, "doc.json", lookup_in(fake_registry()));
  const auto graph = fg::read_graph(fg::GraphSource::from_text(bad, "doc.json"));
  ASSERT_FALSE(document.ok());
  ASSERT_FALSE(graph.ok());
  EXPECT_EQ(document.diagnostics().to_text(), graph.diagnostics().to_text());
}

}  // namespace
}  // namespace antumbra::editor
