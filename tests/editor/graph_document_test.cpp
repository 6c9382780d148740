// The graph document: parameters listed with their reflection, edits checked against
// it (types, choices, ranges), undoable, and written back with every other byte kept.
#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "antumbra/editor/graph_document.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::changed_lines;
using testing::fixture;
using testing::read;
using testing::source_file;

class GraphDocumentTest : public ::testing::Test {
 protected:
  GraphDocument load(const std::filesystem::path& file) {
    return testing::take(GraphDocument::load(file, lookup_in(registry_)));
  }
  fg::Registry registry_ = testing::make_fake_registry();
};

TEST_F(GraphDocumentTest, ListsPassesAndParamsFromTheReflection) {
  const GraphDocument doc = load(fixture("graph.json"));
  const std::vector<PassView> passes = doc.passes();
  ASSERT_EQ(passes.size(), 3u);
  EXPECT_EQ(passes[0].name, "layers");
  EXPECT_EQ(passes[0].type, "light-layering");
  EXPECT_TRUE(passes[0].known_type);
  ASSERT_EQ(passes[0].params.size(), 2u);
  const ParamView& max_layers = passes[0].params[0];
  EXPECT_EQ(max_layers.name, "maxLayers");
  EXPECT_TRUE(max_layers.declared);
  EXPECT_EQ(max_layers.type, fg::ParamType::integer);
  EXPECT_EQ(max_layers.value, 4);
  EXPECT_TRUE(max_layers.from_file);
  EXPECT_EQ(max_layers.min, 1.0);
  EXPECT_EQ(max_layers.max, 32.0);
  EXPECT_EQ(passes[0].params[1].choices.size(), 3u);

  ASSERT_EQ(passes[1].params.size(), 1u);  // lighting: not in the file, default shown
  EXPECT_FALSE(passes[1].params[0].from_file);
  EXPECT_EQ(passes[1].params[0].value, 1.0);

  ASSERT_EQ(passes[2].params.size(), 4u);  // exposure, operator, enabled, then x-unknown
  EXPECT_EQ(passes[2].params[2].name, "enabled");
  EXPECT_FALSE(passes[2].params[2].from_file);
  EXPECT_EQ(passes[2].params[3].name, "x-unknown");
  EXPECT_FALSE(passes[2].params[3].declared);
  EXPECT_EQ(passes[2].params[3].value, 7);
  EXPECT_EQ(doc.find_pass("tonemap"), 2);
  EXPECT_FALSE(doc.param("tonemap", "nope").has_value());
}

TEST_F(GraphDocumentTest, AParamEditChangesOnlyThatValue) {
  const std::string original = read(fixture("graph.json"));
  GraphDocument doc = load(fixture("graph.json"));
  EXPECT_EQ(doc.to_text(), original);
  const EditResult result = doc.set_param("layers", "maxLayers", 3);
  ASSERT_TRUE(result);
  EXPECT_TRUE(result.changed);
  EXPECT_TRUE(doc.dirty());
  const auto changed = changed_lines(original, doc.to_text());
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0], "        \"maxLayers\": 3,");
  EXPECT_EQ(doc.history().undo_description(), "Set layers.maxLayers to 3");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.to_text(), original);
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.param("layers", "maxLayers")->value, 3);
}

TEST_F(GraphDocumentTest, RangesAreRespected) {
  GraphDocument doc = load(fixture("graph.json"));
  const EditResult clamped = doc.set_param("layers", "maxLayers", 40);
  ASSERT_TRUE(clamped);
  EXPECT_NE(clamped.message.find("outside 1..32; clamped to 32"), std::string::npos)
      << clamped.message;
  EXPECT_EQ(doc.param("layers", "maxLayers")->value, 32);
  const EditResult low = doc.set_param("tonemap", "exposure", -2.5);
  ASSERT_TRUE(low);
  EXPECT_EQ(doc.param("tonemap", "exposure")->value, 0.0);

  const std::size_t steps = doc.history().undo_count();
  const EditResult rejected = doc.set_param("layers", "maxLayers", 0, RangePolicy::reject);
  EXPECT_FALSE(rejected);
  EXPECT_NE(rejected.message.find("outside 1..32"), std::string::npos) << rejected.message;
  EXPECT_EQ(doc.param("layers", "maxLayers")->value, 32);
  EXPECT_EQ(doc.history().undo_count(), steps);
}

