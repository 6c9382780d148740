// Reload is a transaction: a graph or shader that fails leaves the last good plan
// running (same image), and the failure comes back as located diagnostics.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "gpu_test_support.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;
namespace fs = std::filesystem;

namespace {

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
}

// Inserts `line` after the first line containing `anchor`; returns its 1-based number.
int insert_line_after(const fs::path& path, const std::string& anchor, const std::string& line) {
  std::istringstream in(read_text(path));
  std::ostringstream out;
  std::string current;
  int number = 0;
  int inserted = 0;
  while (std::getline(in, current)) {
    ++number;
    out << current << '\n';
    if (inserted == 0 && current.find(anchor) != std::string::npos) {
      out << line << '\n';
      inserted = ++number;
    }
  }
  write_text(path, out.str());
  return inserted;
}

bool same_file(const std::string& a, const fs::path& b) {
  std::error_code error;
  return fs::equivalent(fs::path(a), b, error);
}

}  // namespace

class ReloadTest : public RenderTest {};

TEST_F(ReloadTest, BrokenGraphKeepsTheLastGoodPlan) {
  OPEN_SESSION(session, kSmall);
  const fg::GraphDesc good = default_graph();
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, good));
  session->set_scene(default_scene());
  session->render(1, nullptr);
  const auto before = read_output(*session);
  ASSERT_FALSE(is_blank(before));

  struct Broken {
    std::string what;
    fg::GraphDesc graph;
    const char* code;
  };
  std::vector<Broken> broken;
  {
    fg::GraphDesc graph = good;
    graph.passes.at(2).type = "tonemapp";
    broken.push_back({"unknown pass type", graph, codes::graph::kUnknownPassType});
  }
  {
    fg::GraphDesc graph = good;
    graph.output = "nothing";
    broken.push_back({"output names no resource", graph, nullptr});
  }
  {
    fg::GraphDesc graph = good;
    graph.passes.at(1).params["exposure"] = 100.0;  // range [0, 16]
    broken.push_back({"parameter out of range", graph, nullptr});
  }
  for (const auto& [what, graph, code] : broken) {
    SCOPED_TRACE(what);
    const auto diagnostics = session->load_graph(graph);
    EXPECT_TRUE(diagnostics.has_errors());
    if (code != nullptr) {
      EXPECT_NE(diagnostics.find(code), nullptr) << describe(diagnostics);
    }
    ASSERT_TRUE(session->executor().loaded());
    const fg::Plan& plan = session->executor().plan();
    EXPECT_EQ(plan.name, "deferred");
    EXPECT_EQ(plan.passes.size(), 3u);
    EXPECT_EQ(plan.resources.at(static_cast<std::size_t>(plan.output)).name, "ldr");
    session->render(1, nullptr);
    expect_no_validation_errors(*session);
    EXPECT_TRUE(read_output(*session).texels == before.texels) << "image changed";
  }
}

// A shader with a syntax error, in a copy of passes/: the session started from that
// root keeps its previous plan; the diagnostic is SH001 at the edited file and line.
// Fixing the file and reloading recovers.
TEST_F(ReloadTest, ShaderErrorKeepsTheLastGoodPlan) {
  gpu::testing::TempDir root;
  copy_tree(source_dir() / "passes", root.path() / "passes");
  const fs::path tonemap = root.path() / "passes" / "tonemap" / "tonemap.frag";
  const std::string original = read_text(tonemap);

  OPEN_SESSION(session, kSmall, runtime::DataPaths{root.path()});
  const fg::GraphDesc graph = default_graph();
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, graph));
  session->set_scene(default_scene());
  session->render(1, nullptr);
  const auto before = read_output(*session);
  ASSERT_FALSE(is_blank(before));

  const int line = insert_line_after(tonemap, "void main() {", "  vec3 broken = ;");
  ASSERT_GT(line, 0) << "tonemap.frag has no 'void main() {' line";
  const auto diagnostics = session->load_graph(graph);
  ASSERT_TRUE(diagnostics.has_errors());
  const base::Diagnostic* error = diagnostics.find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr) << describe(diagnostics);
  EXPECT_TRUE(same_file(error->file, tonemap)) << error->file << " is not " << tonemap;
  EXPECT_EQ(error->line, line) << base::format_text(*error);
  EXPECT_EQ(error->severity, base::Severity::error);

  ASSERT_TRUE(session->executor().loaded());
  EXPECT_EQ(session->executor().plan().passes.size(), 3u);
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
  EXPECT_TRUE(read_output(*session).texels == before.texels) << "image changed";

  write_text(tonemap, original);
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, graph));
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
  EXPECT_TRUE(read_output(*session).texels == before.texels) << "image changed after the fix";
}

