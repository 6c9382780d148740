// The BVH the ray-traced shadow reference traverses (passes/common/bvh.hpp): the nearest
// hit it finds is brute force's on random soups, boxes and degenerate inputs, its layout
// keeps the GPU's promises (depth, leaf sizes, every triangle once), and bad input is
// refused or left out, never a crash.

#include "common/bvh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace {

using antumbra::passes::brute_force_hit;
using antumbra::passes::build_bvh;
using antumbra::passes::Bvh;
using antumbra::passes::closest_hit;
namespace shared = antumbra::shared;

struct Soup {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;

  void add(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), {a, b, c});
    indices.insert(indices.end(), {base, base + 1, base + 2});
  }
};

// `count` triangles of about `size` metres scattered over a cube of side `extent`.
Soup random_soup(std::uint32_t count, float extent, float size, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> where(-extent / 2, extent / 2);
  std::uniform_real_distribution<float> offset(-size, size);
  Soup soup;
  for (std::uint32_t t = 0; t < count; ++t) {
    const glm::vec3 c(where(rng), where(rng), where(rng));
    soup.add(c + glm::vec3(offset(rng), offset(rng), offset(rng)),
             c + glm::vec3(offset(rng), offset(rng), offset(rng)),
             c + glm::vec3(offset(rng), offset(rng), offset(rng)));
  }
  return soup;
}

// Every node's children nest in it, leaves hold at most kBvhLeafTriangles (below the
// depth cap) and together every kept triangle once, and the depth is within the GPU's
// stack.
void expect_well_formed(const Bvh& bvh, std::size_t kept) {
  ASSERT_LE(bvh.depth, shared::kBvhMaxDepth);
  std::vector<int> seen(bvh.triangles.size(), 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0u, 1u}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    ASSERT_LT(index, bvh.nodes.size());
    const shared::BvhNode& node = bvh.nodes[index];
    const auto first = std::bit_cast<std::uint32_t>(node.lo.w);
    const auto count = std::bit_cast<std::uint32_t>(node.hi.w);
    if (count == 0) {
      for (const std::uint32_t child : {index + 1, first}) {
        ASSERT_LT(child, bvh.nodes.size());
        const shared::BvhNode& c = bvh.nodes[child];
        for (int a = 0; a < 3; ++a) {
          EXPECT_LE(node.lo[a], c.lo[a]);
          EXPECT_GE(node.hi[a], c.hi[a]);
        }
        stack.push_back({child, depth + 1});
      }
      continue;
    }
    if (depth < shared::kBvhMaxDepth) {
      EXPECT_LE(count, shared::kBvhLeafTriangles);
    }
    for (std::uint32_t i = first; i < first + count; ++i) {
      ASSERT_LT(i, seen.size());
      ++seen[i];
    }
  }
  EXPECT_EQ(bvh.triangles.size(), kept);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

// Rays from random points in a cube of half side `extent` towards random points of the
// soup's finite bounds: the BVH's nearest hit is brute force's.
void expect_hits_match(const Soup& soup, const Bvh& bvh, float extent, std::uint32_t rays) {
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : soup.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> where(-extent, extent);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uint32_t hits = 0;
  for (std::uint32_t r = 0; r < rays; ++r) {
    const glm::vec3 origin(where(rng), where(rng), where(rng));
    const glm::vec3 target = lo + (hi - lo) * glm::vec3(unit(rng), unit(rng), unit(rng));
    const glm::vec3 direction = (target - origin) * 2.0f;  // past the target
    const auto want = brute_force_hit(soup.positions, soup.indices, origin, direction, 0.0f, 1.0f);
    const auto got = closest_hit(bvh, soup.positions, soup.indices, origin, direction, 0.0f, 1.0f);
    ASSERT_EQ(want.has_value(), got.has_value()) << "ray " << r;
    if (!want) continue;
    ++hits;
    EXPECT_EQ(got->t, want->t) << "ray " << r;  // ties may name either triangle
  }
  EXPECT_GT(hits, rays / 10) << "the rays meet the soup: the test says something";
}

TEST(Bvh, NearestHitIsBruteForcesOnARandomSoup) {
  const Soup soup = random_soup(3000, 20.0f, 1.0f, 1);
  const Bvh bvh = build_bvh(soup.positions, soup.indices);
  expect_well_formed(bvh, 3000);
  expect_hits_match(soup, bvh, 10.0f, 2000);
  // Surface-area splits over a uniform soup: no deeper than a few times log2.
  EXPECT_LE(bvh.depth, 30u);
}

TEST(Bvh, AxisAlignedBoxesAreHitOnTheirFaces) {
  // Closed boxes whose faces lie in the planes the BVH's boxes do: rays along the axes
  // graze the flat boxes around those faces.
  Soup soup;
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 lo(static_cast<float>(k) * 1.5f, 0.0f, 0.0f);
    const glm::vec3 hi = lo + glm::vec3(1.0f);
    const glm::vec3 v[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int quads[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};
    for (const auto& q : quads) {
      soup.add(v[q[0]], v[q[1]], v[q[2]]);
      soup.add(v[q[0]], v[q[2]], v[q[3]]);
    }
  }
  const Bvh bvh = build_bvh(soup.positions, soup.indices);
  expect_well_formed(bvh, soup.indices.size() / 3);
  // Straight down onto every box's top, and along x through all of them.
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 origin(static_cast<float>(k) * 1.5f + 0.25f, 5.0f, 0.5f);
    const auto hit = closest_hit(bvh, soup.positions, soup.indices, origin,
                                 glm::vec3(0.0f, -1.0f, 0.0f), 0.0f, 100.0f);
    ASSERT_TRUE(hit.has_value()) << "box " << k;
    EXPECT_FLOAT_EQ(hit->t, 4.0f);
  }
  const auto through = closest_hit(bvh, soup.positions, soup.indices, glm::vec3(-10.0f, 0.5f, 0.5f),
                                   glm::vec3(1.0f, 0.0f, 0.0f), 0.0f, 100.0f);
  ASSERT_TRUE(through.has_value());
  EXPECT_FLOAT_EQ(through->t, 10.0f);
  expect_hits_match(soup, bvh, 30.0f, 2000);
}

