// Scenario names and sizes under --scale: the names say the size that is rendered and
// the shadow atlas shrinks with the screen.
#include <algorithm>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "antumbra/base/json_document.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "bench_scenarios.hpp"

namespace antumbra::app {
namespace {

const Scenario& named(const std::vector<Scenario>& all, const std::string& name) {
  for (const auto& s : all) {
    if (s.name == name) return s;
  }
  throw std::runtime_error("no scenario " + name);
}

TEST(BenchScenarios, FullScaleKeepsTheSeedsNames) {
  const auto all = builtin_scenarios(1.0);
  const auto& s = named(all, "table1/pcss-11/720p");
  EXPECT_EQ(s.width, 1280u);
  EXPECT_EQ(s.height, 720u);
  EXPECT_EQ(s.face, 1024u);
  EXPECT_EQ(named(all, "lights/ssss-11/1080p/1024l").face, 512u);
}

TEST(BenchScenarios, NamesCarryTheScaledSize) {
  const auto all = builtin_scenarios(0.25);
  std::set<std::string> names;
  for (const auto& s : all) {
    names.insert(s.name);
    EXPECT_EQ(s.name.find("720p"), std::string::npos) << s.name;
    EXPECT_EQ(s.name.find("1080p"), std::string::npos) << s.name;
    const std::string size = '/' + std::to_string(s.height) + 'p';
    EXPECT_NE(s.name.find(size), std::string::npos) << s.name;
  }
  EXPECT_EQ(names.size(), all.size()) << "two scenarios share a name";
  const auto& s = named(all, "table1/pcss-11/180p");
  EXPECT_EQ(s.width, 320u);
  EXPECT_EQ(s.height, 180u);
  EXPECT_EQ(named(all, "table2/ssss-11/270p/4l").width, 480u);
}

TEST(BenchScenarios, ScaleShrinksTheAtlasFaces) {
  const auto all = builtin_scenarios(0.25);
  EXPECT_EQ(named(all, "table1/hard/180p").face, 256u);
  EXPECT_EQ(named(all, "lights/ssss-11/270p/1024l").face, 128u);
}

TEST(BenchScenarios, FaceSizesDivideByTheDerivedMapsFactors) {
  for (const double scale : {0.01, 0.1, 0.33, 0.5, 1.0, 1.7}) {
    for (const int lights : {16, 1024}) {
      const unsigned face = shadow_face_size(lights, scale);
      EXPECT_GE(face, 16u);
      EXPECT_EQ(face % 16, 0u) << "scale " << scale;
    }
  }
  EXPECT_EQ(shadow_face_size(16, 0.1), 96u);
}

TEST(BenchScenarios, FitShadowResourcesUsesTheFaceAndKeepsTheMinMapsFactor) {
  auto document = base::load_json_file(std::string(ANTUMBRA_TEST_SOURCE_DIR) +
                                       "/data/graphs/layered-ssss-min.json");
  ASSERT_TRUE(document.ok());
  auto graph = fg::parse_graph(document.value());
  ASSERT_TRUE(graph.ok());
  fit_shadow_resources(graph.value(), 4, shadow_face_size(4, 0.25));
  const auto& resources = graph->resources;
  const auto& atlas = resources[static_cast<std::size_t>(graph->find_resource("atlas"))];
  const auto& colour = resources[static_cast<std::size_t>(graph->find_resource("shadowColour"))];
  const auto& min_depth = resources[static_cast<std::size_t>(graph->find_resource("minDepth"))];
  EXPECT_EQ(atlas.size.width, 256u);
  EXPECT_EQ(atlas.size.height, 256u);
  EXPECT_EQ(atlas.layers, 24u);
  EXPECT_EQ(colour.size.width, 256u);
  EXPECT_EQ(min_depth.size.width, 32u);  // the graph's 1024 / 128 = 8 kept
  EXPECT_EQ(min_depth.layers, 24u);
  // One face record per layer and not one more: a spare record makes the hardware
  // rasteriser pack faces and pay for clip distances (shadow_data.h: header, 4096 lights,
  // 80-byte records).
  const auto& data = resources[static_cast<std::size_t>(graph->find_resource("shadowData"))];
  EXPECT_EQ(data.buffer_size, 16u + 64u * 4096u + 80u * 24u);
}

TEST(BenchScenarios, ManyTableShadowsTheDistrictAndTheCityOnTheComputeRasterisers) {
  const auto many = select_scenarios(builtin_scenarios(1.0), {"many/"});
  ASSERT_EQ(many.size(), 3u);
  const auto& some = named(many, "many/ssss-11/1080p/1024l-64m/compute/screen/vis");
  const auto& all = named(many, "many/ssss-11/1080p/1024l-1024m/compute/screen/vis");
  const auto& city = named(many, "many/ssss-11/1080p/4096l-1024m/compute/screen/vis");
  EXPECT_EQ(some.scene, kDistrictScene);
  EXPECT_EQ(some.moving, 64);
  EXPECT_EQ(all.moving, 1024);
  EXPECT_EQ(city.scene, kCityScene);
  EXPECT_EQ(city.lights, 4096);
  EXPECT_EQ(city.moving, 1024);
  EXPECT_EQ(city.rasterizer, "compute");
  // Cached: still lights keep their faces, moving ones redraw theirs (as the moving table).
  EXPECT_TRUE(some.shadow_cache);
  EXPECT_TRUE(city.shadow_cache);
  // --quick keeps the district's share of the lights for both scenes.
  const auto quick = select_scenarios(builtin_scenarios(0.25, kQuickDistrict), {"many/"});
  ASSERT_EQ(quick.size(), 3u);
  EXPECT_EQ(named(quick, "many/ssss-11/135p/1024l-256m/compute/screen/vis").scene, kCityScene);
}

TEST(BenchScenarios, MovingTableHasThreeTechniquesPerLightCountOnBothRasterisers) {
  const auto moving = select_scenarios(builtin_scenarios(1.0), {"moving/"});
  ASSERT_EQ(moving.size(), 48u);
  for (const char* technique : {"hard", "pcss-11", "ssss-11"}) {
    for (const int lights : {16, 64, 256, 1024}) {
      const std::string name =
          std::string("moving/") + technique + "/1080p/" + std::to_string(lights) + "l";
      const auto& compute = named(moving, name + "/compute");
      EXPECT_EQ(compute.rasterizer, "compute");
      ASSERT_FALSE(compute.overrides.empty());
      const auto has = [](const Scenario& s, const char* type, const char* param,
                          const char* value) {
        return std::any_of(s.overrides.begin(), s.overrides.end(), [&](const ParamOverride& o) {
          return o.pass_type == type && o.param == param && o.value == value;
        });
      };
      EXPECT_TRUE(has(compute, "point-shadow-atlas", "rasterizer", "compute"));
      EXPECT_TRUE(has(compute, "tonemap", "stage", "compute"));
      const auto& screen = named(moving, name + "/compute/screen");
      EXPECT_EQ(screen.rasterizer, "compute");
      ASSERT_FALSE(screen.overrides.empty());
      EXPECT_EQ(screen.overrides.back().param, "resolution");
      EXPECT_EQ(screen.overrides.back().value, "screen");
      // The same with the compute G-buffer: no raster pass left in the frame.
      const auto& vis = named(moving, name + "/compute/screen/vis");
      EXPECT_TRUE(has(vis, "gbuffer", "rasterizer", "compute"));
      EXPECT_TRUE(has(vis, "point-shadow-atlas", "resolution", "screen"));
      EXPECT_FALSE(has(screen, "gbuffer", "rasterizer", "compute"));
      // Pinned, so that "auto" does not change what a row measures from device to device.
      EXPECT_TRUE(has(screen, "gbuffer", "rasterizer", "hardware"));
      const auto& s = named(moving, name);
      EXPECT_EQ(s.rasterizer, "hardware");
      EXPECT_EQ(s.table, "moving");
      EXPECT_EQ(s.lights, lights);
      EXPECT_EQ(s.width, 1920u);
      EXPECT_TRUE(s.shadow_cache) << name;
      bool cache_override = false;
      for (const auto& o : s.overrides) {
        if (o.pass_type == "point-shadow-atlas" && o.param == "cache") {
          cache_override = o.value.get<bool>();
        }
      }
      EXPECT_TRUE(cache_override) << name;
      if (lights == 1024) {
        EXPECT_EQ(s.scene, "district.json");
        EXPECT_EQ(s.moving, 64);
      } else {
        EXPECT_EQ(s.scene, "atrium.json");
        EXPECT_EQ(s.moving, lights) << "every light moves";
      }
    }
  }
  EXPECT_EQ(named(moving, "moving/pcss-11/1080p/16l").kernel, 11);
  // The other tables keep still lights in the atrium (the dynamic table's has moving
  // objects).
  for (const auto& s : builtin_scenarios(1.0)) {
    if (s.table == "moving" || s.table == "materials" || s.table == "many" || s.table == "pages") {
      continue;
    }
    EXPECT_EQ(s.moving, 0) << s.name;
    const char* scene = s.table == "dynamic" ? kDynamicScene
                        : s.table == "sun"   ? kSunScene
                                             : "atrium.json";
    EXPECT_EQ(s.scene, scene) << s.name;
  }
}

// The materials table: the atrium and its textured, cut-out twin, 16 moving lights, on
// every rasteriser variant of the moving table, shadows cached.
TEST(BenchScenarios, MaterialsTableComparesTheCutoutSceneWithTheAtrium) {
  const auto rows = select_scenarios(builtin_scenarios(1.0), {"materials/"});
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& s : rows) {
    EXPECT_EQ(s.moving, 16) << s.name;
    EXPECT_TRUE(s.shadow_cache) << s.name;
    EXPECT_TRUE(s.scene == "atrium.json" || s.scene == kCutoutScene) << s.name;
  }
  const auto& cut = named(rows, "materials/ssss-11/1080p/16l/atrium-cutouts/compute/screen");
  EXPECT_EQ(cut.scene, kCutoutScene);
  EXPECT_EQ(cut.rasterizer, "compute");
  EXPECT_EQ(named(rows, "materials/ssss-11/1080p/16l/atrium").rasterizer, "hardware");
}

TEST(BenchScenarios, MovingTableScalesLikeTheOthers) {
  const auto all = builtin_scenarios(0.25);
  const auto& s = named(all, "moving/ssss-11/270p/1024l");
  EXPECT_EQ(s.width, 480u);
  EXPECT_EQ(s.face, 128u);
  EXPECT_EQ(bench_motion(s).moving, 64);
}

// --quick shrinks the district's rows further than the rest and keeps fewer of their
// lights, moving fewer of them; only theirs change, and their names say so.
TEST(BenchScenarios, QuickDistrictRowsAreSmallerAndSayWhatTheyHold) {
  const auto quick = builtin_scenarios(kQuickScale, kQuickDistrict);
  const auto plain = builtin_scenarios(kQuickScale);
  ASSERT_EQ(quick.size(), plain.size());
  const auto& district = named(quick, "moving/ssss-11/135p/256l-district/compute");
  EXPECT_EQ(district.width, 240u);
  EXPECT_EQ(district.lights, kQuickDistrict.lights);
  EXPECT_EQ(district.face,
            shadow_face_size(kQuickDistrict.lights, kQuickScale * kQuickDistrict.scale));
  EXPECT_EQ(district.scene, kDistrictScene);
  EXPECT_EQ(district.moving, kQuickDistrict.moving);
  EXPECT_EQ(named(plain, "moving/ssss-11/270p/1024l").moving, kDistrictMovingLights);
  for (std::size_t i = 0; i < quick.size(); ++i) {
    if (quick[i].scene == kDistrictScene || quick[i].scene == kCityScene) continue;
    EXPECT_EQ(quick[i].name, plain[i].name);
    EXPECT_EQ(quick[i].face, plain[i].face);
  }
  EXPECT_EQ(named(quick, "lights/ssss-11/270p/1024l").face, 128u);  // the atrium's 1024
}

TEST(BenchScenarios, MovingScenesHaveTheirLightsAfterTheLightCount) {
  // What run_scenario renders: the scenario's scene with its light count.
  for (const char* file : {"atrium.json", "district.json"}) {
    const auto scene =
        scene::load_scene_file(std::string(ANTUMBRA_TEST_SOURCE_DIR) + "/data/scenes/" + file);
    ASSERT_TRUE(scene.ok()) << scene.diagnostics().to_text();
    for (const auto& s : select_scenarios(builtin_scenarios(1.0), {"moving/ssss-11/"})) {
      if (s.scene != file) continue;
      const auto lights = with_light_count(scene.value(), s.lights).lights;
      ASSERT_EQ(lights.size(), static_cast<std::size_t>(s.lights)) << s.name;
      // Frame 0 and frame 1 differ in exactly the moving lights.
      const auto a = scene::animate_lights(lights, 0, bench_motion(s));
      const auto b = scene::animate_lights(lights, 1, bench_motion(s));
      int moved = 0;
      for (std::size_t i = 0; i < lights.size(); ++i) {
        if (a[i].position != b[i].position) ++moved;
      }
      EXPECT_EQ(moved, s.moving) << s.name;
    }
  }
}

}  // namespace
// The pages table: the many table's rows and the atrium's moving lights (also with the
// min-filtered maps, EVSM4 and VSSM), each drawn into a page pool of a fixed number of layers.
TEST(BenchScenarios, PagesTableDrawsIntoAFixedPool) {
  const auto pages = select_scenarios(builtin_scenarios(1.0), {"pages/"});
  ASSERT_EQ(pages.size(), 7u);
  EXPECT_EQ(named(pages, "pages/evsm4/1080p/16l-16m/compute/screen/vis/pool32").graph,
            "evsm4.json");
  EXPECT_EQ(named(pages, "pages/vssm/1080p/16l-16m/compute/screen/vis/pool32").graph, "vssm.json");
  const auto& min = named(pages, "pages/ssss-min-11/1080p/16l-16m/compute/screen/vis/pool32");
  EXPECT_EQ(min.graph, "layered-ssss-min.json");
  EXPECT_EQ(min.pool_layers, 32u);
  const auto& atrium = named(pages, "pages/ssss-11/1080p/16l-16m/compute/screen/vis/pool32");
  const auto& city = named(pages, "pages/ssss-11/1080p/4096l-1024m/compute/screen/vis/pool512");
  EXPECT_EQ(atrium.pool_layers, 32u);
  EXPECT_EQ(atrium.moving, 16);
  EXPECT_EQ(city.scene, kCityScene);
  EXPECT_EQ(city.pool_layers, 512u);
  EXPECT_EQ(city.rasterizer, "compute");
  EXPECT_TRUE(city.shadow_cache);
  EXPECT_EQ(named(pages, "pages/ssss-11/1080p/1024l-64m/compute/screen/vis/pool512").moving, 64);
  for (const auto& s : select_scenarios(builtin_scenarios(1.0), {"many/", "moving/"})) {
    EXPECT_EQ(s.pool_layers, 0u) << s.name << ": squares";
  }
  // A pool's atlas is whole 128^2 pages, --quick's too.
  for (const auto& s : select_scenarios(builtin_scenarios(0.25, kQuickDistrict), {"pages/"})) {
    EXPECT_GE(s.face, 128u) << s.name;
    EXPECT_EQ(s.face % 128, 0u) << s.name;
  }
}

