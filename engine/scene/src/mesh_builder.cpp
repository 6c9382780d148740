#include "mesh_builder.hpp"

#include <vector>

namespace antumbra::scene::detail {

std::uint32_t MeshBuilder::vertex(const glm::vec3& position, const glm::vec3& normal,
                                  const glm::vec2& uv) {
  mesh_.vertices.push_back(Vertex{position, normal, uv});
  return static_cast<std::uint32_t>(mesh_.vertices.size() - 1);
}

void MeshBuilder::triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const Vertex& va = mesh_.vertices[a];
  const Vertex& vb = mesh_.vertices[b];
  const Vertex& vc = mesh_.vertices[c];
  const glm::vec3 geometric = glm::cross(vb.position - va.position, vc.position - va.position);
  if (glm::dot(geometric, geometric) <= 0.0f) return;
  const glm::vec3 wanted = va.normal + vb.normal + vc.normal;
  if (glm::dot(geometric, wanted) < 0.0f) std::swap(b, c);
  mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
}

void MeshBuilder::polygon(const std::vector<Vertex>& corners) {
  std::vector<std::uint32_t> ids;
  ids.reserve(corners.size());
  for (const Vertex& v : corners) ids.push_back(vertex(v.position, v.normal, v.uv));
  for (std::size_t i = 1; i + 1 < ids.size(); ++i) triangle(ids[0], ids[i], ids[i + 1]);
}

}  // namespace antumbra::scene::detail
