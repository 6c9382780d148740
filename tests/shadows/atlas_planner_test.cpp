// Slot assignment, culling counts and cache-invalidation rules of the point-shadow
// atlas (passes/point_shadow_atlas/atlas_planner.*), plus the pass's reflection. CPU only.

#include "point_shadow_atlas/atlas_planner.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "antumbra/scene/scene_file.hpp"
#include "atrium_scene.hpp"
#include "common/shadow_faces.hpp"
#include "point_shadow_atlas/point_shadow_atlas_pass.hpp"
#include "point_shadow_atlas/pool_fit.hpp"

using namespace antumbra;
using passes::AtlasPlanner;
using passes::AtlasSettings;

namespace {

glm::mat4 camera_of(const scene::Scene& s) {
  return s.camera.view_projection(16.0f / 9.0f);
}

AtlasSettings settings(std::uint32_t layers = 96) {
  AtlasSettings s;
  s.layers = layers;
  s.face_size = 256;
  return s;
}

std::uint32_t visible_count(const scene::Scene& s, std::size_t light) {
  const auto frustum = passes::shadow_faces::camera_frustum(camera_of(s));
  const auto mask =
      passes::shadow_faces::visible_faces(frustum, s.lights[light].position, s.lights[light].range);
  return static_cast<std::uint32_t>(__builtin_popcount(mask));
}

}  // namespace

TEST(AtlasPlanner, FirstFrameRendersEveryVisibleFaceOfAtrium) {
  const auto scene = test::atrium_scene();
  AtlasPlanner planner;
  const auto& f = planner.plan(scene, camera_of(scene), 1, 0, settings());
  EXPECT_TRUE(f.clear_all);
  EXPECT_EQ(f.stats.total, 96u);
  EXPECT_GT(f.stats.culled, 0u) << "the atrium camera cannot see behind itself";
  EXPECT_LT(f.stats.culled, 96u);
  EXPECT_EQ(f.stats.rendered + f.stats.culled, 96u);
  EXPECT_EQ(f.stats.cached, 0u);
  EXPECT_EQ(f.render_layers.size(), f.stats.rendered);
  EXPECT_TRUE(std::is_sorted(f.render_layers.begin(), f.render_layers.end()));
  ASSERT_EQ(f.lights.size(), 16u);
  for (std::uint32_t i = 0; i < 16; ++i) {
    EXPECT_EQ(f.lights[i].params.z, static_cast<float>(6 * i));
    EXPECT_EQ(f.faces[6 * i + 3].info.x, i);
    EXPECT_EQ(passes::face_of(f.faces[6 * i + 3]), 3u);
    EXPECT_EQ(passes::face_place(f.faces[6 * i + 3]).layer, 6 * i + 3);
  }
  EXPECT_EQ(f.header.counts.x, 16u);
  EXPECT_EQ(f.header.counts.y, 96u);
  EXPECT_EQ(f.header.counts.z, 256u);
}

TEST(AtlasPlanner, UnchangedSecondFrameRendersNothing) {
  const auto scene = test::atrium_scene();
  AtlasPlanner planner;
  const auto rendered = planner.plan(scene, camera_of(scene), 1, 0, settings()).stats.rendered;
  const auto& f = planner.plan(scene, camera_of(scene), 1, 1, settings());
  EXPECT_FALSE(f.clear_all);
  EXPECT_EQ(f.stats.rendered, 0u);
  EXPECT_EQ(f.stats.cached, rendered);
  EXPECT_TRUE(f.render_layers.empty());
}

TEST(AtlasPlanner, MovingOneLightRerendersOnlyItsVisibleFaces) {
  auto scene = test::atrium_scene();
  AtlasPlanner planner;
  planner.plan(scene, camera_of(scene), 1, 0, settings());
  scene.lights[5].position.x += 0.25f;
  const auto& f = planner.plan(scene, camera_of(scene), 1, 1, settings());
  EXPECT_EQ(f.stats.rendered, visible_count(scene, 5));
  for (std::uint32_t layer : f.render_layers) {
    EXPECT_GE(layer, 30u);
    EXPECT_LT(layer, 36u);
  }
  scene.lights[5].range += 0.5f;  // the range is the far plane: new depths
  EXPECT_EQ(planner.plan(scene, camera_of(scene), 1, 2, settings()).stats.rendered,
            visible_count(scene, 5));
}

