// Structural edits of the graph file (issue 31): each one undo step, written back as a
// splice of the text; connections checked by compiling and refused with the compiler's
// code, the document unchanged, while errors the graph already had refuse nothing.
#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/editor/graph_edits.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "editor_test_support.hpp"
#include "text_diff.hpp"

namespace antumbra::editor {
namespace {

using base::Json;
using testing::fixture;
using testing::read;

// The fixture's layers -> lighting -> tonemap, with a blur pass to wire in: `lighting`
// runs after `blur`, which stands below it, writes `blurred` and reads nothing yet.
constexpr const char* kAfterGraph = R"({
  "version": 1,
  "resources": {
    "table": { "kind": "buffer", "size": 4112 },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "blurred": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "ldr": { "kind": "image", "format": "rgba8", "size": "viewport" }
  },
  "passes": [
    { "name": "layers", "type": "light-layering", "out": { "assignment": "table" } },
    { "name": "lighting", "type": "lighting", "after": ["blur"],
      "in": { "assignment": "table" }, "out": { "hdr": "hdr" } },
    { "name": "blur", "type": "blur", "out": { "dst": "blurred" } },
    { "name": "tonemap", "type": "tonemap", "in": { "hdr": "hdr" }, "out": { "ldr": "ldr" } }
  ],
  "output": "ldr"
}
)";

class GraphEditsTest : public ::testing::Test {
 protected:
  GraphDocument load(const std::filesystem::path& file) {
    return testing::take(GraphDocument::load(file, lookup_in(registry_)));
  }
  GraphDocument parse(const std::string& text) {
    return testing::take(GraphDocument::parse(text, "after.json", lookup_in(registry_)));
  }
  base::Diagnostics errors(const GraphDocument& doc) const {
    const auto plan =
        fg::compile_graph(fg::GraphSource::from_text(doc.to_text(), "g.json"), registry_);
    base::Diagnostics out;
    for (const auto& d : plan.diagnostics()) {
      if (d.severity == base::Severity::error) out.add(d);
    }
    return out;
  }
  // A refused edit leaves the text and the history as they were.
  static void expect_refused(const EditResult& result, const GraphDocument& doc,
                             const std::string& before, const char* code) {
    EXPECT_FALSE(result.ok) << result.message;
    EXPECT_FALSE(result.changed);
    EXPECT_EQ(result.code, code) << result.message;
    EXPECT_EQ(doc.to_text(), before);
  }
  fg::Registry registry_ = testing::make_fake_registry();
};

TEST_F(GraphEditsTest, AddPassAppendsLinesAndIsOneUndoStep) {
  const std::string original = read(fixture("graph.json"));
  GraphDocument doc = load(fixture("graph.json"));
  GraphEdits edits(doc, registry_);
  const EditResult added = edits.add_pass("blur");
  ASSERT_TRUE(added.ok) << added.message;
  EXPECT_TRUE(added.changed);
  const Json& pass = doc.json()["passes"][3];
  EXPECT_EQ(pass, Json::parse(R"({"name": "blur", "type": "blur", "in": {}, "out": {}})"));
  const auto diff = testing::line_diff(original, doc.to_text());
  // The last pass's closing line gains a comma; the new pass's closes the same way.
  EXPECT_TRUE(diff.removed.empty());
  EXPECT_EQ(diff.added, (std::vector<std::string>{"    },", "    {", "      \"name\": \"blur\",",
                                                  "      \"type\": \"blur\",", "      \"in\": {},",
                                                  "      \"out\": {}"}));
  EXPECT_EQ(doc.history().undo_count(), 1u);
  ASSERT_TRUE(edits.add_pass("blur").ok);
  EXPECT_EQ(doc.json()["passes"][4]["name"], "blur2");  // a default name is unique
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.to_text(), original);
}

TEST_F(GraphEditsTest, AddPassRefusesUnknownTypesAndTakenNames) {
  const std::string original = read(fixture("graph.json"));
  GraphDocument doc = load(fixture("graph.json"));
  GraphEdits edits(doc, registry_);
  const EditResult unknown = edits.add_pass("blurr");
  expect_refused(unknown, doc, original, codes::graph::kUnknownPassType);
  EXPECT_NE(unknown.message.find("did you mean 'blur'"), std::string::npos) << unknown.message;
  EXPECT_FALSE(edits.add_pass("blur", "tonemap").ok);
  EXPECT_FALSE(edits.add_pass("blur", "2fast").ok);
  EXPECT_FALSE(doc.can_undo());
}

