// Packed faces (passes/point_shadow_atlas/face_packer.*, docs/technique.md "Packed faces"):
// where squares go, that none overlap or leave their layer, that a layer keeps one size,
// and how the planner fits every light into a full atlas by drawing faces smaller
// (atlas_planner.cpp, fit_sizes). CPU only.

#include "point_shadow_atlas/face_packer.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "antumbra/scene/scene_file.hpp"
#include "atrium_scene.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

using namespace antumbra;
using passes::FacePacker;
using passes::FacePlace;

namespace {

// Every texel of every placed square, checked for overlap and bounds.
void expect_disjoint(const FacePacker& packer, std::uint32_t layers) {
  std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> used;
  std::map<std::uint32_t, std::uint32_t> layer_size;
  for (std::uint32_t r = 0; r < packer.records(); ++r) {
    const auto place = packer.place_of(r);
    if (!place) continue;
    const std::uint32_t size = packer.size_of(r);
    ASSERT_LT(place->layer, layers);
    const auto [it, fresh] = layer_size.emplace(place->layer, size);
    EXPECT_EQ(it->second, size) << "layer " << place->layer << " holds two sizes";
    ASSERT_LE((place->cell.x + 1) * size, packer.layer_size());
    ASSERT_LE((place->cell.y + 1) * size, packer.layer_size());
    // One texel per square is enough to tell overlaps apart on a grid of its size.
    EXPECT_TRUE(used.emplace(place->layer, place->cell.x * size, place->cell.y * size).second)
        << "record " << r << " overlaps another square";
  }
}

}  // namespace

TEST(FacePacker, SmallSquaresShareALayerOnAGrid) {
  FacePacker packer;
  packer.reset(2, 256, 40);
  for (std::uint32_t r = 0; r < 16; ++r) {
    const auto place = packer.place(r, 64);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->layer, 0u);
    EXPECT_EQ(place->cell, glm::uvec2(r % 4, r / 4));
  }
  // Layer 0 is full of 64s: a 128 takes the next empty layer, a 64 finds no room.
  const auto big = packer.place(16, 128);
  ASSERT_TRUE(big);
  EXPECT_EQ(big->layer, 1u);
  EXPECT_FALSE(packer.place(17, 64));
  EXPECT_FALSE(packer.place(17, 256));
  expect_disjoint(packer, 2);
  EXPECT_EQ(packer.stats().layers_used, 2u);
  EXPECT_EQ(packer.stats().texels, 16u * 64 * 64 + 128 * 128);
}

TEST(FacePacker, AReleasedSquareIsReusedAndAnEmptyLayerChangesSize) {
  FacePacker packer;
  packer.reset(1, 256, 8);
  ASSERT_TRUE(packer.place(0, 128));
  ASSERT_TRUE(packer.place(1, 128));
  packer.release(0);
  EXPECT_FALSE(packer.place_of(0));
  const auto again = packer.place(2, 128);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->cell, glm::uvec2(0, 0));
  packer.release(1);
  packer.release(2);
  EXPECT_EQ(packer.stats().layers_used, 0u);
  const auto whole = packer.place(3, 256);
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->layer, 0u);
}

TEST(FacePacker, RefusesSizesItCannotName) {
  EXPECT_TRUE(FacePacker::valid_size(1000, 1000));
  EXPECT_TRUE(FacePacker::valid_size(512, 1000));
  EXPECT_FALSE(FacePacker::valid_size(96, 1024));    // not a power of two
  EXPECT_FALSE(FacePacker::valid_size(2048, 1024));  // larger than a layer
  EXPECT_FALSE(FacePacker::valid_size(4, 4096));     // past 512 cells a side
  EXPECT_EQ(FacePacker::smallest(4096), 8u);
  FacePacker packer;
  packer.reset(1, 1024, 2);
  EXPECT_FALSE(packer.place(0, 96));
  EXPECT_FALSE(packer.place(0, 0));
}

TEST(FacePacker, WithoutSharingEachSquareTakesALayerAtItsCorner) {
  FacePacker packer;
  packer.reset(3, 256, 4, false);
  for (std::uint32_t r = 0; r < 3; ++r) {
    const auto place = packer.place(r, 64);
    ASSERT_TRUE(place);
    EXPECT_EQ(*place, (FacePlace{.layer = r}));
  }
  EXPECT_FALSE(packer.place(3, 64));
}

