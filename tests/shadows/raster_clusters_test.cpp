// The compute shadow rasteriser's CPU side: which meshes count as closed (back-facing
// clusters may be skipped only there), the cluster geometry it uploads, and the graph's
// view of its ports (transfer_dst under rasterizer "compute") and its format check.

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <optional>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/scene/primitives.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "common/frame_data.hpp"
#include "common/rasterizer_choice.hpp"
#include "point_shadow_atlas/raster_clusters.hpp"
#include "register_builtin_passes.hpp"

using namespace antumbra;
namespace fs = std::filesystem;

namespace {

fs::path repo_dir() {
  return fs::path(ANTUMBRA_TEST_SOURCE_DIR);
}

}  // namespace

TEST(RasterClusters, PrimitivesAreClosedAndCutOrFlippedMeshesAreNot) {
  EXPECT_TRUE(passes::mesh_is_closed(scene::make_box({1.0f, 2.0f, 3.0f})));
  EXPECT_TRUE(passes::mesh_is_closed(scene::make_sphere(1.0f, 16, 8)));
  EXPECT_TRUE(passes::mesh_is_closed(scene::make_cylinder(0.5f, 2.0f, 12)));
  EXPECT_FALSE(passes::mesh_is_closed(scene::make_plane({2.0f, 2.0f})));

  scene::Mesh cut = scene::make_box({1.0f, 1.0f, 1.0f});
  cut.indices.resize(cut.indices.size() - 3);  // one triangle missing: a hole
  EXPECT_FALSE(passes::mesh_is_closed(cut));

  scene::Mesh flipped = scene::make_box({1.0f, 1.0f, 1.0f});
  std::swap(flipped.indices[0], flipped.indices[1]);  // one triangle wound the other way
  EXPECT_FALSE(passes::mesh_is_closed(flipped));

  EXPECT_FALSE(passes::mesh_is_closed(scene::Mesh{}));
}

TEST(RasterClusters, AtriumClustersCoverEveryTriangleOnceWithItsFlags) {
  auto loaded = scene::load_scene_file((repo_dir() / "data/scenes/atrium.json").string());
  ASSERT_TRUE(loaded.ok());
  const scene::Scene& scene = loaded.value();
  const passes::RasterGeometry geometry = passes::build_raster_geometry(scene);
  const passes::MergedGeometry merged = passes::merge_scene_geometry(scene);
  ASSERT_EQ(geometry.indices.size(), merged.indices.size());

  // The same triangles (as index triples) in another order.
  const auto triples = [](const std::vector<std::uint32_t>& indices) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
      out.push_back({indices[i], indices[i + 1], indices[i + 2]});
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(triples(geometry.indices), triples(merged.indices));

  std::uint32_t next = 0;
  std::uint32_t translucent = 0;
  for (const auto& c : geometry.clusters) {
    EXPECT_EQ(c.info.x, next) << "clusters are contiguous in the index list";
    EXPECT_GE(c.info.y, 1u);
    EXPECT_LE(c.info.y, shared::kRasterGroup);
    next += 3 * c.info.y;
    const bool is_translucent = (c.info.z & shared::kClusterTranslucent) != 0u;
    EXPECT_EQ(is_translucent, scene.materials[c.info.w].translucent);
    translucent += is_translucent ? 1u : 0u;
    // Every vertex of the cluster lies in its sphere.
    for (std::uint32_t i = c.info.x; i < c.info.x + 3 * c.info.y; ++i) {
      const glm::vec3 p = merged.vertices[geometry.indices[i]].position;
      EXPECT_LE(glm::length(p - glm::vec3(c.sphere)), c.sphere.w * 1.0001f + 1e-5f);
    }
  }
  EXPECT_EQ(next, geometry.indices.size());
  EXPECT_EQ(translucent, geometry.translucent_clusters);
  EXPECT_EQ(translucent, 4u) << "four small glass panes, one cluster each";
  const auto closed =
      std::count_if(geometry.clusters.begin(), geometry.clusters.end(),
                    [](const auto& c) { return (c.info.z & shared::kClusterClosed) != 0u; });
  EXPECT_GT(closed, 0) << "the atrium's boxes and columns are closed";
}