TEST_F(GraphEditsTest, RemovePassRemovesOnlyItsLines) {
  const std::string original = read(fixture("graph.json"));
  GraphDocument doc = load(fixture("graph.json"));
  GraphEdits edits(doc, registry_);
  // Allowed although tonemap reads what lighting writes: the compiler then says so.
  ASSERT_TRUE(edits.remove_pass("lighting").ok);
  const std::size_t begin = original.find("    {\n      \"name\": \"lighting\"");
  const std::size_t end = original.find("    {\n      \"name\": \"tonemap\"");
  EXPECT_EQ(doc.to_text(), original.substr(0, begin) + original.substr(end));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.to_text(), original);

  ASSERT_TRUE(edits.remove_pass("tonemap").ok);  // the last: the comma above goes
  const auto diff = testing::line_diff(original, doc.to_text());
  EXPECT_TRUE(diff.added.empty());
  EXPECT_EQ(diff.removed.front(), "    },");
  EXPECT_EQ(diff.removed.size(), 16u);  // the comma's line and tonemap's but its last
  EXPECT_FALSE(edits.remove_pass("tonemap").ok);
}

TEST_F(GraphEditsTest, RenameIsAOneLineDiffAndFollowsAfterEntries) {
  const std::string original = read(fixture("graph.json"));
  GraphDocument doc = load(fixture("graph.json"));
  GraphEdits edits(doc, registry_);
  ASSERT_TRUE(edits.rename_pass("tonemap", "finish").ok);
  const auto diff = testing::line_diff(original, doc.to_text());
  EXPECT_EQ(diff.removed, (std::vector<std::string>{"      \"name\": \"tonemap\","}));
  EXPECT_EQ(diff.added, (std::vector<std::string>{"      \"name\": \"finish\","}));
  EXPECT_EQ(doc.history().undo_count(), 1u);

  const std::string before = doc.to_text();
  EXPECT_FALSE(edits.rename_pass("finish", "").ok);
  EXPECT_FALSE(edits.rename_pass("finish", "lighting").ok);
  EXPECT_FALSE(edits.rename_pass("finish", "two words").ok);
  EXPECT_FALSE(edits.rename_pass("nope", "other").ok);
  EXPECT_EQ(doc.to_text(), before);

  GraphDocument after = parse(kAfterGraph);
  GraphEdits after_edits(after, registry_);
  ASSERT_TRUE(after_edits.rename_pass("blur", "soften").ok);
  EXPECT_EQ(after.json()["passes"][1]["after"], Json::parse(R"(["soften"])"));
  const auto before_lines = testing::split_lines(kAfterGraph);
  const auto after_lines = testing::split_lines(after.to_text());
  ASSERT_EQ(before_lines.size(), after_lines.size());
  std::size_t changed = 0;
  for (std::size_t i = 0; i < before_lines.size(); ++i)
    changed += before_lines[i] != after_lines[i];
  EXPECT_EQ(changed, 2u);  // blur's own line and the line of lighting's "after"
  EXPECT_TRUE(errors(after).empty()) << errors(after).to_text();
}

TEST_F(GraphEditsTest, ConnectMakesAResourceAndMovesTheWriterAboveTheReader) {
  GraphDocument doc = load(fixture("graph.json"));
  ASSERT_TRUE(doc.reset_param("tonemap", "x-unknown").ok);  // the one error it has
  ASSERT_TRUE(errors(doc).empty()) << errors(doc).to_text();
  GraphEdits edits(doc, registry_);
  ASSERT_TRUE(edits.add_pass("blur").ok);
  ASSERT_TRUE(edits.connect({"lighting", "hdr"}, {"blur", "src"}).ok);
  const std::size_t steps = doc.history().undo_count();
  const std::string before = doc.to_text();
  // blur stands below tonemap: connecting it into tonemap moves it up, in the same step.
  const EditResult wired = edits.connect({"blur", "dst"}, {"tonemap", "hdr"});
  ASSERT_TRUE(wired.ok) << wired.message;
  EXPECT_EQ(doc.history().undo_count(), steps + 1);
  EXPECT_EQ(doc.json()["resources"]["dst"],
            Json::parse(R"({"kind": "image", "format": "rgba16f", "size": "viewport"})"));
  EXPECT_EQ(doc.json()["passes"][2]["name"], "blur");
  EXPECT_EQ(doc.json()["passes"][2]["out"]["dst"], "dst");
  EXPECT_EQ(doc.json()["passes"][3]["in"]["hdr"], "dst");
  EXPECT_TRUE(errors(doc).empty()) << errors(doc).to_text();
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.to_text(), before);
}