TEST(Bvh, DegenerateAndCoincidentTrianglesBuildAndAreNeverHit) {
  Soup soup;
  // 200 triangles on one point, 200 on one line, 200 identical real ones.
  for (int k = 0; k < 200; ++k) soup.add(glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f));
  for (int k = 0; k < 200; ++k) {
    soup.add(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f));
  }
  for (int k = 0; k < 200; ++k) {
    soup.add(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, -1.0f),
             glm::vec3(1.0f, 0.0f, -1.0f));
  }
  const Bvh bvh = build_bvh(soup.positions, soup.indices);
  // Centroids in one place cannot be split by a plane: halves by count, within the depth.
  expect_well_formed(bvh, 600);
  const auto through_point =
      closest_hit(bvh, soup.positions, soup.indices, glm::vec3(1.0f, 1.0f, 5.0f),
                  glm::vec3(0.0f, 0.0f, -1.0f), 0.0f, 100.0f);
  EXPECT_FALSE(through_point.has_value()) << "zero-area triangles are hit by nothing";
  const auto real = closest_hit(bvh, soup.positions, soup.indices, glm::vec3(0.2f, 0.2f, 5.0f),
                                glm::vec3(0.0f, 0.0f, -1.0f), 0.0f, 100.0f);
  ASSERT_TRUE(real.has_value());
  EXPECT_FLOAT_EQ(real->t, 6.0f);
  EXPECT_GE(real->triangle, 400u);
}

TEST(Bvh, HugeAndTinyTrianglesAndNonFiniteVerticesAreHandled) {
  Soup soup = random_soup(500, 2.0e6f, 1.0e5f, 3);  // a scene a thousand kilometres wide
  const Soup tiny = random_soup(500, 1.0e-3f, 1.0e-5f, 4);
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  soup.positions.insert(soup.positions.end(), tiny.positions.begin(), tiny.positions.end());
  for (const std::uint32_t index : tiny.indices) soup.indices.push_back(base + index);
  // Two triangles with a non-finite vertex: left out, and never hit.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  soup.add(glm::vec3(nan, 0.0f, 0.0f), glm::vec3(1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  soup.add(glm::vec3(inf, 0.0f, 0.0f), glm::vec3(1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const Bvh bvh = build_bvh(soup.positions, soup.indices);
  expect_well_formed(bvh, 1000);
  expect_hits_match(soup, bvh, 1.0e6f, 1000);
  // The tiny cluster at the origin, hit from outside it.
  std::uint32_t tiny_hits = 0;
  for (std::size_t t = 0; t < 500; ++t) {
    const glm::vec3 a = tiny.positions[tiny.indices[t * 3]];
    const glm::vec3 b = tiny.positions[tiny.indices[t * 3 + 1]];
    const glm::vec3 c = tiny.positions[tiny.indices[t * 3 + 2]];
    const glm::vec3 centre = (a + b + c) / 3.0f;
    const glm::vec3 origin = centre + glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 direction = centre - origin;
    const auto want = brute_force_hit(soup.positions, soup.indices, origin, direction, 0.0f, 2.0f);
    const auto got = closest_hit(bvh, soup.positions, soup.indices, origin, direction, 0.0f, 2.0f);
    ASSERT_EQ(want.has_value(), got.has_value()) << "tiny triangle " << t;
    if (got) {
      EXPECT_EQ(got->t, want->t);
      ++tiny_hits;
    }
  }
  EXPECT_GT(tiny_hits, 250u) << "a ray at a triangle's centre meets it (or one in front)";
}

TEST(Bvh, EmptyInputsAndBadIndices) {
  const Bvh empty = build_bvh({}, {});
  EXPECT_TRUE(empty.nodes.empty());
  EXPECT_TRUE(empty.triangles.empty());
  EXPECT_FALSE(closest_hit(empty, {}, {}, glm::vec3(0.0f), glm::vec3(1.0f), 0.0f, 1.0f));

  Soup one;
  one.add(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const Bvh single = build_bvh(one.positions, one.indices);
  ASSERT_EQ(single.nodes.size(), 1u);
  EXPECT_EQ(single.depth, 1u);
  // A zero direction meets nothing; a ray ending before the triangle neither.
  EXPECT_FALSE(closest_hit(single, one.positions, one.indices, glm::vec3(0.2f, 0.2f, 1.0f),
                           glm::vec3(0.0f), 0.0f, 10.0f));
  EXPECT_FALSE(closest_hit(single, one.positions, one.indices, glm::vec3(0.2f, 0.2f, 1.0f),
                           glm::vec3(0.0f, 0.0f, -1.0f), 0.0f, 0.5f));
  EXPECT_TRUE(closest_hit(single, one.positions, one.indices, glm::vec3(0.2f, 0.2f, 1.0f),
                          glm::vec3(0.0f, 0.0f, -1.0f), 0.0f, 1.5f));

  const std::vector<glm::vec3> three(3, glm::vec3(0.0f));
  const std::vector<std::uint32_t> past_the_end{0, 1, 3};
  EXPECT_THROW(build_bvh(three, past_the_end), std::invalid_argument);
  const std::vector<std::uint32_t> not_triangles{0, 1};
  EXPECT_THROW(build_bvh(three, not_triangles), std::invalid_argument);
}

}  // namespace