// The cull's block spheres (one per kCullGroup clusters) hold every cluster's sphere, and a
// block with a dynamic cluster is never skipped (its bounds move with the mesh).
TEST(RasterClusters, BlockSpheresHoldTheirClustersAndDynamicBlocksAreNeverSkipped) {
  auto loaded = scene::load_scene_file((repo_dir() / "data/scenes/atrium-dynamic.json").string());
  ASSERT_TRUE(loaded.ok());
  const passes::RasterGeometry geometry = passes::build_raster_geometry(loaded.value());
  ASSERT_LT(geometry.static_clusters, geometry.clusters.size()) << "the scene has a dynamic mesh";
  const std::vector<glm::vec4> blocks =
      passes::cluster_block_spheres(geometry.clusters, geometry.static_clusters);
  const std::size_t group = shared::kCullGroup;
  ASSERT_EQ(blocks.size(), (geometry.clusters.size() + group - 1) / group);
  for (std::size_t c = 0; c < geometry.clusters.size(); ++c) {
    const glm::vec4 block = blocks[c / group];
    const glm::vec4 sphere = geometry.clusters[c].sphere;
    if (c >= geometry.static_clusters) {
      EXPECT_LT(block.w, 0.0f) << "cluster " << c << " is dynamic";
      continue;
    }
    if (block.w < 0.0f) continue;  // a static cluster sharing its block with a dynamic one
    EXPECT_LE(glm::length(glm::vec3(sphere) - glm::vec3(block)) + sphere.w, block.w)
        << "cluster " << c;
  }
  EXPECT_GE(blocks.front().w, 0.0f) << "the first block is all static";
}

// Cut clusters (one-sided or alpha-tested materials) are flagged for the cut list and
// counted, translucent ones too, and every cluster's triangles keep the winding the
// merged geometry uploads, mirrored meshes included (docs/technique.md, "Compute shadow
// rasteriser", cut clusters).
TEST(RasterClusters, CutTranslucentAndMirroredMeshesAreFlaggedAndWoundAsUploaded) {
  scene::Scene scene;
  const auto material = [&](bool double_sided, bool mask, bool translucent) {
    scene::Material m;
    m.double_sided = double_sided;
    m.translucent = translucent;
    if (mask) {
      m.alpha_mode = scene::AlphaMode::mask;
      m.alpha = 0.25f;  // below the cutoff: alpha-tested without a texture
    }
    scene.materials.push_back(m);
    return static_cast<int>(scene.materials.size() - 1);
  };
  const int solid = material(true, false, false);
  const int one_sided = material(false, false, false);
  const int masked = material(true, true, false);
  const int glass = material(true, false, true);
  const int masked_glass = material(true, true, true);
  const auto add = [&](int m, glm::mat4 transform, bool dynamic) {
    scene::Mesh mesh = scene::make_box({1.0f, 1.0f, 1.0f});
    mesh.material = m;
    mesh.transform = transform;
    mesh.dynamic = dynamic;
    scene.meshes.push_back(std::move(mesh));
  };
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  add(solid, glm::mat4(1.0f), false);
  add(one_sided, mirror, false);
  add(masked, glm::mat4(1.0f), false);
  add(glass, glm::mat4(1.0f), false);
  add(masked_glass, glm::mat4(1.0f), false);
  add(one_sided, glm::mat4(1.0f), true);  // a dynamic cut mesh
  const passes::RasterGeometry geometry = passes::build_raster_geometry(scene);
  ASSERT_EQ(geometry.clusters.size(), 6u) << "a box is one cluster";
  std::uint32_t cut = 0;
  for (const auto& c : geometry.clusters) {
    const bool is_cut = (c.info.z & shared::kClusterCut) != 0u;
    const auto m = static_cast<std::size_t>(c.info.w);
    EXPECT_EQ(is_cut, !scene.materials[m].double_sided || scene.materials[m].alpha_tested())
        << "material " << m;
    EXPECT_EQ((c.info.z & shared::kClusterTranslucent) != 0u, scene.materials[m].translucent);
    cut += is_cut ? 1u : 0u;
  }
  EXPECT_EQ(cut, 4u);  // the one-sided boxes (static and dynamic), the masked ones
  EXPECT_EQ(geometry.cut_clusters, 4u);
  EXPECT_EQ(geometry.translucent_clusters, 2u);
  EXPECT_EQ(geometry.cut_translucent_clusters, 1u);

  // Oriented triangles: the same (up to rotation) as the merged geometry's, so a mirrored
  // one-sided box faces the light with the same sides on both rasterisers.
  const auto oriented = [](const std::vector<std::uint32_t>& indices) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
      std::array<std::uint32_t, 3> t{indices[i], indices[i + 1], indices[i + 2]};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(oriented(geometry.indices), oriented(passes::merge_scene_geometry(scene).indices));
}

