// shadow-hard / shadow-pcf / shadow-pcss over a synthetic point-shadow atlas: a test
// pass ray-casts the scene (floor + a box between the light and the floor) into six
// 64x64 cube faces on the CPU and uploads them with the face matrices, following the
// shadow_data.h contract. Checks, along a floor line from under the box (umbra) to
// open floor: umbra dark, open floor fully lit (no acne), the hard edge where the
// geometry puts it and binary, PCF and PCSS with intermediate values at the penumbra.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/gpu/resources.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "executor_harness.hpp"
#include "lighting_test_support.hpp"

using namespace antumbra;
using namespace antumbra::lighting_testing;

namespace {

constexpr std::uint32_t kFace = 64;
constexpr float kNear = 0.05f;
const glm::vec3 kSyntheticLight{0.0f, 4.0f, 0.0f};
constexpr float kRange = 12.0f;
const glm::vec3 kBoxMin{-0.5f, 1.8f, -0.5f};
const glm::vec3 kBoxMax{0.5f, 2.2f, 0.5f};

glm::mat4 face_view_proj(std::uint32_t face) {
  static const glm::vec3 kDirs[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  static const glm::vec3 kUps[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                    {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  const glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, kNear, kRange);
  return proj * glm::lookAtRH(kSyntheticLight, kSyntheticLight + kDirs[face], kUps[face]);
}

// Nearest hit of the ray (light + t dir) with the floor plane y = 0 and the box.
float cast(const glm::vec3& dir) {
  float best = std::numeric_limits<float>::infinity();
  if (dir.y < 0.0f) best = -kSyntheticLight.y / dir.y;
  float t0 = 0.0f;
  float t1 = best;
  for (int a = 0; a < 3; ++a) {
    const float inv = 1.0f / dir[a];
    float n = (kBoxMin[a] - kSyntheticLight[a]) * inv;
    float f = (kBoxMax[a] - kSyntheticLight[a]) * inv;
    if (n > f) std::swap(n, f);
    t0 = std::max(t0, n);
    t1 = std::min(t1, f);
  }
  return t0 <= t1 ? t0 : best;
}

// "test-atlas-fill": the six faces of light 0 at atlas layers 0..5, plus shadowData.
class AtlasFillPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe() {
    fg::PassDesc desc;
    desc.type = "test-atlas-fill";
    desc.ports = {
        {.name = passes::port::kAtlas,
         .direction = fg::PortDirection::output,
         .access = fg::Access::transfer_dst,
         .stage = fg::Stage::transfer,
         .formats = {fg::Format::d32f},
         .min_layers = 6,
         .max_layers = 6},
        {.name = passes::port::kShadowData,
         .direction = fg::PortDirection::output,
         .kind = fg::ResourceKind::buffer,
         .access = fg::Access::transfer_dst,
         .stage = fg::Stage::transfer},
    };
    return desc;
  }
  explicit AtlasFillPass(const fg::PlanPass& /*pass*/) {}

  void prepare(fgvk::PrepareContext& context) override {
    staging_ = gpu::Buffer::create(context.gpu, VkDeviceSize{6} * kFace * kFace * 4,
                                   VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUsage::upload,
                                   "test.atlas.staging");
    auto* depth = reinterpret_cast<float*>(staging_.mapped());
    for (std::uint32_t face = 0; face < 6; ++face) {
      const glm::mat4 view_proj = face_view_proj(face);
      const glm::mat4 inv = glm::inverse(view_proj);
      for (std::uint32_t y = 0; y < kFace; ++y) {
        for (std::uint32_t x = 0; x < kFace; ++x) {
          const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / float(kFace) * 2.0f - 1.0f;
          const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
          const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - kSyntheticLight);
          const float t = cast(dir);
          float d = 1.0f;
          if (std::isfinite(t)) {
            const glm::vec4 clip = view_proj * glm::vec4(kSyntheticLight + t * dir, 1.0f);
            d = std::clamp(clip.z / clip.w, 0.0f, 1.0f);
          }
          depth[(face * kFace + y) * kFace + x] = d;
        }
      }
    }
    data_.assign(passes::shadow_data_bytes(6) / 4, 0u);
    auto* bytes = reinterpret_cast<std::uint8_t*>(data_.data());
    const passes::ShadowHeader header{{1u, 6u, kFace, 0u}};
    std::memcpy(bytes, &header, sizeof header);
    for (std::uint32_t i = 0; i < passes::kMaxShadowLights; ++i) {
      passes::ShadowLight light;  // no atlas slot
      if (i == 0) {
        light.position_range = glm::vec4(kSyntheticLight, kRange);
        light.params = glm::vec4(0.5f, kNear, 0.0f, 0.0f);
      }
      std::memcpy(bytes + passes::kShadowLightsOffset + i * sizeof light, &light, sizeof light);
    }
    for (std::uint32_t face = 0; face < 6; ++face) {
      const passes::ShadowFace f{face_view_proj(face),
                                 {0u, passes::encode_face_info(face, {.layer = face}), 1u, 0u}};
      std::memcpy(bytes + passes::kShadowFacesOffset + face * sizeof f, &f, sizeof f);
    }
  }

  void execute(fgvk::ExecuteContext& context) override {
    const auto& atlas = context.bindings.required_image(passes::port::kAtlas);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 6};
    region.imageExtent = {kFace, kFace, 1};
    vkCmdCopyBufferToImage(context.cmd, staging_.handle(), atlas.image, atlas.layout, 1, &region);
    // vkCmdUpdateBuffer takes at most 64 KiB a call; shadowData is larger.
    const VkBuffer shadow_data = context.bindings.buffer(passes::port::kShadowData)->buffer;
    const VkDeviceSize bytes = data_.size() * 4;
    for (VkDeviceSize offset = 0; offset < bytes; offset += 65536) {
      vkCmdUpdateBuffer(context.cmd, shadow_data, offset,
                        std::min<VkDeviceSize>(65536, bytes - offset),
                        reinterpret_cast<const std::byte*>(data_.data()) + offset);
    }
  }