TEST_F(GraphEditsTest, AnImageIntoABufferPortIsRefusedWithTheCompilersCode) {
  GraphDocument doc = load(fixture("graph.json"));
  GraphEdits edits(doc, registry_);
  ASSERT_TRUE(edits.add_pass("blur").ok);  // its unbound output is an error already
  const std::string before = doc.to_text();
  const std::size_t steps = doc.history().undo_count();
  const EditResult check = edits.check_connect({"lighting", "hdr"}, {"blur", "weights"});
  expect_refused(check, doc, before, codes::graph::kPortKind);
  expect_refused(edits.connect({"lighting", "hdr"}, {"blur", "weights"}), doc, before,
                 codes::graph::kPortKind);
  EXPECT_EQ(doc.history().undo_count(), steps);
  // Errors the graph had do not refuse: blur's unbound output stays unbound.
  EXPECT_TRUE(edits.check_connect({"lighting", "hdr"}, {"blur", "src"}).ok);
  EXPECT_EQ(doc.to_text(), before);  // a check changes nothing
}

TEST_F(GraphEditsTest, ACycleIsRefusedWithFG071) {
  GraphDocument doc = parse(kAfterGraph);
  GraphEdits edits(doc, registry_);
  ASSERT_TRUE(errors(doc).empty()) << errors(doc).to_text();
  // lighting runs after blur; blur reading lighting's hdr closes a cycle (the compiler's).
  expect_refused(edits.connect({"lighting", "hdr"}, {"blur", "src"}), doc, kAfterGraph,
                 codes::graph::kCycle);
  // A reader above a writer that depends on it: the editor names the cycle itself.
  ASSERT_TRUE(edits.connect({"blur", "dst"}, {"tonemap", "hdr"}).ok);
  const std::string before = doc.to_text();
  const EditResult cycle = edits.connect({"tonemap", "ldr"}, {"blur", "src"});
  expect_refused(cycle, doc, before, codes::graph::kCycle);
  EXPECT_NE(cycle.message.find("blur -> tonemap (via blurred)"), std::string::npos)
      << cycle.message;
}

TEST_F(GraphEditsTest, ASecondWriterAndAReadOfOnesOwnWriteAreRefused) {
  GraphDocument doc = parse(kAfterGraph);
  GraphEdits edits(doc, registry_);
  expect_refused(edits.bind({"blur", "dst"}, "hdr"), doc, kAfterGraph,
                 codes::editor::kSecondWriter);
  expect_refused(edits.connect({"blur", "dst"}, {"blur", "src"}), doc, kAfterGraph,
                 codes::graph::kReadWriteSamePass);
  expect_refused(edits.bind({"blur", "src"}, "nope"), doc, kAfterGraph,
                 codes::graph::kUnknownResource);
  expect_refused(edits.connect({"blur", "src"}, {"tonemap", "hdr"}), doc, kAfterGraph,
                 codes::graph::kPortDirection);
  ASSERT_TRUE(edits.bind({"tonemap", "hdr"}, "blurred").ok);
  EXPECT_EQ(doc.json()["passes"][3]["in"]["hdr"], "blurred");
}

TEST_F(GraphEditsTest, DisconnectAndCreateResource) {
  GraphDocument doc = parse(kAfterGraph);
  GraphEdits edits(doc, registry_);
  ASSERT_TRUE(edits.disconnect({"tonemap", "hdr"}).ok);
  EXPECT_EQ(doc.json()["passes"][3]["in"], Json::object());
  EXPECT_FALSE(edits.disconnect({"tonemap", "hdr"}).ok);
  ASSERT_TRUE(edits.disconnect({"blur", "dst"}).ok);  // an output too

  // Named after the port, else after the pass and the port; sized like the image the
  // port's contract names.
  ASSERT_TRUE(edits.bind({"blur", "src"}, "hdr").ok);
  const EditResult made = edits.create_resource({"blur", "dst"});
  ASSERT_TRUE(made.ok) << made.message;
  EXPECT_EQ(doc.json()["passes"][2]["out"]["dst"], "dst");
  ASSERT_TRUE(edits.create_resource({"blur", "dst"}).ok);
  EXPECT_EQ(doc.json()["passes"][2]["out"]["dst"], "blur_dst");
  EXPECT_EQ(doc.json()["resources"]["blur_dst"]["size"], "viewport");
  ASSERT_TRUE(edits.create_resource({"layers", "assignment"}).ok);
  EXPECT_EQ(doc.json()["resources"]["assignment"],
            Json::parse(R"({"kind": "buffer", "size": 65536})"));
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.to_text(), kAfterGraph);
}

}  // namespace
}  // namespace antumbra::editor