// 16 point lights want 96 faces of 256^2 in 6 layers of 256^2: the atlas holds 96 faces
// of 64^2, so every light gets 64^2 faces, none more, none left out.
TEST(FacePackerPlanner, AFullAtlasDrawsEveryLightSmallerInsteadOfDroppingLights) {
  const auto scene = test::atrium_scene();
  ASSERT_EQ(scene.lights.size(), 16u);
  passes::AtlasSettings s;
  s.layers = 6;
  s.face_size = 256;
  s.records = 96;
  passes::AtlasPlanner planner;
  const auto& f = planner.plan(scene, scene.camera.view_projection(16.0f / 9.0f), 1, 0, s);
  EXPECT_TRUE(f.unshadowed.empty());
  ASSERT_EQ(f.degraded.size(), 16u);
  for (const auto& d : f.degraded) {
    EXPECT_EQ(d.wanted, 256u);
    EXPECT_EQ(d.given, 64u) << d.name;
  }
  for (std::uint32_t i = 0; i < 16; ++i) {
    EXPECT_EQ(f.lights[i].projection.y, 64.0f);
    EXPECT_EQ(f.lights[i].params.z, static_cast<float>(6 * i));
  }
  EXPECT_EQ(f.stats.layers_used, 6u);
  EXPECT_EQ(f.stats.texels_held, 96u * 64 * 64);
  // Every record's square is distinct and inside the atlas.
  std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> squares;
  for (std::uint32_t r = 0; r < 96; ++r) {
    const auto place = passes::face_place(f.faces[r]);
    EXPECT_LT(place.layer, 6u);
    EXPECT_LT(place.cell.x, 4u);
    EXPECT_LT(place.cell.y, 4u);
    EXPECT_TRUE(squares.emplace(place.layer, place.cell.x, place.cell.y).second);
  }
  // The next frame keeps every square: nothing moves, so cached faces stay valid.
  std::vector<std::uint32_t> before;
  for (const auto& face : f.faces) before.push_back(face.info.y);
  const auto& g = planner.plan(scene, scene.camera.view_projection(16.0f / 9.0f), 1, 1, s);
  for (std::uint32_t r = 0; r < 96; ++r) EXPECT_EQ(g.faces[r].info.y, before[r]);
  EXPECT_EQ(g.stats.rendered, 0u);
}

// Faces are drawn no smaller than 16^2: an atlas of 32^2 layers holds four a layer. One
// layer cannot hold a point light's six faces (every light unshadowed); two hold the first
// light's, and the others, not fitting, go without from the last one up.
TEST(FacePackerPlanner, LightsThatFitNowhereAreUnshadowedFromTheEnd) {
  const auto scene = test::atrium_scene();
  passes::AtlasSettings s;
  s.layers = 1;
  s.face_size = 32;  // 4 faces of 16^2 a layer: not even one point light's six
  s.records = 96;
  passes::AtlasPlanner planner;
  const auto& f = planner.plan(scene, scene.camera.view_projection(16.0f / 9.0f), 1, 0, s);
  EXPECT_EQ(f.unshadowed.size(), 16u);
  s.layers = 2;  // 8 faces of 16^2: the first light alone
  passes::AtlasPlanner two;
  const auto& g = two.plan(scene, scene.camera.view_projection(16.0f / 9.0f), 1, 0, s);
  EXPECT_EQ(g.unshadowed.size(), 15u);
  EXPECT_EQ(g.lights[0].projection.y, 16.0f);
  EXPECT_EQ(g.unshadowed.front(), scene.lights[1].name);
}

// Every light a scene may have casts its shadow (ANTUMBRA_MAX_SHADOW_LIGHTS = 4096, the
// scene's maximum): 4096 lights in 2046 layers of 512^2 with a record for each face get
// smaller faces and none is left without (the city's case; before, lights past 1024 had no
// entry in shadowData at all).
TEST(FacePackerPlanner, FourThousandLightsAllGetFaces) {
  // As many as a scene file may have (SC028): every light a scene can hold can cast.
  static_assert(scene::kMaxSceneLights == shared::kMaxShadowLights);
  auto scene = test::atrium_scene();
  const auto first = scene.lights.front();
  scene.lights.clear();
  for (int i = 0; i < 4096; ++i) {
    auto light = first;
    light.name = std::to_string(i);
    light.name.insert(0, 1, 'l');  // not operator+: GCC 12 warns falsely (-Wrestrict)
    const int row = i / 64;        // a 64 x 64 grid, 2 m apart
    light.position +=
        glm::vec3(static_cast<float>(i % 64) * 2.0f, 0.0f, static_cast<float>(row) * 2.0f);
    scene.lights.push_back(light);
  }
  passes::AtlasSettings s;
  s.layers = 2046;
  s.face_size = 512;
  s.records = 6 * 4096;
  passes::AtlasPlanner planner;
  const auto& f = planner.plan(scene, scene.camera.view_projection(16.0f / 9.0f), 1, 0, s);
  ASSERT_EQ(f.lights.size(), 4096u);
  EXPECT_TRUE(f.unshadowed.empty());
  EXPECT_EQ(f.lights[4095].params.z, 6.0f * 4095.0f);
  // 24576 faces of 512^2 would take 24576 layers: the largest halve, the last lights first,
  // until they fit (the first lights keep 256^2, four a layer; the rest 128^2, sixteen).
  EXPECT_EQ(f.lights[0].projection.y, 256.0f);
  EXPECT_EQ(f.lights[4095].projection.y, 128.0f);
  EXPECT_EQ(f.degraded.size(), 4096u);
  EXPECT_LE(f.stats.layers_used, 2046u);
  EXPECT_GE(f.stats.layers_used, 2040u);  // and the atlas is used, not left half empty
}