// A pool row's graph: the atlas, its colour map and min-filtered map pool_layers deep plus the
// layers its records' fallback tiles take, a pageTables buffer with a table for every face record
// shadowData holds, written by the atlas pass and bound by exactly the passes that read
// the atlas.
TEST(BenchScenarios, FitPagePoolBindsTheTablesToEveryReaderOfTheAtlas) {
  fg::GraphDesc graph;
  for (const char* name : {"atlas", "shadowColour", "depth", "minDepth", "moments"}) {
    fg::ResourceDesc r;
    r.name = name;
    r.layers = 2046;
    r.size = {false, 1.0, 1.0, 512, 512};
    graph.resources.push_back(r);
  }
  fg::ResourceDesc data;
  data.name = "shadowData";
  data.kind = fg::ResourceKind::buffer;
  data.buffer_size = 16 + 64 * 4096 + 80 * 6144;
  graph.resources.push_back(data);
  fg::PassInstanceDesc atlas;
  atlas.type = "point-shadow-atlas";
  atlas.outputs.push_back({"atlas", "atlas", "/passes/0/out/atlas"});
  fg::PassInstanceDesc reader;
  reader.type = "layered-penumbra";
  reader.inputs.push_back({"atlas", "atlas", "/passes/1/in/atlas"});
  fg::PassInstanceDesc other;
  other.type = "anisotropic-blur";
  other.inputs.push_back({"depth", "depth", "/passes/2/in/depth"});
  graph.passes = {atlas, reader, other};
  fit_page_pool(graph, 0);
  EXPECT_EQ(graph.resources.size(), 6u) << "no pool: nothing changes";
  fit_page_pool(graph, 512);
  // 6144 records' fallback tiles take 384 pages: 24 more layers of 16.
  EXPECT_EQ(graph.resources[0].layers, 512u + 24u);
  EXPECT_EQ(graph.resources[1].layers, 512u + 24u);
  EXPECT_EQ(graph.resources[2].layers, 2046u);
  EXPECT_EQ(graph.resources[3].layers, 512u + 24u) << "the min-filtered map keeps the pool's";
  EXPECT_EQ(graph.resources[4].layers, 512u + 24u) << "the moments keep the pool's";
  ASSERT_EQ(graph.resources.size(), 7u);
  EXPECT_EQ(graph.resources[6].name, "pageTables");
  EXPECT_EQ(graph.resources[6].buffer_size, 6144u * 16 * 4) << "16 pages of 128^2 per face";
  EXPECT_EQ(graph.passes[0].params["pagePool"], true);
  EXPECT_EQ(graph.passes[0].outputs.back().port, "pageTables");
  EXPECT_EQ(graph.passes[1].inputs.back().port, "pageTables");
  EXPECT_EQ(graph.passes[2].inputs.size(), 1u);
}

