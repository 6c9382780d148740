// The edge-adjacency list penumbra-wedges extracts silhouettes from
// (penumbra_wedges/silhouette_edges.hpp): welding by position, the two triangles of each
// edge, open and non-manifold edges, winding flips and welded normals.

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "penumbra_wedges/silhouette_edges.hpp"

namespace antumbra::passes {
namespace {

struct Mesh {
  std::vector<GpuVertex> vertices;
  std::vector<std::uint32_t> indices;
};

// A unit cube as a glTF exporter writes it: 4 vertices per face (24, split so each face
// has its own normal), two counter-clockwise triangles per face seen from outside.
Mesh split_cube() {
  Mesh m;
  const std::array<glm::vec3, 6> normals{glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0),
                                         glm::vec3(0, 1, 0), glm::vec3(0, -1, 0),
                                         glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)};
  for (const glm::vec3& n : normals) {
    // Two axes spanning the face, u x v = n.
    const glm::vec3 u = std::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 v = glm::cross(n, u);
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (const glm::vec2 c :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      m.vertices.push_back({0.5f * (n + c.x * u + c.y * v), n, 0});
    }
    // u x v = n: (0, 1, 2) runs counter-clockwise seen from outside.
    for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
  }
  return m;
}

TEST(SilhouetteEdges, SplitCubeWeldsIntoAClosedSurface) {
  const Mesh cube = split_cube();
  const EdgeList list = build_edge_list(cube.vertices, cube.indices);
  EXPECT_EQ(list.welded_vertices, 8u);
  EXPECT_EQ(list.edges.size(), 18u);  // 12 cube edges and 6 face diagonals
  EXPECT_EQ(list.boundary, 0u);
  EXPECT_EQ(list.nonmanifold, 0u);
  for (const auto& e : list.edges) {
    EXPECT_NE(e.vertices.w, ANTUMBRA_NO_TRIANGLE);
    EXPECT_EQ(e.welded.z & ANTUMBRA_EDGE_FLIPPED, 0u) << "consistently wound";
  }
  // Every corner meets three faces at right angles: the welded normal is the diagonal.
  ASSERT_EQ(list.normals.size(), 8u);
  for (const auto& v : cube.vertices) {
    const glm::vec3 expected = glm::normalize(glm::sign(v.position));
    bool found = false;
    for (const auto& n : list.normals) {
      found = found || glm::length(glm::vec3(n) - expected) < 1e-5f;
    }
    EXPECT_TRUE(found) << v.position.x << " " << v.position.y << " " << v.position.z;
  }
}

TEST(SilhouetteEdges, EachEdgeNamesItsTwoTrianglesThirdVertices) {
  const Mesh cube = split_cube();
  const EdgeList list = build_edge_list(cube.vertices, cube.indices);
  for (const auto& e : list.edges) {
    const glm::vec3 p0 = cube.vertices[e.vertices.x].position;
    const glm::vec3 p1 = cube.vertices[e.vertices.y].position;
    const glm::vec3 a = cube.vertices[e.vertices.z].position;
    const glm::vec3 b = cube.vertices[e.vertices.w].position;
    // The first triangle (p0, p1, a) and the second (p1, p0, b) both face outwards.
    const glm::vec3 centre = (p0 + p1) * 0.5f;
    EXPECT_GT(glm::dot(glm::cross(p1 - p0, a - p0), centre), 0.0f);
    EXPECT_GT(glm::dot(glm::cross(p0 - p1, b - p1), centre), 0.0f);
  }
}

TEST(SilhouetteEdges, OpenQuadHasFourBoundaryEdges) {
  Mesh quad;
  for (const glm::vec3 p :
       {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 0, 1), glm::vec3(0, 0, 1)}) {
    quad.vertices.push_back({p, glm::vec3(0, 1, 0), 0});
  }
  quad.indices = {0, 2, 1, 0, 3, 2};
  const EdgeList list = build_edge_list(quad.vertices, quad.indices);
  EXPECT_EQ(list.edges.size(), 5u);
  EXPECT_EQ(list.boundary, 4u);
  int open = 0;
  for (const auto& e : list.edges) open += e.vertices.w == ANTUMBRA_NO_TRIANGLE ? 1 : 0;
  EXPECT_EQ(open, 4);
}

TEST(SilhouetteEdges, WindingFlipsAreFlaggedAndBadTrianglesSkipped) {
  Mesh m;
  for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1),
                            glm::vec3(1, 0, 1), glm::vec3(0, 1, 0)}) {
    m.vertices.push_back({p, glm::vec3(0, 1, 0), 0});
  }
  // The second triangle runs along the shared edge (1 -> 2) the same way as the first.
  m.indices = {0, 1, 2, 1, 2, 3, 0, 0, 4,  // degenerate
               0, 1, 99};                  // an index out of range
  const EdgeList list = build_edge_list(m.vertices, m.indices);
  EXPECT_EQ(list.edges.size(), 5u);
  int flipped = 0;
  for (const auto& e : list.edges) flipped += (e.welded.z & ANTUMBRA_EDGE_FLIPPED) != 0u ? 1 : 0;
  EXPECT_EQ(flipped, 1);
}

TEST(SilhouetteEdges, NonManifoldEdgesBecomeOpenEdges) {
  Mesh m;
  for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                            glm::vec3(0, -1, 0), glm::vec3(0, 0, 1)}) {
    m.vertices.push_back({p, glm::vec3(0, 0, 1), 0});
  }
  m.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};  // three fins on the edge 0-1
  const EdgeList list = build_edge_list(m.vertices, m.indices);
  EXPECT_EQ(list.nonmanifold, 3u);
  EXPECT_EQ(list.boundary, 6u);
  EXPECT_EQ(list.edges.size(), 9u);
}

}  // namespace
}  // namespace antumbra::passes