TEST_F(GraphDocumentTest, TypesChoicesAndNamesAreChecked) {
  GraphDocument doc = load(fixture("graph.json"));
  EXPECT_FALSE(doc.set_param("layers", "maxLayers", 2.5));
  EXPECT_FALSE(doc.set_param("layers", "maxLayers", "3"));
  EXPECT_FALSE(doc.set_param("tonemap", "enabled", "yes"));
  EXPECT_FALSE(doc.set_param("tonemap", "exposure", true));
  const EditResult choice = doc.set_param("layers", "order", "dsatr");
  EXPECT_FALSE(choice);
  EXPECT_NE(choice.message.find("did you mean 'dsatur'"), std::string::npos) << choice.message;
  const EditResult name = doc.set_param("layers", "maxLayer", 3);
  EXPECT_FALSE(name);
  EXPECT_NE(name.message.find("did you mean 'maxLayers'"), std::string::npos) << name.message;
  EXPECT_FALSE(doc.set_param("nope", "maxLayers", 3));
  EXPECT_FALSE(doc.can_undo());

  ASSERT_TRUE(doc.set_param("layers", "maxLayers", 3.0));  // an integral number is fine
  EXPECT_TRUE(doc.param("layers", "maxLayers")->value.is_number_integer());
  ASSERT_TRUE(doc.set_param("layers", "order", "smallest-last"));
  const EditResult same = doc.set_param("layers", "order", "smallest-last");
  EXPECT_TRUE(same);
  EXPECT_FALSE(same.changed);
  EXPECT_EQ(doc.history().undo_count(), 2u);
}

TEST_F(GraphDocumentTest, UnknownPassTypesAreShownButNotEdited) {
  GraphDocument doc =
      testing::take(GraphDocument::load(fixture("graph.json"), [](std::string_view) {
        return static_cast<const fg::PassDesc*>(nullptr);
      }));
  const auto passes = doc.passes();
  EXPECT_FALSE(passes[0].known_type);
  ASSERT_EQ(passes[0].params.size(), 2u);  // the file's values, read-only
  EXPECT_FALSE(passes[0].params[0].declared);
  const EditResult result = doc.set_param("layers", "maxLayers", 3);
  EXPECT_FALSE(result);
  EXPECT_NE(result.message.find("unknown"), std::string::npos) << result.message;
}

TEST_F(GraphDocumentTest, NewParamsAreAddedAndRemovedByUndo) {
  const std::string original = read(fixture("graph.json"));
  GraphDocument doc = load(fixture("graph.json"));
  ASSERT_TRUE(doc.set_param("tonemap", "enabled", false));
  ASSERT_TRUE(doc.set_param("lighting", "ambient", 0.5));  // the pass had no "params"
  const base::Json& tonemap = doc.json()["passes"][2]["params"];
  std::vector<std::string> keys;
  for (auto it = tonemap.begin(); it != tonemap.end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"exposure", "operator", "x-unknown", "enabled"}));
  EXPECT_EQ(doc.json()["passes"][1]["params"]["ambient"], 0.5);
  // Still a graph the engine's parser accepts.
  const auto reparsed = base::parse_json(doc.to_text(), "graph.json");
  ASSERT_TRUE(reparsed.ok());
  EXPECT_TRUE(fg::parse_graph(reparsed.value()).ok());

  ASSERT_TRUE(doc.reset_param("tonemap", "exposure"));
  EXPECT_FALSE(doc.param("tonemap", "exposure")->from_file);
  while (doc.undo()) {
  }
  EXPECT_EQ(doc.to_text(), original);
}