TEST(BenchScenarios, ComputeRowsWriteAnR32fAtlas) {
  fg::GraphDesc graph;
  fg::ResourceDesc atlas;
  atlas.name = "atlas";
  atlas.format = fg::Format::d32f;
  graph.resources.push_back(atlas);
  fit_atlas_format(graph, "hardware");
  EXPECT_EQ(graph.resources[0].format, fg::Format::d32f);
  fit_atlas_format(graph, "compute");
  EXPECT_EQ(graph.resources[0].format, fg::Format::r32f);
}

// Compute rows cull faces by receivers: the atlas pass reads the G-buffer's depth.
TEST(BenchScenarios, ComputeRowsBindTheGBufferDepthToTheAtlas) {
  fg::GraphDesc graph;
  fg::PassInstanceDesc gbuffer;
  gbuffer.type = "gbuffer";
  gbuffer.outputs.push_back({"depth", "sceneDepth", "/passes/0/out/depth"});
  fg::PassInstanceDesc atlas;
  atlas.type = "point-shadow-atlas";
  atlas.pointer = "/passes/1";
  graph.passes = {gbuffer, atlas};
  fit_atlas_format(graph, "hardware");
  EXPECT_TRUE(graph.passes[1].inputs.empty());
  fit_atlas_format(graph, "compute");
  ASSERT_EQ(graph.passes[1].inputs.size(), 1u);
  EXPECT_EQ(graph.passes[1].inputs[0].port, "depth");
  EXPECT_EQ(graph.passes[1].inputs[0].resource, "sceneDepth");
  fit_atlas_format(graph, "compute");
  EXPECT_EQ(graph.passes[1].inputs.size(), 1u) << "bound once";
}

}  // namespace antumbra::app

