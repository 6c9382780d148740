// common/bvh.glsl on a device: the shader's nearest hits are the CPU traversal's (the
// builder's own, tested against brute force in bvh_test.cpp) for rays through a random
// soup and a row of axis-aligned boxes, within float's rounding (the CPU tests triangles
// in double): hit or miss agree on all but a stated handful of grazing rays, and the
// distances within 1e-4 of the ray's length.

#include <bit>
#include <cstdio>
#include <cstring>
#include <random>

#include "atlas_gpu_fixture.hpp"
#include "common/bvh.hpp"

namespace {

class BvhGpuTest : public AtlasGpuTest {};

TEST_F(BvhGpuTest, ShaderTraversalFindsTheCpusNearestHits) {
  // A soup of 2000 triangles in a 20 m cube and a floor under it.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> where(-10.0f, 10.0f);
  std::uniform_real_distribution<float> offset(-1.0f, 1.0f);
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  const auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), {a, b, c});
    indices.insert(indices.end(), {base, base + 1, base + 2});
  };
  for (int t = 0; t < 2000; ++t) {
    const glm::vec3 c(where(rng), where(rng), where(rng));
    add(c + glm::vec3(offset(rng), offset(rng), offset(rng)),
        c + glm::vec3(offset(rng), offset(rng), offset(rng)),
        c + glm::vec3(offset(rng), offset(rng), offset(rng)));
  }
  add(glm::vec3(-20.0f, -11.0f, -20.0f), glm::vec3(20.0f, -11.0f, -20.0f),
      glm::vec3(20.0f, -11.0f, 20.0f));
  add(glm::vec3(-20.0f, -11.0f, -20.0f), glm::vec3(20.0f, -11.0f, 20.0f),
      glm::vec3(-20.0f, -11.0f, 20.0f));
  const passes::Bvh bvh = passes::build_bvh(positions, indices);
  const std::vector<glm::vec4> vertices = passes::bvh_vertices(bvh, positions, indices);

  std::vector<std::byte> data(16 + bvh.nodes.size() * sizeof(shared::BvhNode) +
                              vertices.size() * sizeof(glm::vec4));
  const glm::uvec4 header(static_cast<std::uint32_t>(bvh.nodes.size()), 0u, 0u, 0u);
  std::memcpy(data.data(), &header, 16);
  std::memcpy(data.data() + 16, bvh.nodes.data(), bvh.nodes.size() * sizeof(shared::BvhNode));
  std::memcpy(data.data() + 16 + bvh.nodes.size() * sizeof(shared::BvhNode), vertices.data(),
              vertices.size() * sizeof(glm::vec4));

  // Rays from a 30 m cube towards points of the soup's cube and past it, and straight down.
  constexpr std::size_t kRays = 4096;
  std::vector<glm::vec4> points;
  std::uniform_real_distribution<float> far(-15.0f, 15.0f);
  for (std::size_t r = 0; r < kRays; ++r) {
    const glm::vec3 origin(far(rng), far(rng), far(rng));
    glm::vec3 direction = glm::vec3(where(rng), where(rng), where(rng)) - origin;
    if (r % 8 == 0) direction = glm::vec3(0.0f, -1.0f, 0.0f);
    points.emplace_back(origin, 0.0f);
    points.emplace_back(direction, r % 8 == 0 ? 100.0f : 2.0f);
  }
  const std::vector<glm::vec4> out =
      run_check_shader("tests/shadows/bvh_check.comp", {}, data, points);
  ASSERT_EQ(out.size(), points.size());

  int hits = 0;
  int disagreements = 0;
  float worst = 0.0f;
  for (std::size_t r = 0; r < kRays; ++r) {
    const glm::vec4 origin = points[2 * r];
    const glm::vec4 direction = points[2 * r + 1];
    const auto cpu = passes::closest_hit(bvh, positions, indices, glm::vec3(origin),
                                         glm::vec3(direction), origin.w, direction.w);
    const glm::vec4 gpu = out[2 * r];
    if (cpu.has_value() != (gpu.x > 0.5f)) {
      ++disagreements;
      continue;
    }
    if (!cpu) continue;
    ++hits;
    worst = std::max(worst, std::abs(gpu.y - cpu->t) * glm::length(glm::vec3(direction)));
    // The same triangle, or one the ray meets at the same distance (within rounding).
    if (std::bit_cast<std::uint32_t>(gpu.z) != cpu->triangle) {
      EXPECT_NEAR(gpu.y, cpu->t, 1e-4f) << "ray " << r;
    }
  }
  std::printf("bvh on the device: %d of %zu rays hit, %d disagree on hit or miss, worst %.2e m\n",
              hits, kRays, disagreements, static_cast<double>(worst));
  EXPECT_GT(static_cast<std::size_t>(hits), kRays / 4)
      << "the rays meet the soup: the test says something";
  EXPECT_LE(disagreements, 4) << "only rays grazing an edge may fall either side of it";
  EXPECT_LT(worst, 1e-4f) << "metres";
}

}  // namespace
