// A host's pass type rendered through RenderSession (docs/adding-a-pass.md, "A pass type
// from outside the tree"), with validation + synchronization validation on: the session
// registers "host-tint" and searches the host's shader folder after passes/; a graph that
// uses it tints the frame, and a host shader in no folder is a located diagnostic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "gpu_test_support.hpp"
#include "host_graph.hpp"
#include "render_test_support.hpp"

namespace antumbra::render_testing {
namespace {

namespace fs = std::filesystem;
using host_example::testing::host_options;
using host_example::testing::host_shader_dir;
using host_example::testing::kTintPass;

constexpr int kFrames = 2;

class HostPassRenderTest : public RenderTest {
 protected:
  // The graph with the tint pass, copied beside the test as a host would keep it.
  fs::path write_tinted_graph() {
    fs::path file = dir_.path() / "host-tint.json";
    std::ofstream(file) << host_example::testing::tinted_graph_text(
        {{"tintRed", 1.0}, {"tintGreen", 0.5}, {"tintBlue", 0.25}, {"strength", 1.0}});
    return file;
  }

  gpu::testing::TempDir dir_;
};

TEST_F(HostPassRenderTest, TheHostPassTintsTheFrame) {
  OPEN_SESSION(session, host_options());
  session->set_scene(default_scene());
  load_graph_ok(*session, default_graph());
  session->render(kFrames, nullptr);
  const Image8 plain = to_image8(read_output(*session));

  const fs::path graph = write_tinted_graph();
  const auto diagnostics = session->load_graph(fg::GraphSource::from_file(graph.string()));
  ASSERT_FALSE(diagnostics.has_errors()) << describe(diagnostics);
  session->render(kFrames, nullptr);
  const Image8 tinted = to_image8(read_output(*session));
  expect_no_validation_errors(*session);

  ASSERT_EQ(plain.width, tinted.width);
  ASSERT_EQ(plain.height, tinted.height);
  ASSERT_EQ(plain.channels, tinted.channels);
  // Each channel multiplied by the tint (1, 0.5, 0.25), within a step of rounding.
  const float tint[3] = {1.0f, 0.5f, 0.25f};
  std::size_t off = 0;
  std::size_t lit = 0;  // pixels bright enough in green for the tint to show
  const std::size_t pixels = static_cast<std::size_t>(plain.width) * plain.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t at = i * plain.channels + c;
      const float expected = static_cast<float>(plain.bytes[at]) * tint[c];
      if (std::abs(static_cast<float>(tinted.bytes[at]) - expected) > 1.5f) ++off;
    }
    if (plain.bytes[i * plain.channels + 1] >= 32) ++lit;
  }
  EXPECT_EQ(off, 0u) << "channels not multiplied by the tint";
  EXPECT_GT(lit, pixels / 10) << "the frame is too dark to show a tint";

  // The host's shader and what it includes are watched like the built-in ones.
  const auto files = session->executor().shader_files();
  const auto watched = [&](const std::string& tail) {
    return std::any_of(files.begin(), files.end(),
                       [&](const std::string& f) { return f.ends_with(tail); });
  };
  EXPECT_TRUE(watched("tests/host_pass/shaders/host_tint/host_tint.comp"));
  EXPECT_TRUE(watched("tests/host_pass/shaders/host_tint/host_tint_interface.h"));
  EXPECT_TRUE(watched("passes/interface/shared/workgroups.h"));
  EXPECT_TRUE(watched("passes/tonemap/tonemap.frag"));
  const auto readers = session->executor().passes_reading(
      {(host_shader_dir() / "host_tint" / "host_tint.comp").lexically_normal().string()});
  EXPECT_EQ(readers, std::vector<std::string>{"tint"});
}

TEST_F(HostPassRenderTest, AHostShaderInNoFolderIsALocatedDiagnostic) {
  runtime::SessionOptions options = host_options();
  // A folder without host_tint/: the type is registered, its shader is nowhere.
  const fs::path elsewhere = dir_.path() / "shaders";
  fs::create_directories(elsewhere);
  options.shader_dirs = {elsewhere};
  OPEN_SESSION(session, options);
  session->set_scene(default_scene());
  load_graph_ok(*session, default_graph());

  const fs::path graph = write_tinted_graph();
  const auto diagnostics = session->load_graph(fg::GraphSource::from_file(graph.string()));
  ASSERT_TRUE(diagnostics.has_errors());
  const base::Diagnostic* d = diagnostics.find(codes::shader::kUnreadable);
  ASSERT_NE(d, nullptr) << describe(diagnostics);
  EXPECT_EQ(d->severity, base::Severity::error);
  EXPECT_EQ(d->file, graph.string());
  EXPECT_EQ(d->pointer, "/passes/" + std::to_string(kTintPass) + "/type");
  EXPECT_GT(d->line, 0);
  EXPECT_GT(d->column, 0);
  // The shader, the pass and every folder searched.
  for (const std::string& words :
       {std::string("'host_tint/host_tint.comp'"), std::string("pass 'tint'"),
        base::quote_name((source_dir() / "passes").string()),
        base::quote_name(elsewhere.string())}) {
    EXPECT_NE(d->message.find(words), std::string::npos) << words << " not in: " << d->message;
  }

  // The graph before keeps running.
  EXPECT_EQ(session->executor().plan().name, "deferred");
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
}

}  // namespace
}  // namespace antumbra::render_testing
