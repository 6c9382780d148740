// Static and dynamic casters, and the update budget, on a device (lavapipe in CI,
// validation and synchronization validation on): a dynamic crate that moves moves its
// shadow, drawn over the static cache, and the image equals a fresh render of the crate
// placed there as static geometry; faces it does not touch are not redrawn; a budget of a
// few faces a frame never shows uninitialised faces nor shadows more than maxStaleFrames
// behind their lights.

#include <cstdint>
#include <vector>

#include "antumbra/scene/light_motion.hpp"
#include "atlas_gpu_fixture.hpp"

namespace {

// A lamp over a floor with a static pillar and a crate that swings and turns beneath it
// (16 frames a cycle); a second light far from the crate's path. All 20 m from the origin,
// so that bounds left in the crate's own space would miss its faces.
constexpr const char* kCrateScene = R"({
  "version": 1,
  "camera": {"position": [20, 4, 6], "target": [20, 0.5, 0]},
  "objects": [
    {"name": "floor", "primitive": "plane", "size": [12, 12], "position": [20, 0, 0]},
    {"name": "pillar", "primitive": "box", "size": [0.5, 2, 0.5], "position": [21.8, 1, -1.2]},
    {"name": "crate", "primitive": "box", "size": [0.6, 0.6, 0.6], "position": [20, 0.8, 0]}
  ],
  "lights": [
    {"name": "lamp", "position": [20.2, 3, 0.3], "range": 8, "size": 0.1},
    {"name": "far", "position": [15.5, 2.5, -3.5], "range": 3}
  ],
  "dynamic": [{"object": "crate", "motion": {"offset": [1.5, 0, 0.6], "spin": 90, "period": 16}}]
})";

struct FaceCounts {
  std::uint32_t rendered = 0, cached = 0, dynamic = 0, over_cache = 0, deferred = 0, forced = 0,
                stalest = 0;
};

class DynamicCastersGpuTest : public AtlasGpuTest {
 protected:
  // data/graphs/hard.json at kFace-texel faces: the hardware rasteriser, or the compute
  // one with an r32f atlas and receiver culling.
  void load_hard(bool compute, const base::Json& params = base::Json::object()) {
    auto document = base::load_json_file((source_dir() / "data/graphs/hard.json").string());
    ASSERT_TRUE(document.ok());
    auto graph = fg::parse_graph(document.value());
    ASSERT_TRUE(graph.ok());
    for (auto& r : graph.value().resources) {
      if (r.name == "atlas") r.size = {false, 1.0, 1.0, kFace, kFace};
      if (r.name == "atlas" && compute) r.format = fg::Format::r32f;
    }
    for (auto& p : graph.value().passes) {
      if (p.type != "point-shadow-atlas") continue;
      p.params.update(params);
      if (compute) {
        p.params["rasterizer"] = "compute";
        p.inputs.push_back({"depth", "depth", p.pointer + "/in/depth"});
      }
    }
    load_desc(graph.value());
  }

  FaceCounts counted_frame() {
    frame();
    FaceCounts c;
    for (const auto& m : report_.messages()) {
      if (m.code != "SHD010") continue;
      const auto& d = m.details;
      c = {d["rendered"].get<std::uint32_t>(),     d["cached"].get<std::uint32_t>(),
           d["dynamic"].get<std::uint32_t>(),      d["overStaticCache"].get<std::uint32_t>(),
           d["deferred"].get<std::uint32_t>(),     d["forced"].get<std::uint32_t>(),
           d["stalestFrames"].get<std::uint32_t>()};
    }
    return c;
  }

  static scene::Scene crate_scene() {
    auto parsed = scene::parse_scene_text(kCrateScene, "crate.json");
    if (!parsed.ok()) throw std::runtime_error(parsed.diagnostics().to_text());
    return std::move(parsed.value());
  }

  // Runs the crate for a few frames, then checks the last image against a fresh render
  // of the crate frozen where it ended.
  void crate_matches_a_fresh_render(bool compute, const base::Json& params = base::Json::object()) {
    scene_ = crate_scene();
    load_hard(compute, params);
    counted_frame();
    const auto start = read_hdr();
    FaceCounts moved;
    for (int i = 0; i < 5; ++i) {
      const FaceCounts c = counted_frame();
      moved.rendered += c.rendered;
      moved.dynamic += c.dynamic;
      moved.over_cache += c.over_cache;
    }
    const auto image = read_hdr();
    EXPECT_NE(image, start) << "the crate and its shadow moved";
    scene_ = frozen();
    load_hard(compute, params);
    frame();
    EXPECT_EQ(read_hdr(), image) << "the shadow drawn over the cache is the crate's, where it is";
    const bool cache = params.value("staticCache", true);
    if (!compute && !cache) {
      EXPECT_EQ(moved.over_cache, 0u);
    }
    if (!compute && cache) {
      EXPECT_GT(moved.dynamic, 0u);
      EXPECT_EQ(moved.dynamic, moved.rendered) << "only the crate's move redrew faces";
      EXPECT_GT(moved.over_cache, 0u) << "the lamp's faces drew the crate over their cache";
      // The lamp's +Y face looks away from the crate and the far light never sees it: at
      // most 5 of the 12 faces are redrawn a frame.
      EXPECT_LE(moved.rendered, 5u * 5u);
    }
  }
};

}  // namespace

TEST_F(DynamicCastersGpuTest, CrateMovesItsShadowOverTheStaticCache) {
  crate_matches_a_fresh_render(false);
}

TEST_F(DynamicCastersGpuTest, CrateMovesItsShadowOnTheComputeRasteriser) {
  crate_matches_a_fresh_render(true);
}

TEST_F(DynamicCastersGpuTest, StaticCacheOffRedrawsWholeFacesToTheSameImage) {
  crate_matches_a_fresh_render(false, {{"staticCache", false}});
}

// Sixteen moving lights on a budget of 12 faces a frame: the first frame draws every face
// (never uninitialised), no shadow falls more than maxStaleFrames behind, and once the
// lights stop every face catches up: the image is a fresh render's.
TEST_F(DynamicCastersGpuTest, BudgetNeverShowsUninitialisedOrTooStaleFaces) {
  const std::vector<scene::PointLight> base = scene_.lights;
  load_hard(false, {{"faceBudget", 12}, {"maxStaleFrames", 2}});
  const FaceCounts first = counted_frame();
  EXPECT_GT(first.forced, 0u) << "every visible face of the first frame is drawn";
  EXPECT_EQ(first.deferred, 0u);
  const auto first_image = read_hdr();
  FaceCounts moving;
  scene::LightMotion motion;
  for (std::uint64_t f = 1; f <= 8; ++f) {
    scene_.lights = scene::animate_lights(base, f, motion);
    const FaceCounts c = counted_frame();
    EXPECT_LE(c.stalest, 2u) << "frame " << f;
    moving.deferred += c.deferred;
    moving.stalest = std::max(moving.stalest, c.stalest);
  }
  EXPECT_GT(moving.deferred, 0u) << "the budget held faces back";
  EXPECT_GT(moving.stalest, 0u);
  for (int i = 0; i < 3; ++i) counted_frame();  // the lights stand: at most 2 frames late
  const auto caught_up = read_hdr();
  load_hard(false);
  frame();
  EXPECT_EQ(read_hdr(), caught_up);
  // And the very first frame was a complete one.
  scene_.lights = base;
  load_hard(false);
  frame();
  EXPECT_EQ(read_hdr(), first_image);
}