TEST(AtlasPlanner, GeometryChangeOrInvalidateRerendersEverything) {
  const auto scene = test::atrium_scene();
  AtlasPlanner planner;
  const auto first = planner.plan(scene, camera_of(scene), 1, 0, settings()).stats.rendered;
  EXPECT_EQ(planner.plan(scene, camera_of(scene), 2, 1, settings()).stats.rendered, first);
  EXPECT_EQ(planner.plan(scene, camera_of(scene), 2, 2, settings()).stats.rendered, 0u);
  planner.invalidate();
  const auto& f = planner.plan(scene, camera_of(scene), 2, 3, settings());
  EXPECT_TRUE(f.clear_all);
  EXPECT_EQ(f.stats.rendered, first);
}

TEST(AtlasPlanner, CacheOffRendersEveryVisibleFaceEachFrame) {
  const auto scene = test::atrium_scene();
  AtlasPlanner planner;
  auto s = settings();
  s.cache = false;
  const auto first = planner.plan(scene, camera_of(scene), 1, 0, s).stats.rendered;
  const auto& f = planner.plan(scene, camera_of(scene), 1, 1, s);
  EXPECT_EQ(f.stats.rendered, first);
  EXPECT_EQ(f.stats.cached, 0u);
}

TEST(AtlasPlanner, CulledFaceIsRenderedWhenItComesIntoView) {
  auto scene = test::atrium_scene();
  AtlasPlanner planner;
  const auto& first = planner.plan(scene, camera_of(scene), 1, 0, settings());
  const auto culled = first.stats.culled;
  ASSERT_GT(culled, 0u);
  // Look from the other end of the nave: faces culled before are needed now and were
  // never drawn.
  auto turned = scene;
  turned.camera.position = {14.2f, 1.7f, 0.0f};
  turned.camera.target = {0.0f, 2.2f, 0.0f};
  const auto& second = planner.plan(turned, camera_of(turned), 1, 1, settings());
  EXPECT_GT(second.stats.rendered, 0u);
  // Faces seen from both views were drawn once and are cached now.
  EXPECT_GT(second.stats.cached, 0u);
  // Back to the first view: everything it needs is still valid.
  const auto& third = planner.plan(scene, camera_of(scene), 1, 2, settings());
  EXPECT_EQ(third.stats.rendered, 0u);
  EXPECT_EQ(third.stats.culled, culled);
}

TEST(AtlasPlanner, CullingOffKeepsEveryFace) {
  const auto scene = test::atrium_scene();
  AtlasPlanner planner;
  auto s = settings();
  s.cull_faces = false;
  const auto& f = planner.plan(scene, camera_of(scene), 1, 0, s);
  EXPECT_EQ(f.stats.culled, 0u);
  EXPECT_EQ(f.stats.rendered, 96u);
}

TEST(AtlasPlanner, LightsThatDoNotFitAreNamedAndGetNoLayers) {
  auto scene = test::atrium_scene();
  scene.lights[1].casts_shadows = false;
  AtlasPlanner planner;
  const auto& f = planner.plan(scene, camera_of(scene), 1, 0, settings(18));  // 3 slots
  EXPECT_EQ(f.lights[0].params.z, 0.0f);
  EXPECT_EQ(f.lights[1].params.z, -1.0f);  // casts no shadows: skipped, takes no slot
  EXPECT_EQ(f.lights[2].params.z, 6.0f);
  EXPECT_EQ(f.lights[3].params.z, 12.0f);
  ASSERT_EQ(f.unshadowed.size(), 12u);
  EXPECT_EQ(f.unshadowed.front(), "l04");
  EXPECT_EQ(f.unshadowed.back(), "l15");
  for (std::size_t i = 4; i < 16; ++i) EXPECT_EQ(f.lights[i].params.z, -1.0f);
  EXPECT_EQ(f.stats.total, 18u);
}