namespace antumbra::app {

// The penumbra table: PCSS and layered SSSS at every light radius, cached shadows, the
// radius applied to every light of the scene.
TEST(BenchScenarios, PenumbraTableSweepsTheLightRadius) {
  const auto rows = select_scenarios(builtin_scenarios(1.0), {"penumbra/"});
  ASSERT_EQ(rows.size(), 3 * std::size(kPenumbraLightSizes));
  for (const auto& s : rows) {
    EXPECT_TRUE(s.technique == "pcss" || s.technique == "ssss" || s.technique == "ssss-min")
        << s.name;
    EXPECT_GT(s.light_size, 0.0f);
    EXPECT_TRUE(s.shadow_cache) << s.name;
  }
  EXPECT_EQ(rows.front().name, "penumbra/pcss-11/1080p/16l/r0.05m");
  EXPECT_EQ(rows.back().name, "penumbra/ssss-min-11/1080p/16l/r1.00m");
  scene::Scene scene;
  scene.lights.resize(2);
  scene.lights[1].type = scene::LightType::directional;
  scene.lights[1].size = 0.5f;  // degrees: the sun keeps its angular size
  set_light_size(scene, 0.25f);
  EXPECT_FLOAT_EQ(scene.lights[0].size, 0.25f);
  EXPECT_FLOAT_EQ(scene.lights[1].size, 0.5f);
  set_light_size(scene, 0.0f);
  EXPECT_FLOAT_EQ(scene.lights[0].size, 0.25f) << "0 keeps the scene's radii";
}

}  // namespace antumbra::app