// With no previous plan, a shader error leaves the session without one.
TEST_F(ReloadTest, ShaderErrorOnFirstLoadLoadsNothing) {
  gpu::testing::TempDir root;
  copy_tree(source_dir() / "passes", root.path() / "passes");
  const fs::path tonemap = root.path() / "passes" / "tonemap" / "tonemap.frag";
  const int line = insert_line_after(tonemap, "void main() {", "  vec3 broken = ;");
  ASSERT_GT(line, 0);

  OPEN_SESSION(session, kSmall, runtime::DataPaths{root.path()});
  const auto diagnostics = session->load_graph(default_graph());
  const base::Diagnostic* error = diagnostics.find(codes::shader::kCompile);
  ASSERT_NE(error, nullptr) << describe(diagnostics);
  EXPECT_TRUE(same_file(error->file, tonemap)) << error->file;
  EXPECT_EQ(error->line, line);
  EXPECT_FALSE(session->executor().loaded());
}

// Resources whose description did not change move to the new plan with their contents:
// the same VkImage, the cached shadow atlas still valid (nothing flashes); a resource
// whose size changed is reallocated. A failed load hands nothing over.
TEST_F(ReloadTest, UnchangedResourcesKeepTheirImagesAcrossAReload) {
  OPEN_SESSION(session, kSmall);
  session->set_scene(default_scene());
  auto graph = load_graph_file(source_dir() / "data" / "graphs" / "layered-ssss.json");
  load_graph_ok(*session, graph);
  session->render(2, nullptr);
  const VkImage atlas = session->executor().image("atlas")->image;
  const VkImage penumbra = session->executor().image("penumbra")->image;
  const auto atlas_texels = read_resource(*session, "atlas", 30).texels;

  for (auto& p : graph.passes) {
    if (p.type == "anisotropic-blur") p.params["kernel"] = "5";
  }
  for (auto& r : graph.resources) {
    // 8 layers of storage: new images
    if (r.name == "penumbra" || r.name == "shadowH" || r.name == "shadow") r.layers = 2;
  }
  load_graph_ok(*session, graph);
  EXPECT_GE(session->executor().kept_resources(), 3u) << "atlas, shadowColour and the output";
  EXPECT_EQ(session->executor().image("atlas")->image, atlas) << "the atlas was reallocated";
  EXPECT_NE(session->executor().image("penumbra")->image, penumbra);
  EXPECT_EQ(read_resource(*session, "atlas", 30).texels, atlas_texels)
      << "the kept atlas lost its contents";
  session->render(2, nullptr);
  EXPECT_EQ(session->executor().image("atlas")->image, atlas);

  auto broken = graph;
  broken.passes.front().type = "no-such-pass";
  EXPECT_TRUE(session->load_graph(broken).has_errors());
  EXPECT_EQ(session->executor().image("atlas")->image, atlas);
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
}

namespace {

// The point-shadow-atlas report of the last frame: faces drawn.
std::uint32_t faces_rendered(const runtime::RenderSession& session) {
  for (const auto& m : session.last_report().messages()) {
    if (m.code == "SHD010") return m.details["rendered"].get<std::uint32_t>();
  }
  ADD_FAILURE() << "no SHD010 note from the atlas pass";
  return 0;
}

}  // namespace

// A reload that leaves the atlas as it was (the blur changes) keeps its static cache:
// the first frame after the swap draws no face and matches a fresh session's frame of
// the new graph exactly. A change to how faces are drawn (the depth bias) draws them all.
TEST_F(ReloadTest, TheShadowCacheSurvivesAReloadThatLeavesTheAtlasAlone) {
  OPEN_SESSION(session, kSmall);
  session->set_scene(default_scene());
  auto graph = load_graph_file(source_dir() / "data" / "graphs" / "layered-ssss.json");
  load_graph_ok(*session, graph);
  session->render(2, nullptr);
  EXPECT_EQ(faces_rendered(*session), 0u) << "a still scene should be all cached";
  for (auto& p : graph.passes) {
    if (p.type == "anisotropic-blur") p.params["kernel"] = "23";
  }
  load_graph_ok(*session, graph);
  session->render(1, nullptr);
  EXPECT_EQ(faces_rendered(*session), 0u) << "the reload threw the shadow cache away";
  const auto after_reload = read_output(*session);

  OPEN_SESSION(fresh, kSmall);
  fresh->set_scene(default_scene());
  load_graph_ok(*fresh, graph);
  fresh->render(1, nullptr);
  EXPECT_GT(faces_rendered(*fresh), 0u);
  EXPECT_EQ(max_abs_difference(read_output(*fresh), after_reload), 0.0f)
      << "the adopted cache differs from drawing every face";

  for (auto& p : graph.passes) {
    if (p.type == "point-shadow-atlas") p.params["depthBias"] = 2.5;
  }
  load_graph_ok(*session, graph);
  EXPECT_GE(session->executor().kept_resources(), 3u);
  session->render(1, nullptr);
  EXPECT_GT(faces_rendered(*session), 0u) << "other biases must draw the faces again";
  expect_no_validation_errors(*session);
  expect_no_validation_errors(*fresh);
}