 private:
  gpu::Buffer staging_;
  std::vector<std::uint32_t> data_;
};

// "test-depth-usage": reads the atlas as a depth attachment and draws nothing. The real
// atlas is rendered as a depth attachment; the synthetic one is only copied into, and
// sampling a depth image in DEPTH_STENCIL_READ_ONLY_OPTIMAL (the executor's layout for a
// sampled depth port) requires the attachment usage this declaration adds.
class DepthUsagePass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe() {
    fg::PassDesc desc;
    desc.type = "test-depth-usage";
    desc.ports = {{.name = passes::port::kAtlas,
                   .access = fg::Access::depth_read,
                   .stage = fg::Stage::graphics,
                   .formats = {fg::Format::d32f},
                   .min_layers = 6,
                   .max_layers = 6}};
    desc.side_effects = true;
    return desc;
  }
  explicit DepthUsagePass(const fg::PlanPass& /*pass*/) {}
  void prepare(fgvk::PrepareContext& /*context*/) override {}
  void execute(fgvk::ExecuteContext& /*context*/) override {}
};

std::unique_ptr<fgvk::Pass> make_depth_usage(const fg::PlanPass& pass) {
  return std::make_unique<DepthUsagePass>(pass);
}

std::unique_ptr<fgvk::Pass> make_atlas_fill(const fg::PlanPass& pass) {
  return std::make_unique<AtlasFillPass>(pass);
}

