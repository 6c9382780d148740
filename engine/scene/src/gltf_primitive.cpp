#include <cmath>

#include "antumbra/base/diagnostic_codes.hpp"
#include "gltf_accessors.hpp"

namespace antumbra::scene::detail {
namespace {

constexpr int kModeTriangles = TINYGLTF_MODE_TRIANGLES;
constexpr int kModeStrip = TINYGLTF_MODE_TRIANGLE_STRIP;
constexpr int kModeFan = TINYGLTF_MODE_TRIANGLE_FAN;

int attribute(const tinygltf::Primitive& prim, const char* name) {
  const auto it = prim.attributes.find(name);
  return it == prim.attributes.end() ? -1 : it->second;
}

std::vector<std::uint32_t> to_triangle_list(const std::vector<std::uint32_t>& in, int mode) {
  if (mode == kModeTriangles) return in;
  std::vector<std::uint32_t> out;
  for (std::size_t i = 2; i < in.size(); ++i) {
    if (mode == kModeFan) {
      out.insert(out.end(), {in[0], in[i - 1], in[i]});
    } else if (i % 2 == 0) {  // strips alternate winding to keep one orientation
      out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
    } else {
      out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
    }
  }
  return out;
}

bool usable_normal(const glm::vec3& n) {
  return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) && glm::dot(n, n) > 1e-12f;
}

// Area-weighted smooth normals over shared vertices (flat for unshared ones).
void compute_normals(Mesh& mesh, bool only_unusable) {
  std::vector<glm::vec3> sum(mesh.vertices.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    const glm::vec3 n = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                   mesh.vertices[c].position - mesh.vertices[a].position);
    sum[a] += n;
    sum[b] += n;
    sum[c] += n;
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    glm::vec3& n = mesh.vertices[v].normal;
    if (only_unusable && usable_normal(n)) {
      n = glm::normalize(n);
      continue;
    }
    n = usable_normal(sum[v]) ? glm::normalize(sum[v]) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

// An attribute of `n` elements beside POSITION's `count`.
bool same_count(std::size_t n, std::size_t count, const char* what, const std::string& p,
                GltfIssue& issue) {
  if (n == count) return true;
  return fail(issue, codes::scene::kGltfCountMismatch,
              std::string(what) + " has " + std::to_string(n) + " elements but POSITION has " +
                  std::to_string(count),
              p + "/attributes/" + what);
}

struct ShadingAttributes {
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec2> uvs1;
  std::vector<glm::vec4> tangents;  // read only when a normal map needs them
};

// TEXCOORD_0, TEXCOORD_1 and TANGENT, each `count` long when present.
bool read_shading_attributes(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                             const std::string& p, std::size_t count, bool want_tangents,
                             ShadingAttributes& out, GltfIssue& issue,
                             std::vector<GltfIssue>& warnings) {
  const auto check_count = [&](std::size_t n, const char* what) {
    return same_count(n, count, what, p, issue);
  };
  for (const char* set : {"TEXCOORD_0", "TEXCOORD_1"}) {
    const int id = attribute(prim, set);
    if (id < 0) continue;
    auto& target = std::string_view(set) == "TEXCOORD_0" ? out.uvs : out.uvs1;
    if (!read_texcoords(model, id, p + "/attributes/" + set, set, target, issue)) return false;
    if (!check_count(target.size(), set)) return false;
  }
  const int id = attribute(prim, "TANGENT");
  if (id < 0 || !want_tangents) return true;
  if (!read_tangents(model, id, p + "/attributes/TANGENT", out.tangents, issue)) return false;
  if (!check_count(out.tangents.size(), "TANGENT")) return false;
  // Unusable ones (zero, NaN) make the whole set generated instead.
  for (const glm::vec4& t : out.tangents) {
    if (!usable_normal(glm::vec3(t)) || !std::isfinite(t.w)) {
      warnings.push_back({codes::scene::kGltfNonFinite,
                          "TANGENT has zero or non-finite vectors; tangents are generated",
                          p + "/attributes/TANGENT"});
      out.tangents.clear();
      break;
    }
  }
  return true;
}

}  // namespace

void generate_tangents(Mesh& mesh, int set) {
  std::vector<glm::vec3> tangent(mesh.vertices.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> bitangent(mesh.vertices.size(), glm::vec3(0.0f));
  const auto uv = [&](std::uint32_t v) {
    return set == 1 ? mesh.vertices[v].uv1 : mesh.vertices[v].uv;
  };
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    const glm::vec3 e1 = mesh.vertices[b].position - mesh.vertices[a].position;
    const glm::vec3 e2 = mesh.vertices[c].position - mesh.vertices[a].position;
    const glm::vec2 d1 = uv(b) - uv(a);
    const glm::vec2 d2 = uv(c) - uv(a);
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(det) || std::abs(det) < 1e-20f) continue;  // no uv gradient
    // Weighted by the triangle's area in position space (the unnormalised solve).
    const float sign = det > 0.0f ? 1.0f : -1.0f;
    const glm::vec3 t = (e1 * d2.y - e2 * d1.y) * sign;
    const glm::vec3 bt = (e2 * d1.x - e1 * d2.x) * sign;
    for (const std::uint32_t v : {a, b, c}) {
      tangent[v] += t;
      bitangent[v] += bt;
    }
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    Vertex& vx = mesh.vertices[v];
    glm::vec3 t = tangent[v] - vx.normal * glm::dot(vx.normal, tangent[v]);
    if (!usable_normal(t)) {
      // No gradient (degenerate or constant uv): any direction across the normal.
      t = glm::cross(vx.normal,
                     std::abs(vx.normal.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
    }
    t = glm::normalize(t);
    // glTF's v runs down the image while a normal map's green points up it: the
    // bitangent, cross(normal, tangent) * w, runs against the coordinates' v gradient.
    const float w = glm::dot(glm::cross(vx.normal, t), bitangent[v]) > 0.0f ? -1.0f : 1.0f;
    vx.tangent = glm::vec4(t, w);
  }
}

bool build_primitive_mesh(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                          const std::string& p, int tangent_set, Mesh& mesh, GltfIssue& issue,
                          std::vector<GltfIssue>& warnings) {
  if (prim.mode >= 0 && prim.mode < kModeTriangles) {
    warnings.push_back(
        {codes::scene::kGltfUnsupported, "points and lines are skipped", p + "/mode"});
    return true;
  }
  if (prim.mode != kModeTriangles && prim.mode != kModeStrip && prim.mode != kModeFan) {
    return fail(issue, codes::scene::kGltfParse,
                "invalid primitive mode " + std::to_string(prim.mode), p + "/mode");
  }
  const int position_id = attribute(prim, "POSITION");
  if (position_id < 0) {
    return fail(issue, codes::scene::kGltfBadAccessor, "primitive has no POSITION attribute",
                p + "/attributes");
  }
  std::vector<glm::vec3> positions;
  if (!read_positions(model, position_id, p + "/attributes/POSITION", positions, issue)) {
    return false;
  }
  for (const glm::vec3& v : positions) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      return fail(issue, codes::scene::kGltfNonFinite, "POSITION contains NaN or infinite values",
                  "/accessors/" + std::to_string(position_id));
    }
  }
  const std::size_t count = positions.size();
  const auto check_count = [&](std::size_t n, const char* what) {
    return same_count(n, count, what, p, issue);
  };
  std::vector<glm::vec3> normals;
  if (const int id = attribute(prim, "NORMAL"); id >= 0) {
    if (!read_normals(model, id, p + "/attributes/NORMAL", normals, issue)) return false;
    if (!check_count(normals.size(), "NORMAL")) return false;
  }
  ShadingAttributes shading;
  if (!read_shading_attributes(model, prim, p, count, tangent_set >= 0, shading, issue, warnings)) {
    return false;
  }
  const auto& uvs = shading.uvs;
  const auto& uvs1 = shading.uvs1;
  const auto& tangents = shading.tangents;
  std::vector<std::uint32_t> indices;
  if (prim.indices >= 0) {
    if (!read_indices(model, prim.indices, p + "/indices", indices, issue)) return false;
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= count) {
        return fail(issue, codes::scene::kGltfIndexOutOfRange,
                    "index " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
                        " is out of range for " + std::to_string(count) + " vertices",
                    "/accessors/" + std::to_string(prim.indices));
      }
    }
  } else {
    indices.resize(count);
    for (std::size_t i = 0; i < count; ++i) indices[i] = static_cast<std::uint32_t>(i);
  }
  if (prim.mode == kModeTriangles && indices.size() % 3 != 0) {
    return fail(issue, codes::scene::kGltfCountMismatch,
                std::to_string(indices.size()) + " indices do not form whole triangles",
                prim.indices >= 0 ? "/accessors/" + std::to_string(prim.indices) : p);
  }
  mesh.vertices.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    mesh.vertices[i].position = positions[i];
    mesh.vertices[i].normal = normals.empty() ? glm::vec3(0.0f) : normals[i];
    mesh.vertices[i].uv = uvs.empty() ? glm::vec2(0.0f) : uvs[i];
    mesh.vertices[i].uv1 = uvs1.empty() ? glm::vec2(0.0f) : uvs1[i];
    if (!tangents.empty()) {
      mesh.vertices[i].tangent =
          glm::vec4(glm::normalize(glm::vec3(tangents[i])), tangents[i].w < 0.0f ? -1.0f : 1.0f);
    }
  }
  mesh.indices = to_triangle_list(indices, prim.mode);
  compute_normals(mesh, /*only_unusable=*/!normals.empty());
  if (tangent_set >= 0 && tangents.empty()) generate_tangents(mesh, tangent_set);
  return true;
}

}  // namespace antumbra::scene::detail