// A reload re-creates the passes and the transient buffers (shadowData, pageTables) while
// the atlas and its page pool are adopted, cached pages included. The atlas pass once wrote
// only the face records lights own into the new shadowData, trusting the rest to read "no
// owner" from earlier frames: in the new buffer they were whatever its memory held, and the
// min filter over the page pool took such records for faces and wrote over real pages.
// Which memory the new buffer got alternated with the frame slot: every other reload of
// page-pool-min.json differed from a fresh load (105 of 20,736 channels here), which made
// ContractSweepTest fail now and then.
TEST_F(ReloadTest, AReloadedPagedGraphRendersWhatAFreshLoadDoes) {
  constexpr VkExtent2D kTiny{96, 54};
  OPEN_SESSION(session, kTiny);
  session->set_scene(load_scene(gpu_data_dir() / "contract_sweep.json"));
  const auto graph = load_graph_file(source_dir() / "data" / "graphs" / "page-pool-min.json");
  load_graph_ok(*session, graph);
  session->render(1, nullptr);
  const auto fresh = read_output(*session);
  for (std::uint32_t reload = 1; reload <= 3; ++reload) {
    SCOPED_TRACE("reload " + std::to_string(reload));
    load_graph_ok(*session, graph);
    EXPECT_GE(session->executor().kept_resources(), 2u) << "the atlas and its maps are kept";
    session->render(1, nullptr);
    EXPECT_EQ(faces_rendered(*session), 0u) << "the reload threw the page cache away";
    EXPECT_EQ(max_abs_difference(read_output(*session), fresh), 0.0f);
  }
  expect_no_validation_errors(*session);
}

namespace {

// Resident set size of this process in bytes (Linux), 0 when unknown.
std::size_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  std::size_t resident = 0;
  statm >> pages >> resident;
  return resident * 4096u;
}

}  // namespace

// The soak of issue 4: 200 reloads alternating a valid graph (a parameter changes, so
// every pass is re-prepared) and an invalid one, one frame after each. Bounds: after the
// GPU drained, device memory, allocator blocks and dedicated allocations are exactly
// what they were after the first reloads; every valid reload destroys as many objects
// as the previous one (nothing accumulates); nothing waits in the destruction queue;
// and the process grows by less than 32 MiB (allocator caches, glslang pools).
TEST_F(ReloadTest, SoakOf200ReloadsLeaksNothing) {
  OPEN_SESSION(session, kSmall);
  auto graph = load_graph_file(source_dir() / "data" / "graphs" / "layered-ssss.json");
  session->set_scene(default_scene());
  load_graph_ok(*session, graph);
  session->render(1, nullptr);
  auto broken = graph;
  broken.passes.back().type = "no-such-pass";

  auto& gpu = session->gpu();
  VkDeviceSize bytes_after_warmup = 0;
  std::size_t blocks_after_warmup = 0;
  std::size_t dedicated_after_warmup = 0;
  std::size_t rss_after_warmup = 0;
  std::uint64_t destroyed_before = 0;
  std::vector<std::uint64_t> destroyed_per_reload;
  constexpr int kReloads = 200;
  constexpr int kWarmup = 10;
  for (int i = 0; i < kReloads; ++i) {
    const bool valid = i % 2 == 0;
    if (valid) {
      for (auto& p : graph.passes) {
        if (p.type == "anisotropic-blur") p.params["depthThreshold"] = 0.02 + 0.0001 * i;
      }
      load_graph_ok(*session, graph);
    } else {
      ASSERT_TRUE(session->load_graph(broken).has_errors());
    }
    session->render(1, nullptr);
    if (valid && i >= kWarmup) {
      gpu.wait_idle();
      destroyed_per_reload.push_back(gpu.destroyed_count() - destroyed_before);
    }
    if (valid) destroyed_before = gpu.destroyed_count();
    if (i == kWarmup) {
      gpu.wait_idle();
      bytes_after_warmup = gpu.allocator().allocated_bytes();
      blocks_after_warmup = gpu.allocator().block_count();
      dedicated_after_warmup = gpu.allocator().dedicated_count();
      rss_after_warmup = resident_bytes();
      destroyed_before = gpu.destroyed_count();
    }
  }
  gpu.wait_idle();
  EXPECT_EQ(gpu.pending_destruction_count(), 0u);
  EXPECT_EQ(gpu.allocator().allocated_bytes(), bytes_after_warmup);
  EXPECT_EQ(gpu.allocator().block_count(), blocks_after_warmup);
  EXPECT_EQ(gpu.allocator().dedicated_count(), dedicated_after_warmup);
  ASSERT_FALSE(destroyed_per_reload.empty());
  const auto [low, high] =
      std::minmax_element(destroyed_per_reload.begin() + 1, destroyed_per_reload.end());
  EXPECT_EQ(*low, *high) << "objects destroyed per valid reload vary: something accumulates";
  const std::size_t rss = resident_bytes();
  const double growth_mib =
      (static_cast<double>(rss) - static_cast<double>(rss_after_warmup)) / (1024.0 * 1024.0);
  std::printf(
      "soak: %d reloads, device memory %llu bytes (unchanged), %llu objects destroyed "
      "per valid reload, RSS growth %.1f MiB\n",
      kReloads, static_cast<unsigned long long>(gpu.allocator().allocated_bytes()),
      static_cast<unsigned long long>(*high), growth_mib);
  RecordProperty("rss_growth_mib", std::to_string(growth_mib));
  EXPECT_LT(growth_mib, 32.0);
  expect_no_validation_errors(*session);
}
