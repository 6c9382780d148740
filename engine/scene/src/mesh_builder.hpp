#pragma once
// Appends vertices and triangles to a Mesh, orienting every face from its vertex
// normals: a face is wound counter-clockwise around the direction its normals point
// to. Builders then only need correct normals, and winding mistakes cannot creep in.

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene::detail {

class MeshBuilder {
 public:
  explicit MeshBuilder(Mesh& mesh) : mesh_(mesh) {}

  std::uint32_t vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv);
  // Triangle of existing vertices, flipped if its geometric normal disagrees with the
  // sum of its vertex normals. Degenerate triangles are dropped.
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Convex planar polygon of new vertices (in order around the perimeter), fan-split.
  void polygon(const std::vector<Vertex>& corners);
  void polygon(std::initializer_list<Vertex> corners) { polygon(std::vector<Vertex>(corners)); }
  void quad(const Vertex& a, const Vertex& b, const Vertex& c, const Vertex& d) {
    polygon({a, b, c, d});
  }

 private:
  Mesh& mesh_;
};

}  // namespace antumbra::scene::detail