TEST(AtlasPlanner, ReassignedSlotIsRerendered) {
  auto scene = test::atrium_scene();
  AtlasPlanner planner;
  planner.plan(scene, camera_of(scene), 1, 0, settings());
  scene.lights[0].casts_shadows = false;  // every later light moves down one slot
  const auto& f = planner.plan(scene, camera_of(scene), 1, 1, settings());
  EXPECT_EQ(f.stats.total, 90u);
  EXPECT_EQ(f.stats.cached, 0u);
  EXPECT_EQ(f.faces[90].info.x, 0xFFFFFFFFu);  // the freed last slot holds no light
}

TEST(PointShadowAtlasReflection, PortsAndParams) {
  const auto desc = passes::PointShadowAtlasPass::describe();
  EXPECT_EQ(desc.type, "point-shadow-atlas");
  const auto* atlas = desc.find_port("atlas");
  ASSERT_NE(atlas, nullptr);
  EXPECT_EQ(atlas->access, fg::Access::depth_attachment);
  EXPECT_EQ(atlas->min_layers, 6u);
  EXPECT_EQ(atlas->max_layers, 0u);
  const auto* colour = desc.find_port("colour");
  ASSERT_NE(colour, nullptr);
  EXPECT_TRUE(colour->optional);
  const auto* data = desc.find_port("shadowData");
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(data->kind, fg::ResourceKind::buffer);
  EXPECT_EQ(data->access, fg::Access::transfer_dst);
  const auto* depth = desc.find_port("depth");
  ASSERT_NE(depth, nullptr);
  EXPECT_TRUE(depth->optional);
  EXPECT_EQ(depth->direction, fg::PortDirection::input);
  // Under the compute rasteriser the GPU's face decision writes the shadow data.
  ASSERT_NE(desc.port_use, nullptr);
  const auto use =
      desc.port_use(*data, base::Json{{"rasterizer", "compute"}}, fg::Format::undefined);
  ASSERT_TRUE(use.has_value());
  EXPECT_EQ(use->access, fg::Access::storage_write);
  EXPECT_EQ(use->stage, fg::Stage::compute);
  EXPECT_FALSE(desc.port_use(*data, base::Json::object(), fg::Format::undefined).has_value());
  for (const char* name : {"nearPlane", "depthBias", "slopeBias", "cullFaces", "cache",
                           "translucentColour", "layeredDraw", "receiverCulling"}) {
    const auto* p = desc.find_param(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_FALSE(p->description.empty()) << name;
  }
  EXPECT_EQ(passes::shadow_data_bytes(96), 269840u);
}

TEST(AtlasPlanner, LayersAreAllocatedByLightType) {
  // Point 6 layers, spot 1, the sun one per cascade, in light order; the type is passed
  // to consumers.
  scene::Scene s = test::atrium_scene();
  s.lights.resize(3);
  s.lights[1].type = scene::LightType::spot;
  s.lights[1].direction = {0.0f, -1.0f, 0.0f};
  s.lights[1].spot_outer = 30.0f;
  s.lights[2].type = scene::LightType::directional;
  s.lights[2].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  s.lights[2].size = 0.5f;
  s.lights.push_back(s.lights[0]);
  s.lights[3].name = "last point";
  AtlasPlanner planner;
  AtlasSettings st = settings(17);
  st.cull_faces = false;
  const auto& f = planner.plan(s, camera_of(s), 1, 0, st);
  EXPECT_EQ(f.lights[0].params.z, 0.0f);
  EXPECT_EQ(f.lights[1].params.z, 6.0f);
  EXPECT_EQ(f.lights[2].params.z, 7.0f);
  EXPECT_EQ(f.lights[3].params.z, 11.0f);
  EXPECT_EQ(f.stats.total, 17u);
  EXPECT_EQ(f.lights[0].direction_type.w, passes::kLightTypePoint);
  EXPECT_EQ(f.lights[1].direction_type.w, passes::kLightTypeSpot);
  EXPECT_EQ(f.lights[2].direction_type.w, passes::kLightTypeDirectional);
  EXPECT_NEAR(f.lights[1].projection.x, std::tan(glm::radians(30.0f)), 1e-6f);
  EXPECT_NEAR(f.lights[2].params.x, std::tan(glm::radians(0.5f)), 1e-7f);  // tan(angle)
  EXPECT_GT(f.lights[2].projection.x, 0.0f);                               // half width
  EXPECT_NEAR(f.lights[2].projection.w, 4.1f, 1e-6f) << "4 cascades, blend band 0.1";
  EXPECT_EQ(f.lights[0].projection.w, 0.0f) << "only the sun has cascades";
  for (std::uint32_t c = 0; c < 4; ++c) {
    EXPECT_EQ(f.faces[7 + c].info.x, 2u);
    EXPECT_EQ(passes::face_of(f.faces[7 + c]), c);
  }
  // One layer short: the last point light goes unshadowed, the others keep theirs.
  const auto& g = planner.plan(s, camera_of(s), 1, 1, settings(16));
  EXPECT_EQ(g.lights[3].params.z, -1.0f);
  ASSERT_EQ(g.unshadowed.size(), 1u);
  EXPECT_EQ(g.unshadowed[0], "last point");
  // Two layers left for the sun: it keeps two cascades rather than losing its shadow.
  const auto& h = planner.plan(s, camera_of(s), 1, 2, settings(9));
  EXPECT_EQ(h.lights[2].params.z, 7.0f);
  EXPECT_EQ(std::floor(h.lights[2].projection.w), 2.0f);
  EXPECT_EQ(h.faces[8].info.x, 2u);
}

TEST(AtlasPlanner, SunIsRefittedWhenTheCameraMoves) {
  scene::Scene s = test::atrium_scene();
  s.lights.resize(1);
  s.lights[0].type = scene::LightType::directional;
  s.lights[0].direction = {0.0f, -1.0f, 0.0f};
  AtlasPlanner planner;
  planner.plan(s, camera_of(s), 1, 0, settings(6));
  EXPECT_EQ(planner.plan(s, camera_of(s), 1, 1, settings(6)).stats.cached, 4u);
  s.camera.position += glm::vec3(3.0f, 0.0f, 0.0f);
  s.camera.target += glm::vec3(3.0f, 0.0f, 0.0f);
  EXPECT_EQ(planner.plan(s, camera_of(s), 1, 2, settings(6)).stats.rendered, 4u);
}

// Receiver culling: the GPU decides what is drawn, the planner hands it every visible face
// and the epoch each layer should hold, which changes only with the face.
TEST(AtlasPlanner, GpuDecisionGetsEveryVisibleFaceAndStableEpochs) {
  auto scene = test::atrium_scene();
  AtlasPlanner planner;
  AtlasSettings s = settings();
  s.gpu_decides = true;
  const auto first = planner.plan(scene, camera_of(scene), 1, 0, s);
  EXPECT_EQ(first.stats.candidates + first.stats.culled, 96u);
  EXPECT_EQ(first.render_layers.size(), first.stats.candidates);
  EXPECT_EQ(first.stats.rendered, 0u) << "the GPU counts what it draws";
  for (const std::uint32_t epoch : first.epochs) EXPECT_NE(epoch, 0u);
  const auto second = planner.plan(scene, camera_of(scene), 1, 1, s);
  EXPECT_EQ(second.render_layers, first.render_layers) << "candidates again: the GPU may skip";
  EXPECT_EQ(second.epochs, first.epochs) << "nothing changed: the same contents";
  scene.lights[3].position.x += 0.5f;
  const auto moved = planner.plan(scene, camera_of(scene), 1, 2, s);
  for (std::uint32_t layer = 0; layer < 96; ++layer) {
    if (layer / 6 == 3) {
      EXPECT_NE(moved.epochs[layer], second.epochs[layer]) << "layer " << layer;
    } else {
      EXPECT_EQ(moved.epochs[layer], second.epochs[layer]) << "layer " << layer;
    }
  }
  s.cache = false;
  const auto uncached = planner.plan(scene, camera_of(scene), 1, 3, s);
  for (std::uint32_t layer = 0; layer < 96; ++layer) {
    EXPECT_NE(uncached.epochs[layer], moved.epochs[layer]) << "no cache: redrawn each frame";
  }
}

// The CPU's own decision gives a drawn face a new epoch and keeps a cached face's.
TEST(AtlasPlanner, DrawnFacesGetNewEpochsCachedOnesKeepTheirs) {
  auto scene = test::atrium_scene();
  AtlasPlanner planner;
  const auto first = planner.plan(scene, camera_of(scene), 1, 0, settings());
  const auto second = planner.plan(scene, camera_of(scene), 1, 1, settings());
  EXPECT_EQ(second.epochs, first.epochs);
  scene.lights[3].position.x += 0.5f;
  const auto moved = planner.plan(scene, camera_of(scene), 1, 2, settings());
  for (const std::uint32_t layer : moved.render_layers) {
    EXPECT_NE(moved.epochs[layer], second.epochs[layer]);
  }
  EXPECT_FALSE(moved.render_layers.empty());
  for (std::uint32_t layer = 0; layer < 96; ++layer) {
    if (layer / 6 != 3) {
      EXPECT_EQ(moved.epochs[layer], second.epochs[layer]) << "layer " << layer;
    }
  }
}

// A page pool (docs/technique.md, "Page pool"): six layers cannot hold the atrium's 96
// faces at 256^2 in squares, so faces are drawn smaller; in a pool every light keeps its
// size, has no square (projection.z < 0) and each record names its page table's first
// word (record x (256 / 128)^2) above its face number.
TEST(AtlasPlanner, APagePoolGivesEveryLightItsSizeAndATable) {
  const auto scene = test::atrium_scene();
  AtlasSettings s = settings(6);
  s.records = 96;
  s.gpu_decides = true;
  AtlasPlanner squares;
  const auto packed = squares.plan(scene, camera_of(scene), 1, 0, s);
  EXPECT_FALSE(packed.degraded.empty()) << "six layers hold fewer faces at their size";
  s.page_pool = true;
  AtlasPlanner pool;
  const auto paged = pool.plan(scene, camera_of(scene), 1, 0, s);
  EXPECT_TRUE(paged.degraded.empty());
  EXPECT_TRUE(paged.unshadowed.empty());
  for (const auto& light : paged.lights) {
    EXPECT_EQ(light.projection.y, 256.0f);
    EXPECT_LT(light.projection.z, 0.0f);
  }
  for (std::uint32_t record = 0; record < 96; ++record) {
    const std::uint32_t info = paged.faces[record].info.y;
    EXPECT_EQ(info >> ANTUMBRA_FACE_LAYER_SHIFT, record * 4) << "record " << record;
    EXPECT_EQ(info & 7u, record % 6) << "record " << record;
    EXPECT_EQ(passes::face_size(paged, record), 256u);
  }
}

// A frame resets only the records lights owned on the last one (a graph's records past
// its lights cost nothing): records a light gives up read "no owner" again, with no
// epoch, as a planner that starts anew gives them, and are owned again when lights come
// back; the GPU takes the records owned now or on the last frame (every one at first).
TEST(AtlasPlanner, RecordsLightsGiveUpReadUnownedAndComeBack) {
  auto scene = test::atrium_scene();
  AtlasSettings s = settings(32);
  s.face_size = 1024;
  s.records = 6144;
  s.gpu_decides = true;
  s.page_pool = true;
  AtlasPlanner planner;
  const auto all = planner.plan(scene, camera_of(scene), 1, 0, s);
  const auto owned = static_cast<std::uint32_t>(scene.lights.size()) * 6;
  ASSERT_EQ(all.faces.size(), 6144u);
  EXPECT_EQ(all.live_records, 6144u) << "a first frame: the GPU takes every record once";
  for (std::uint32_t record = 0; record < owned; ++record) {
    EXPECT_EQ(all.faces[record].info.x, record / 6) << "record " << record;
  }
  auto fewer = scene;
  fewer.lights.resize(4);
  const auto few = planner.plan(fewer, camera_of(fewer), 1, 1, s);
  EXPECT_EQ(few.live_records, owned) << "the records given up read \"no owner\" once more";
  AtlasPlanner fresh;
  const auto expected = fresh.plan(fewer, camera_of(fewer), 1, 1, s);
  for (std::uint32_t record = 24; record < 6144; ++record) {
    EXPECT_EQ(few.faces[record].info, expected.faces[record].info) << "record " << record;
    EXPECT_EQ(few.faces[record].info.x, 0xFFFFFFFFu) << "record " << record;
    EXPECT_EQ(few.faces[record].view_proj, expected.faces[record].view_proj) << "record " << record;
    EXPECT_EQ(few.epochs[record], 0u) << "record " << record;
  }
  EXPECT_EQ(planner.plan(fewer, camera_of(fewer), 1, 2, s).live_records, 24u)
      << "then only the four lights' records";
  const auto back = planner.plan(scene, camera_of(scene), 1, 3, s);
  for (std::uint32_t record = 0; record < owned; ++record) {
    EXPECT_EQ(back.faces[record].info.x, record / 6) << "record " << record;
    EXPECT_NE(back.epochs[record], 0u) << "record " << record;
  }
}

// A pool too small halves the face-size cap from the largest face drawn; a pool with room
// to spare for faces twice as wide doubles it after PoolFit::kCalmFrames frames, up to no
// cap; counts of frames planned before a change are ignored (they come back late).
TEST(PoolFit, HalvesOnMissingPagesAndDoublesBackWhenCalm) {
  passes::PoolFit fit;
  std::uint64_t frame = 10;
  // Counts of frame `frame - 2` (two frames in flight), while planning `frame`.
  const auto step = [&](std::uint32_t needed, std::uint32_t missing, std::uint32_t largest) {
    fit.update({.frame = frame - 2, .pages = 100, .needed = needed, .missing = missing},
               {.index = frame, .largest = largest, .atlas = 1024});
    ++frame;
  };
  EXPECT_EQ(fit.cap(), 0u);
  step(150, 50, 512);
  EXPECT_EQ(fit.cap(), 256u) << "half the largest face drawn, not of the atlas's";
  step(150, 50, 512);
  EXPECT_EQ(fit.cap(), 256u) << "the counts of a frame planned before the change are ignored";
  step(120, 20, 256);
  EXPECT_EQ(fit.cap(), 128u);
  for (int i = 0; i < 10; ++i) step(5, 1, 128);
  EXPECT_EQ(fit.cap(), 128u) << "never below a page";
  for (std::uint32_t i = 0; i + 1 < passes::PoolFit::kCalmFrames; ++i) step(23, 0, 128);
  EXPECT_EQ(fit.cap(), 128u) << "not calm long enough";
  step(23, 0, 128);
  EXPECT_EQ(fit.cap(), 256u);
  for (std::uint32_t i = 0; i < 3 * passes::PoolFit::kCalmFrames; ++i) step(40, 0, 256);
  EXPECT_EQ(fit.cap(), 256u) << "faces twice as wide would not fit";
  for (std::uint32_t i = 0; i < 3 * passes::PoolFit::kCalmFrames; ++i) step(10, 0, 256);
  EXPECT_EQ(fit.cap(), 0u) << "back to the atlas's size";
}

// The planner draws a pool's faces at most at the cap and names the lights it shrank.
TEST(AtlasPlanner, APoolCapShrinksFacesAndSaysWhich) {
  const auto scene = test::atrium_scene();
  AtlasSettings s = settings(6);
  s.records = 96;
  s.gpu_decides = true;
  s.page_pool = true;
  s.pool_cap = 128;
  AtlasPlanner pool;
  const auto capped = pool.plan(scene, camera_of(scene), 1, 0, s);
  EXPECT_EQ(capped.degraded.size(), scene.lights.size());
  for (const auto& light : capped.lights) EXPECT_EQ(light.projection.y, 128.0f);
}