TEST_F(GraphDocumentTest, ASliderDragIsOneStep) {
  GraphDocument doc = load(fixture("graph.json"));
  doc.begin_gesture();
  for (int i = 1; i <= 10; ++i) doc.set_param("tonemap", "exposure", 1.0 + 0.1 * i);
  doc.end_gesture();
  EXPECT_EQ(doc.history().undo_count(), 1u);
  doc.undo();
  EXPECT_EQ(doc.param("tonemap", "exposure")->value, 1.0);
}

TEST_F(GraphDocumentTest, SavingWritesTheEditAndNothingElse) {
  testing::ScratchDir dir;
  const auto file = dir.copy(fixture("graph.json"));
  const std::string original = read(file);
  GraphDocument doc = load(file);
  doc.save();  // unchanged: byte-identical
  EXPECT_EQ(read(file), original);
  doc.set_param("tonemap", "exposure", 2.25);
  doc.save();
  EXPECT_FALSE(doc.dirty());
  const auto changed = changed_lines(original, read(file));
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0], "        \"exposure\": 2.25,");
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"graph.json"}));
  EXPECT_EQ(load(file).param("tonemap", "exposure")->value, 2.25);
}

TEST_F(GraphDocumentTest, ShippedGraphsRoundTripByteForByte) {
  testing::ScratchDir dir;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_file("data/graphs"))) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const std::string original = read(entry.path());
    GraphDocument doc = load(dir.copy(entry.path()));
    EXPECT_EQ(doc.to_text(), original);
    doc.save();
    EXPECT_EQ(read(doc.file()), original);
    ++count;
  }
  EXPECT_GE(count, 5);
}

TEST_F(GraphDocumentTest, AHandFormattedGraphKeepsItsLayout) {
  const std::string original = read(source_file("data/graphs/pcss.json"));
  GraphDocument doc = load(source_file("data/graphs/pcss.json"));
  ASSERT_TRUE(doc.set_param("tonemap", "exposure", 1.5));
  ASSERT_TRUE(doc.set_param("lighting", "blockerSearch", 7));
  const auto changed = changed_lines(original, doc.to_text());
  ASSERT_EQ(changed.size(), 2u);
  EXPECT_EQ(changed[0],
            R"(      "params": { "blockerSearch": 7, "kernel": "11", "lightSizeScale": 1.0 },)");
  EXPECT_EQ(changed[1], R"(      "params": { "operator": "aces", "exposure": 1.5 },)");
}

TEST_F(GraphDocumentTest, BadFilesAreLocatedDiagnostics) {
  const auto syntax = GraphDocument::parse("{\n  \"version\": 1,\n  \"passes\": [\n    {\n  ]\n}\n",
                                           "broken.json", lookup_in(registry_));
  ASSERT_FALSE(syntax.ok());
  EXPECT_EQ(syntax.diagnostics()[0].file, "broken.json");
  EXPECT_EQ(syntax.diagnostics()[0].line, 5);
  const auto structure = GraphDocument::parse(
      "{\n  \"version\": 1,\n  \"passes\": [\n    {\"type\": \"tonemap\"}\n  ]\n}\n",
      "nameless.json", lookup_in(registry_));
  ASSERT_FALSE(structure.ok());
  const auto& items = structure.diagnostics().items();
  const auto nameless = std::find_if(items.begin(), items.end(), [](const base::Diagnostic& d) {
    return d.pointer == "/passes/0";
  });
  ASSERT_NE(nameless, items.end()) << structure.diagnostics().to_text();
  EXPECT_EQ(nameless->line, 4);
  EXPECT_EQ(nameless->column, 5);
  const auto missing = GraphDocument::load(fixture("no_such_graph.json"), lookup_in(registry_));
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.diagnostics().find("FG000"), nullptr);
}

}  // namespace
}  // namespace antumbra::editor