namespace {

// tests/data/shadows/atlas.json with the atlas's format and the rasteriser spelt out in
// the file (so that diagnostics can point at them).
fg::Result<fg::Plan> compile_atlas_graph(const std::string& rasterizer, const std::string& format,
                                         const nlohmann::json& params = nlohmann::json::object()) {
  std::ifstream in(repo_dir() / "tests/data/shadows/atlas.json");
  auto json = nlohmann::json::parse(in);
  json["resources"]["atlas"]["format"] = format;
  for (auto& p : json["passes"]) {
    if (p["name"] == "shadows") {
      p["params"]["rasterizer"] = rasterizer;
      p["params"].update(params);
    }
  }
  const auto registry = passes::builtin_pass_registry();
  fg::CompileOptions options;
  options.viewport = {160, 90};
  return fg::compile_text(json.dump(2), "atlas-" + rasterizer + ".json", registry.reflection(),
                          options);
}

const fg::PlanBinding* binding(const fg::Plan& plan, const char* pass, const char* port) {
  for (const auto& p : plan.passes) {
    if (p.name != pass) continue;
    for (const auto& b : p.bindings) {
      if (b.port == port) return &b;
    }
  }
  return nullptr;
}

}  // namespace

TEST(RasterClusters, ComputeRasterizerWritesAStorageAtlasOrCopiesIntoADepthOne) {
  const auto hardware = compile_atlas_graph("hardware", "d32f");
  ASSERT_TRUE(hardware.ok()) << hardware.diagnostics().to_text();
  ASSERT_NE(binding(hardware.value(), "shadows", "atlas"), nullptr);
  EXPECT_EQ(binding(hardware.value(), "shadows", "atlas")->access, fg::Access::depth_attachment);
  EXPECT_EQ(binding(hardware.value(), "shadows", "colour")->access, fg::Access::color_attachment);

  const auto storage = compile_atlas_graph("compute", "r32f");
  ASSERT_TRUE(storage.ok()) << storage.diagnostics().to_text();
  const auto* atlas = binding(storage.value(), "shadows", "atlas");
  ASSERT_NE(atlas, nullptr);
  EXPECT_EQ(atlas->access, fg::Access::storage_read_write) << "cached layers are kept";
  EXPECT_EQ(atlas->stage, fg::Stage::compute);
  EXPECT_EQ(binding(storage.value(), "shadows", "colour")->access, fg::Access::storage_read_write);

  const auto copied = compile_atlas_graph("compute", "d32f");
  ASSERT_TRUE(copied.ok()) << copied.diagnostics().to_text();
  const auto* copied_atlas = binding(copied.value(), "shadows", "atlas");
  ASSERT_NE(copied_atlas, nullptr);
  EXPECT_EQ(copied_atlas->access, fg::Access::transfer_dst);
  EXPECT_EQ(copied_atlas->stage, fg::Stage::transfer);
  EXPECT_EQ(binding(copied.value(), "shadows", "colour")->access, fg::Access::storage_read_write)
      << "the colour map is a storage image either way";
  EXPECT_EQ(binding(copied.value(), "shadows", "shadowData")->access, fg::Access::storage_write)
      << "published by the GPU's face decision";
  EXPECT_EQ(binding(hardware.value(), "shadows", "shadowData")->access, fg::Access::transfer_dst);
}

TEST(RasterClusters, AtlasFormatMustSuitTheRasteriser) {
  EXPECT_TRUE(compile_atlas_graph("hardware", "d16").ok());
  for (const auto& [rasterizer, format] : {std::pair{"compute", "d16"}, {"hardware", "r32f"}}) {
    const auto plan = compile_atlas_graph(rasterizer, format);
    ASSERT_FALSE(plan.ok()) << rasterizer << " " << format;
    const base::Diagnostic* d = plan.diagnostics().find("SHD004");
    ASSERT_NE(d, nullptr) << plan.diagnostics().to_text();
    EXPECT_NE(d->message.find(format), std::string::npos) << d->message;
    EXPECT_NE(d->pointer.find("/params/rasterizer"), std::string::npos) << d->pointer;
    EXPECT_GT(d->line, 0);
  }
}