std::string shadow_graph(const std::string& type, const std::string& params) {
  const bool with_atlas = type != "tiled-lighting" || params.find("shadows") != std::string::npos;
  return R"({ "version": 1, "name": "synthetic-atlas", "resources": {
    "depth": { "kind": "image", "format": "d32f", "size": "viewport" },
    "normal": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "albedo": { "kind": "image", "format": "rgba8", "size": "viewport" },
    "atlas": { "kind": "image", "format": "d32f", "size": [64, 64], "layers": 6 },
    "shadowData": { "kind": "buffer", "size": )" +
         std::to_string(passes::shadow_data_bytes(6)) + R"( },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" } },
  "passes": [
    { "name": "gbuffer", "type": "gbuffer", "out": { "depth": "depth", "normal": "normal", "albedo": "albedo" } },
    { "name": "fill", "type": "test-atlas-fill", "out": { "atlas": "atlas", "shadowData": "shadowData" } },
    { "name": "usage", "type": "test-depth-usage", "in": { "atlas": "atlas" } },
    { "name": "lighting", "type": ")" +
         type + R"(", "params": )" + params + R"(,
      "in": { "depth": "depth", "normal": "normal", "albedo": "albedo")" +
         (with_atlas ? R"(, "atlas": "atlas", "shadowData": "shadowData")" : "") + R"( },
      "out": { "hdr": "hdr" } } ],
  "output": "hdr" })";
}

class SyntheticAtlasTest : public ExecutorTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    scene::Scene scene = floor_scene();
    add_box(scene, 0.5f * (kBoxMin + kBoxMax), kBoxMax - kBoxMin);
    add_light(scene, kSyntheticLight, {1.0f, 1.0f, 1.0f}, 20.0f, kRange, 0.5f);
    if (!open(std::move(scene), {{AtlasFillPass::describe(), &make_atlas_fill},
                                 {DepthUsagePass::describe(), &make_depth_usage}})) {
      GTEST_SKIP() << skip_reason_;
    }
    unshadowed_ = render(shadow_graph("tiled-lighting", "{}"), kGolden);
  }

  std::vector<std::pair<float, float>> profile(const gpu::HostImage& hdr) const {
    return floor_light_fraction(scene_, kGolden, hdr, unshadowed_);
  }

  // Checks shared by every mode; returns the number of penumbra samples.
  int check_profile(const std::string& what, const gpu::HostImage& hdr) const {
    int penumbra = 0;
    std::string line;
    for (const auto& [x, f] : profile(hdr)) {
      if (x < 0.3f) {
        EXPECT_LT(f, 0.02f) << what << ": umbra at x = " << x;
      }
      if (x > 2.2f) {
        EXPECT_GT(f, 0.98f) << what << ": open floor at x = " << x;
      }
      if (f > 0.05f && f < 0.95f) ++penumbra;
      char buf[32];
      std::snprintf(buf, sizeof buf, " %.2f:%.2f", x, f);
      if (x > 0.6f && x < 1.8f) line += buf;
    }
    std::printf("%s profile (x:fraction):%s\n", what.c_str(), line.c_str());
    return penumbra;
  }

  gpu::HostImage unshadowed_;
};

}  // namespace

TEST_F(SyntheticAtlasTest, HardShadowIsBinaryWithTheEdgeWhereTheGeometryPutsIt) {
  const auto hdr = render(shadow_graph("shadow-hard", "{}"), kGolden);
  EXPECT_EQ(check_profile("hard", hdr), 0);
  // The ray over the box's top edge (y 2.2, x 0.5) reaches the floor at x = 0.5 * 4 / 1.8.
  float edge = -1.0f;
  for (const auto& [x, f] : profile(hdr)) {
    if (edge < 0.0f && f > 0.5f) edge = x;
  }
  EXPECT_NEAR(edge, 0.5f * 4.0f / 1.8f, 0.2f);
}

TEST_F(SyntheticAtlasTest, PcfAndPcssHavePenumbrae) {
  const int pcf =
      check_profile("pcf 11", render(shadow_graph("shadow-pcf", R"({"kernel": "11"})"), kGolden));
  const int pcss = check_profile(
      "pcss 5+11",
      render(shadow_graph("shadow-pcss", R"({"kernel": "11", "blockerSearch": 5})"), kGolden));
  EXPECT_GE(pcf, 3);
  EXPECT_GE(pcss, 2);
  // The same through tiled-lighting's modes (one shared shader, so equal images).
  const auto pcf_mode =
      render(shadow_graph("tiled-lighting", R"({"shadows": "pcf", "kernel": "11"})"), kGolden);
  EXPECT_EQ(check_profile("tiled-lighting pcf", pcf_mode), pcf);
}