namespace antumbra::app {

// The dynamic table: the atrium with moving carts and a ball, each technique on the
// hardware rasteriser with and without the static cache and on the compute one.
TEST(BenchScenarios, DynamicTableMovesObjectsNotLights) {
  const auto rows = select_scenarios(builtin_scenarios(1.0), {"dynamic/"});
  ASSERT_EQ(rows.size(), 9u);
  int nocache = 0;
  for (const auto& s : rows) {
    EXPECT_EQ(s.scene, kDynamicScene) << s.name;
    EXPECT_EQ(s.moving, 0) << s.name;
    EXPECT_TRUE(s.shadow_cache) << s.name;
    for (const auto& o : s.overrides) {
      if (o.param == "staticCache") ++nocache;
    }
  }
  EXPECT_EQ(nocache, 3);
  EXPECT_EQ(rows.front().name, "dynamic/hard/1080p/16l");
  EXPECT_EQ(rows.back().name, "dynamic/ssss-11/1080p/16l/compute");
}

// The sun table: the courtyard, one map against four cascades in each filter.
TEST(BenchScenarios, SunTableComparesOneMapWithFourCascades) {
  const auto rows = select_scenarios(builtin_scenarios(1.0), {"sun/"});
  ASSERT_EQ(rows.size(), 12u);
  int four = 0;
  for (const auto& s : rows) {
    EXPECT_EQ(s.scene, kSunScene) << s.name;
    EXPECT_EQ(s.lights, kSunSceneLights) << s.name;
    EXPECT_FALSE(s.shadow_cache) << s.name << ": the cascades' cost, as with a moving camera";
    for (const auto& o : s.overrides) {
      if (o.param == "sunCascades" && o.value == 4) ++four;
    }
  }
  EXPECT_EQ(four, 6);
  EXPECT_EQ(rows.front().name, "sun/hard/1080p/5l/c1");
  EXPECT_EQ(rows.back().name, "sun/vssm/1080p/5l/c4");
}

}  // namespace antumbra::app