// Face sizes are powers of two: any other minimum is refused where it is written, and a
// scale or minimum out of range by the parameter's bounds.
TEST(RasterClusters, MinimumResolutionMustBeAPowerOfTwo) {
  const auto good =
      compile_atlas_graph("hardware", "d32f", {{"resolution", "screen"}, {"minResolution", 128}});
  EXPECT_TRUE(good.ok()) << good.diagnostics().to_text();
  for (const nlohmann::json& bad :
       {nlohmann::json{{"minResolution", 100}}, nlohmann::json{{"minResolution", 0}},
        nlohmann::json{{"minResolution", -64}}, nlohmann::json{{"resolutionScale", 0.0}},
        nlohmann::json{{"resolution", "tiny"}}}) {
    const auto plan = compile_atlas_graph("hardware", "d32f", bad);
    ASSERT_FALSE(plan.ok()) << bad.dump();
    const std::string text = plan.diagnostics().to_text();
    EXPECT_NE(text.find("/params/" + bad.begin().key()), std::string::npos) << text;
  }
}

// An update budget of 0 faces (or fewer) would never draw anything optional, and a
// negative staleness has no meaning: each is refused where it is written.
TEST(AtlasParams, BudgetsOfZeroOrLessAreRefusedWhereWritten) {
  const auto good = compile_atlas_graph(
      "hardware", "d32f", {{"faceBudget", 1}, {"maxStaleFrames", 0}, {"staticCache", false}});
  EXPECT_TRUE(good.ok()) << good.diagnostics().to_text();
  for (const nlohmann::json& bad :
       {nlohmann::json{{"faceBudget", 0}}, nlohmann::json{{"faceBudget", -6}},
        nlohmann::json{{"faceBudget", 2.5}}, nlohmann::json{{"maxStaleFrames", -1}},
        nlohmann::json{{"staticCache", "yes"}}}) {
    const auto plan = compile_atlas_graph("hardware", "d32f", bad);
    ASSERT_FALSE(plan.ok()) << bad.dump();
    const std::string text = plan.diagnostics().to_text();
    EXPECT_NE(text.find("/params/" + bad.begin().key()), std::string::npos) << text;
  }
}

// rasterizer "auto": the device's pick where the atlas allows both, the atlas's format
// where it allows one, and a note that says which and why.
TEST(AtlasParams, AutoRasterizerChoosesByDeviceAndFormat) {
  EXPECT_FALSE(
      passes::pick_rasterizer({"llvmpipe (LLVM 15.0.6, 256 bits)", true, 0x10005}).compute);
  EXPECT_TRUE(passes::pick_rasterizer({"NVIDIA H200", false, 0x10DE}).compute);
  EXPECT_TRUE(passes::pick_rasterizer({"NVIDIA H100 80GB HBM3", false, 0x10DE}).compute);
  EXPECT_FALSE(passes::pick_rasterizer({"NVIDIA GeForce RTX 4090", false, 0x10DE}).compute);
  EXPECT_FALSE(passes::pick_rasterizer({"H200 lookalike", false, 0x1002}).compute);

  const auto registry = passes::builtin_pass_registry();
  const auto compile_for = [&](const std::string& format, std::optional<fg::DeviceTraits> device,
                               const nlohmann::json& params = nlohmann::json::object()) {
    std::ifstream in(repo_dir() / "tests/data/shadows/atlas.json");
    auto json = nlohmann::json::parse(in);
    json["resources"]["atlas"]["format"] = format;
    for (auto& p : json["passes"]) {
      if (p["name"] == "shadows") p["params"].update(params);
    }
    fg::CompileOptions options;
    options.viewport = {160, 90};
    options.device = std::move(device);
    return fg::compile_text(json.dump(2), "auto.json", registry.reflection(), options);
  };
  const auto access = [](const fg::Plan& plan) {
    return binding(plan, "shadows", "atlas")->access;
  };
  const fg::DeviceTraits h200{"NVIDIA H200", false, 0x10DE};
  struct Case {
    const char* format;
    std::optional<fg::DeviceTraits> device;
    fg::Access atlas;
    const char* says;
  };
  for (const Case& c : {
           Case{"d32f", std::nullopt, fg::Access::depth_attachment, "no device"},
           Case{"d32f", h200, fg::Access::transfer_dst, "NVIDIA H200 is an NVIDIA Hopper"},
           Case{"r32f", std::nullopt, fg::Access::storage_read_write, "only the compute"},
           Case{"d16", h200, fg::Access::depth_attachment, "only the hardware"},
       }) {
    const auto plan = compile_for(c.format, c.device);
    ASSERT_TRUE(plan.ok()) << c.format << "\n" << plan.diagnostics().to_text();
    EXPECT_EQ(access(plan.value()), c.atlas) << c.format;
    // The atlas's note (the G-buffer at /passes/0 has its own).
    const base::Diagnostic* note = nullptr;
    for (const auto& d : plan.diagnostics()) {
      if (d.code == "FG076" && d.pointer == "/passes/1") note = &d;
    }
    ASSERT_NE(note, nullptr) << plan.diagnostics().to_text();
    EXPECT_NE(note->message.find(c.says), std::string::npos) << note->message;
  }
  // A value written out is kept, whatever the device.
  const auto pinned = compile_for("d32f", h200, {{"rasterizer", "hardware"}});
  ASSERT_TRUE(pinned.ok());
  EXPECT_EQ(access(pinned.value()), fg::Access::depth_attachment);
  for (const auto& d : pinned.diagnostics()) {
    EXPECT_FALSE(d.code == "FG076" && d.pointer == "/passes/1") << d.message;
  }
}

