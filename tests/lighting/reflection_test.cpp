// Reflection of the tiled-lighting family: the four pass types, their ports and params,
// and what the graph compiler accepts (CPU only, no device).

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "antumbra/fg/compiler.hpp"
#include "register_builtin_passes.hpp"

using namespace antumbra;

namespace {

const fg::PortDesc* port(const fg::PassDesc& desc, const char* name) {
  return desc.find_port(name);
}

// A G-buffer and one lighting pass of `type` with `params`, no shadow inputs bound.
std::string lighting_graph(const std::string& type, const std::string& params) {
  std::string text = R"({ "version": 1, "name": "t", "resources": {
    "depth": { "kind": "image", "format": "d32f", "size": "viewport" },
    "normal": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "albedo": { "kind": "image", "format": "rgba8", "size": "viewport" },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" } },
  "passes": [
    { "name": "gbuffer", "type": "gbuffer", "out": { "depth": "depth", "normal": "normal", "albedo": "albedo" } },
    { "name": "lighting", "type": ")" +
                     type + R"(", "params": )" + params + R"(,
      "in": { "depth": "depth", "normal": "normal", "albedo": "albedo" },
      "out": { "hdr": "hdr" } } ],
  "output": "hdr" })";
  return text;
}

base::Diagnostics compile_text(const std::string& text) {
  const auto registry = passes::builtin_pass_registry();
  return fg::compile_text(text, "test.json", registry.reflection()).diagnostics();
}

}  // namespace

TEST(TiledLightingReflection, RegistersTheFourTypes) {
  const auto registry = passes::builtin_pass_registry();
  const auto& reflection = registry.reflection();
  for (const char* type : {"tiled-lighting", "shadow-hard", "shadow-pcf", "shadow-pcss"}) {
    const auto* desc = reflection.find(type);
    ASSERT_NE(desc, nullptr) << type;
    for (const char* name : {"depth", "normal", "albedo", "hdr"}) {
      ASSERT_NE(port(*desc, name), nullptr) << type << " " << name;
      EXPECT_EQ(port(*desc, name)->stage, fg::Stage::compute);
    }
    EXPECT_EQ(port(*desc, "hdr")->access, fg::Access::storage_write);
    ASSERT_NE(port(*desc, "atlas"), nullptr);
    ASSERT_NE(port(*desc, "shadowData"), nullptr);
    const bool baseline = std::string(type) != "tiled-lighting";
    EXPECT_EQ(port(*desc, "atlas")->optional, !baseline) << type;
    EXPECT_EQ(port(*desc, "shadowData")->optional, !baseline) << type;
    EXPECT_EQ(port(*desc, "shadowData")->kind, fg::ResourceKind::buffer);
    for (const char* name : {"exposure", "ambient", "specular"}) {
      EXPECT_NE(desc->find_param(name), nullptr) << type << " " << name;
    }
  }
  const auto* tiled = reflection.find("tiled-lighting");
  EXPECT_EQ(tiled->find_param("shadows")->default_value, "none");
  for (const char* name : {"layerTable", "shadow", "colour"}) {
    ASSERT_NE(port(*tiled, name), nullptr) << name;
    EXPECT_TRUE(port(*tiled, name)->optional) << name;
  }
  EXPECT_EQ(reflection.find("shadow-hard")->find_param("kernel"), nullptr);
  EXPECT_NE(reflection.find("shadow-pcf")->find_param("kernel"), nullptr);
  EXPECT_EQ(reflection.find("shadow-pcf")->find_param("blockerSearch"), nullptr);
  const auto* pcss = reflection.find("shadow-pcss");
  EXPECT_EQ(pcss->find_param("blockerSearch")->default_value, 5);
  EXPECT_EQ(pcss->find_param("lightSizeScale")->default_value, 1.0);
  EXPECT_EQ(pcss->find_param("kernel")->choices, (std::vector<std::string>{"5", "11", "23"}));
}

TEST(TiledLightingReflection, CompilerChecksModesAndKernels) {
  EXPECT_FALSE(compile_text(lighting_graph("tiled-lighting", "{}")).has_errors())
      << compile_text(lighting_graph("tiled-lighting", "{}")).to_text();
  const auto bad_kernel = compile_text(lighting_graph("tiled-lighting", R"({"kernel": "7"})"));
  EXPECT_TRUE(bad_kernel.has_errors());
  const auto int_kernel = compile_text(lighting_graph("tiled-lighting", R"({"kernel": 11})"));
  EXPECT_TRUE(int_kernel.has_errors());
  const auto bad_mode = compile_text(lighting_graph("tiled-lighting", R"({"shadows": "pcs"})"));
  EXPECT_TRUE(bad_mode.has_errors());
  // The baselines require the atlas ports.
  const auto missing = compile_text(lighting_graph("shadow-pcf", R"({"kernel": "5"})"));
  EXPECT_TRUE(missing.has_errors());
}
