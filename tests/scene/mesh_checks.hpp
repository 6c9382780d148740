#pragma once
// Geometric checks shared by the primitive and glTF tests.

#include <cmath>
#include <map>
#include <tuple>

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene::testing {

// Every directed edge (by position, quantised) of a closed, consistently wound mesh
// appears exactly once, paired with its reverse. Returns the number of edges that break
// this (0 for a watertight, consistently oriented mesh).
inline int unpaired_edges(const Mesh& mesh) {
  using Key = std::tuple<long, long, long>;
  const auto key = [](const glm::vec3& p) {
    const auto q = [](float v) { return std::lround(static_cast<double>(v) * 1e4); };
    return Key{q(p.x), q(p.y), q(p.z)};
  };
  std::map<std::pair<Key, Key>, int> directed;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    for (int e = 0; e < 3; ++e) {
      const Key a = key(mesh.vertices[mesh.indices[i + e]].position);
      const Key b = key(mesh.vertices[mesh.indices[i + (e + 1) % 3]].position);
      ++directed[{a, b}];
    }
  }
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
  }
  return bad;
}

// Triangles whose geometric normal disagrees with their vertex normals.
inline int misoriented_triangles(const Mesh& mesh) {
  int bad = 0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vertex& a = mesh.vertices[mesh.indices[i]];
    const Vertex& b = mesh.vertices[mesh.indices[i + 1]];
    const Vertex& c = mesh.vertices[mesh.indices[i + 2]];
    const glm::vec3 g = glm::cross(b.position - a.position, c.position - a.position);
    if (glm::dot(g, a.normal) <= 0.0f || glm::dot(g, b.normal) <= 0.0f ||
        glm::dot(g, c.normal) <= 0.0f) {
      ++bad;
    }
  }
  return bad;
}

inline bool normals_unit(const Mesh& mesh) {
  for (const Vertex& v : mesh.vertices) {
    if (std::abs(glm::length(v.normal) - 1.0f) > 1e-4f) return false;
  }
  return true;
}

}  // namespace antumbra::scene::testing