// gbuffer's rasterizer "auto": compute (storage images, depth by copy) on Hopper GPUs,
// hardware on CPU devices, unmeasured GPUs, without a device and for non-d32f depth.
TEST(GBufferParams, AutoRasterizerChoosesByDeviceAndDepthFormat) {
  const auto registry = passes::builtin_pass_registry();
  const auto compile_for = [&](const std::string& depth, std::optional<fg::DeviceTraits> device,
                               const nlohmann::json& params = nlohmann::json::object()) {
    std::ifstream in(repo_dir() / "data/graphs/hard.json");
    auto json = nlohmann::json::parse(in);
    json["resources"]["depth"]["format"] = depth;
    for (auto& p : json["passes"]) {
      if (p["type"] == "gbuffer") p["params"] = params;
    }
    fg::CompileOptions options;
    options.viewport = {160, 90};
    options.device = std::move(device);
    return fg::compile_text(json.dump(2), "auto.json", registry.reflection(), options);
  };
  const fg::DeviceTraits h200{"NVIDIA H200", false, 0x10DE};
  struct Case {
    const char* depth;
    std::optional<fg::DeviceTraits> device;
    fg::Access normal;
    const char* says;
  };
  for (const Case& c : {
           Case{"d32f", std::nullopt, fg::Access::color_attachment, "no device"},
           Case{"d32f", h200, fg::Access::storage_write, "NVIDIA H200 is an NVIDIA Hopper"},
           Case{"d32f", fg::DeviceTraits{"llvmpipe (LLVM 15.0.6, 256 bits)", true, 0x10005},
                fg::Access::color_attachment, "CPU device"},
           Case{"d32f", fg::DeviceTraits{"NVIDIA GeForce RTX 4090", false, 0x10DE},
                fg::Access::color_attachment, "was not measured"},
           Case{"d16", h200, fg::Access::color_attachment, "not d32f"},
       }) {
    const auto plan = compile_for(c.depth, c.device);
    ASSERT_TRUE(plan.ok()) << c.says << "\n" << plan.diagnostics().to_text();
    const auto* normal = binding(plan.value(), "gbuffer", "normal");
    ASSERT_NE(normal, nullptr);
    EXPECT_EQ(normal->access, c.normal) << c.says;
    const base::Diagnostic* note = plan.diagnostics().find("FG076");
    ASSERT_NE(note, nullptr) << c.says;
    EXPECT_NE(note->message.find(c.says), std::string::npos) << note->message;
  }
  // A value written out is kept; "compute" with d16 is refused where written.
  const auto pinned = compile_for("d32f", h200, {{"rasterizer", "hardware"}});
  ASSERT_TRUE(pinned.ok());
  EXPECT_EQ(binding(pinned.value(), "gbuffer", "normal")->access, fg::Access::color_attachment);
  const auto refused = compile_for("d16", h200, {{"rasterizer", "compute"}});
  ASSERT_FALSE(refused.ok());
  const base::Diagnostic* error = refused.diagnostics().find("GB001");
  ASSERT_NE(error, nullptr) << refused.diagnostics().to_text();
  EXPECT_EQ(error->pointer, "/passes/0/params/rasterizer");
}
