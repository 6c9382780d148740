// The arch primitive: a 2D outline (piers + curved top around an opening) extruded
// along Z. Built with its base at y = 0, then centred on its bounding box.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "antumbra/scene/primitives.hpp"
#include "mesh_builder.hpp"

namespace antumbra::scene {
namespace {

using detail::MeshBuilder;

// The left half of the arch as seen from +Z, sampled along rays from the springline
// centre O = (0, springline): `curve` on the intrados, `outer` on the outline (the
// left side then the top). Both halves of the shape are star-shaped around O, so the
// quads between consecutive rays never overlap.
struct HalfArch {
  std::vector<glm::vec2> curve;
  std::vector<glm::vec2> outer;
  glm::vec2 center;  // centre of the left intrados arc (normals point to it)
};

HalfArch sample_left_half(const ArchParams& p, float springline) {
  constexpr float kHalfPi = std::numbers::pi_v<float> * 0.5f;
  const float half_w = p.width * 0.5f;
  const float opening = p.width - 2.0f * p.pier_width;
  const glm::vec2 origin(0.0f, springline);
  HalfArch half;
  float radius = opening * 0.5f;
  half.center = origin;
  if (p.style == ArchStyle::pointed) {  // equilateral: radius = span, centre at the far side
    radius = opening;
    half.center = glm::vec2(opening * 0.5f, springline);
  }
  // Ray angles from the horizontal (0) to vertical (pi/2), plus the angle of the outer
  // top-left corner so that the corner is a vertex of the outline.
  std::vector<float> angles;
  for (int i = 0; i <= p.segments; ++i) {
    angles.push_back(kHalfPi * static_cast<float>(i) / static_cast<float>(p.segments));
  }
  const float corner = std::atan2(p.height - springline, half_w);
  const bool has_corner = std::none_of(angles.begin(), angles.end(),
                                       [&](float a) { return std::abs(a - corner) < 1e-4f; });
  if (has_corner) angles.insert(std::upper_bound(angles.begin(), angles.end(), corner), corner);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const float a = angles[i];
    const glm::vec2 d(-std::cos(a), std::sin(a));
    const glm::vec2 oc = origin - half.center;
    const float b = glm::dot(d, oc);
    const float k = glm::dot(oc, oc) - radius * radius;
    const float t_curve = -b + std::sqrt(std::max(b * b - k, 0.0f));
    glm::vec2 c = origin + d * t_curve;
    const float t_side = a < kHalfPi ? half_w / std::cos(a) : 1e30f;
    const float t_top = a > 0.0f ? (p.height - springline) / std::sin(a) : 1e30f;
    glm::vec2 o = origin + d * std::min(t_side, t_top);
    // Snap the exact points so that the two halves and the side faces share vertices.
    if (i == 0) {
      c = {-opening * 0.5f, springline};
      o = {-half_w, springline};
    } else if (i + 1 == angles.size()) {
      c = {0.0f, p.height - p.crown};
      o = {0.0f, p.height};
    } else if (std::abs(a - corner) < 1e-6f) {
      o = {-half_w, p.height};
    } else if (t_side < t_top) {
      o.x = -half_w;
    } else {
      o.y = p.height;
    }
    half.curve.push_back(c);
    half.outer.push_back(o);
  }
  return half;
}

glm::vec2 mirror(glm::vec2 v) {
  return {-v.x, v.y};
}

}  // namespace

float arch_springline(const ArchParams& p) {
  const float opening = p.width - 2.0f * p.pier_width;
  const float rise =
      p.style == ArchStyle::round ? opening * 0.5f : opening * std::sqrt(3.0f) * 0.5f;
  return p.height - p.crown - rise;
}

Mesh make_arch(const ArchParams& p) {
  Mesh mesh;
  MeshBuilder b(mesh);
  const float spring = arch_springline(p);
  const float zf = p.depth * 0.5f;
  const HalfArch half = sample_left_half(p, spring);
  const float half_w = p.width * 0.5f;
  const float inner = half_w - p.pier_width;
  const auto at = [](glm::vec2 q, float z, glm::vec3 n, glm::vec2 uv) {
    return Vertex{glm::vec3(q, z), n, uv};
  };
  // Front (+Z) and back (-Z) faces: pier rectangles plus the spandrel strips.
  for (const float side : {1.0f, -1.0f}) {
    const glm::vec3 n(0, 0, side);
    const float z = zf * side;
    for (const float s : {1.0f, -1.0f}) {
      const auto pt = [&](glm::vec2 q) {
        const glm::vec2 m = s > 0 ? q : mirror(q);
        return at(m, z, n, {m.x * side, p.height - m.y});
      };
      b.quad(pt({-half_w, 0}), pt({-inner, 0}), pt({-inner, spring}), pt({-half_w, spring}));
      for (std::size_t i = 0; i + 1 < half.curve.size(); ++i) {
        b.quad(pt(half.curve[i]), pt(half.curve[i + 1]), pt(half.outer[i + 1]), pt(half.outer[i]));
      }
    }
  }
  // Sides: walk the outline of each half; every segment becomes a quad between the
  // faces. Straight segments get flat normals, the intrados smooth ones that point
  // into the opening (towards the arc's centre).
  for (const float s : {1.0f, -1.0f}) {
    const auto m = [&](glm::vec2 q) { return s > 0 ? q : mirror(q); };
    const auto flat = [&](glm::vec2 q0, glm::vec2 q1, glm::vec2 out) {
      const glm::vec2 a = m(q0), c = m(q1);
      const glm::vec3 n(m(out), 0.0f);
      const float l0 = 0.0f, l1 = glm::length(c - a);
      b.quad(at(a, zf, n, {l0, 0}), at(c, zf, n, {l1, 0}), at(c, -zf, n, {l1, p.depth}),
             at(a, -zf, n, {l0, p.depth}));
    };
    flat({-half_w, 0}, {-inner, 0}, {0, -1});                  // pier bottom
    flat({-inner, 0}, {-inner, spring}, {1, 0});               // pier inner face
    flat({-half_w, 0}, {-half_w, spring}, {-1, 0});            // outer side, below springline
    for (std::size_t i = 0; i + 1 < half.outer.size(); ++i) {  // outer side and top
      const glm::vec2 q0 = half.outer[i], q1 = half.outer[i + 1];
      flat(q0, q1, q0.x == q1.x ? glm::vec2(-1, 0) : glm::vec2(0, 1));
    }
    const glm::vec2 center = m(half.center);
    float along = 0.0f;
    for (std::size_t i = 0; i + 1 < half.curve.size(); ++i) {  // intrados
      const glm::vec2 c0 = m(half.curve[i]), c1 = m(half.curve[i + 1]);
      const glm::vec3 n0(glm::normalize(center - c0), 0.0f);
      const glm::vec3 n1(glm::normalize(center - c1), 0.0f);
      const float next = along + glm::length(c1 - c0);
      b.quad(at(c0, zf, n0, {along, 0}), at(c1, zf, n1, {next, 0}),
             at(c1, -zf, n1, {next, p.depth}), at(c0, -zf, n0, {along, p.depth}));
      along = next;
    }
  }
  for (Vertex& v : mesh.vertices) v.position.y -= p.height * 0.5f;
  mesh.update_bounds();
  return mesh;
}

}  // namespace antumbra::scene
